# The speed-against-error bench (bench/cases/sem_speed_error.sh, issue 14) must keep running;
# make test does not run it otherwise. Its two coarsest p = 1 meshes of Lamb's line load (6 and
# 10 nodes per minimum S wavelength, 288 x 192 and 480 x 320 elements, ~3 s) go through the
# whole pipeline: the runs, the errors against tests/tools/lamb_line_load.py, the CSV rows,
# the markdown table and the PNG (all into this test's work folder, not docs/).
# What can fail besides the pipeline: Q1 with a lumped mass and central differences converges
# at order 2 in h at a fixed CFL number (its phase error is O((k h)^2)), so the observed order
# between the two meshes must lie in 1.7-2.3 (measured at commit: 1.92; errors 53 % and 20 %).
# Where the build has -element_degree, p = 4 at 4 nodes per lambda_min (48 x 32 elements) runs
# too, in both modes of the bench (central differences tuned to 0.45 of the stable step, and
# the defaults), and at the defaults must beat Q1 at 10: issue 14 measured degree 4 at one
# element per lambda_min at the accuracy of Q1 at lambda_min / 19 (5 %). There the 3D series
# runs too, at its smallest: the point force in a whole space at p = 4 on 8^3 elements (2.9
# nodes per lambda_min; tuned, default, and order 4 where the default keeps central
# differences) against a reference of 11^3 elements (4 nodes per lambda_min, ~4 s), whose error
# against the closed form (Aki & Richards eq. 4.23) must stay below 1.2 % (measured at commit:
# 0.72 %) and whose 3D table row must reach the markdown. Timings are printed, never asserted.
set -eu
. tests/tools/lib.sh
degrees=1
"$SW" -help 2>/dev/null | grep -q -- "-element_degree" && degrees="1 4"
SEM_BENCH_DEGREES="$degrees" SEM_BENCH_PPW_1="6 10" SEM_BENCH_PPW_4="4" SEM_BENCH_WORK="$WORK/runs" SEM_BENCH_DOC="$WORK/sem.md" \
  SEM_BENCH_3D_DEGREES="4" SEM_BENCH_3D_PPW_4="3" SEM_BENCH_3D_REF="4 11 0.9" BENCH_CSV="$WORK/results.csv" bash bench/cases/sem_speed_error.sh
$PY - "$WORK" <<'PY'
import math, os, sys
work = sys.argv[1]
rows = {}
for line in open(f"{work}/results.csv"):
    bench, case, metric, value, unit = line.strip().split(",")
    rows[(case, metric)] = float(value)
e6, e10 = rows[("p1_288x192_default", "l2_error_surface_velocity")], rows[("p1_480x320_default", "l2_error_surface_velocity")]
order = math.log(e6 / e10) / math.log(10 / 6)
print(f"p = 1: error {e6:.4f} at 6, {e10:.4f} at 10 nodes per lambda_min: order {order:.2f} (allowed 1.7-2.3)")
ok = 1.7 <= order <= 2.3
if ("p4_48x32_default", "l2_error_surface_velocity") in rows:
    e4 = rows[("p4_48x32_default", "l2_error_surface_velocity")]
    print(f"p = 4 at 4 nodes per lambda_min: error {e4:.4f} (must be below p = 1 at 10: {e10:.4f})")
    ok &= e4 < e10
    e3 = rows[("p4_11x11x11_reference", "l2_error_closed_form")]
    print(f"3D: reference p = 4, 11^3 elements, against the closed form: {e3:.4f} (allowed below 0.012)")
    ok &= e3 < 0.012 and "| 4 | default, order 2 | 8³ |" in open(f"{work}/sem.md").read()
for f in ("sem.md", "sem_speed_error.png"):
    ok &= os.path.getsize(f"{work}/{f}") > 0
ok &= "| 1 | default, order 2 | 480 x 320 |" in open(f"{work}/sem.md").read()
sys.exit(0 if ok else 1)
PY

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
# element per lambda_min at the accuracy of Q1 at lambda_min / 19 (5 %). Timings are printed,
# never asserted.
set -eu
. tests/tools/lib.sh
degrees=1
"$SW" -help 2>/dev/null | grep -q -- "-element_degree" && degrees="1 4"
SEM_BENCH_DEGREES="$degrees" SEM_BENCH_PPW_1="6 10" SEM_BENCH_PPW_4="4" SEM_BENCH_WORK="$WORK/runs" SEM_BENCH_DOC="$WORK/sem.md" \
  BENCH_CSV="$WORK/results.csv" bash bench/cases/sem_speed_error.sh
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
for f in ("sem.md", "sem_speed_error.png"):
    ok &= os.path.getsize(f"{work}/{f}") > 0
ok &= "| 1 | default, order 2 | 480 x 320 |" in open(f"{work}/sem.md").read()
sys.exit(0 if ok else 1)
PY

# The shipped record config/records/el_centro_1940_ns.csv against its provenance
# (config/records/README.md, from the distributor's description): 2688 samples at a uniform
# 0.02 s (0 to 53.74 s), header time_s,acceleration_g, peak 0.349 g at about 2.1 s, peak
# ground velocity of the integral before baseline correction about 0.35-0.38 m/s (quoted to
# two digits: the trapezoid value must round to 0.35..0.38, i.e. lie in [0.345, 0.385)).
# Then slipwave's reading of it (dry runs, the report line): the unit g comes from the
# header (2688 samples, PGA 0.3483 g after the baseline correction: the peak quoted above
# moved by the linear correction, computed here with the same correction), -input_record_pga
# 0.3 gives the scale factor 0.3/PGA, the default interpretation is outcrop, and the report's
# PGV equals the trapezoid integral computed here, with and without baseline correction
# (a record read in m/s^2 instead of g would be 9.8 x smaller).
set -eu
. tests/tools/lib.sh
REC=config/records/el_centro_1940_ns.csv
BASE="-mesh_box_faces 1,10 -mesh_box_upper 1,10 -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200
 -bc_bottom_type absorbing -input_wave sv -input_boundary bottom -input_stf record -input_record $REC -constrain_components y
 -ts_max_time 0.1 -output_fields false -dry_run -output_dir $WORK/out"
$SW $BASE -input_record_pga 0.3 > "$WORK/pga.log"
$SW $BASE -input_record_motion incident > "$WORK/incident.log"
$SW $BASE -input_baseline_correction false > "$WORK/raw.log"
grep "input:" "$WORK"/*.log
$PY - "$REC" "$WORK" <<'PY'
import re, sys
import numpy as np
path, work = sys.argv[1:]
fail = False
def check(ok, what):
    global fail
    print(("ok " if ok else "FAIL ") + what)
    fail |= not ok
header = open(path).readline().strip()
check(header == "time_s,acceleration_g", f"header {header}")
d = np.loadtxt(path, delimiter=",", skiprows=1)
t, a_g = d[:, 0], d[:, 1]
check(len(t) == 2688 and t[0] == 0 and abs(t[-1] - 53.74) < 1e-9, f"{len(t)} samples from {t[0]} to {t[-1]} s")
check(np.max(np.abs(np.diff(t) - 0.02)) < 1e-9, f"uniform step 0.02 s (largest deviation {np.max(np.abs(np.diff(t) - 0.02)):.1e} s)")
k = np.argmax(np.abs(a_g))
check(abs(abs(a_g[k]) - 0.349) <= 0.0005 and abs(t[k] - 2.1) <= 0.05, f"peak {a_g[k]:.4f} g at {t[k]:.2f} s (0.349 g at about 2.1 s)")
g = 9.80665
a = a_g * g
def trapezoid(y):
    return np.concatenate([[0.0], np.cumsum(0.5 * (y[1:] + y[:-1]) * np.diff(t))])
pgv_raw = np.max(np.abs(trapezoid(a)))
check(0.345 <= pgv_raw < 0.385, f"PGV before baseline correction {pgv_raw:.4f} m/s (about 0.35-0.38)")
# slipwave's baseline correction: c0 + c1 (t - t0) with the final velocity and displacement zero
ramp = t - t[0]
def final(y):
    v = trapezoid(y)
    return v[-1], trapezoid(v)[-1]
(v0, d0), (v1, d1), (v, dd) = final(np.ones_like(t)), final(ramp), final(a)
det = v0 * d1 - v1 * d0
corrected = a - (v * d1 - v1 * dd) / det - (v0 * dd - v * d0) / det * ramp
pga = np.max(np.abs(corrected)) / g
pgv = np.max(np.abs(trapezoid(corrected)))
def report(name):
    text = open(f"{work}/{name}.log").read()
    return re.search(r"input: sv wave through 'bottom', record (.*)", text).group(1)
def number(pattern, text):
    m = re.search(pattern, text)
    return float(m.group(1)) if m else float("nan")
line = report("pga")
check("(CSV in g, 2688 samples, 0 to 53.74 s), baseline-corrected" in line, "unit g read from the header; 2688 samples")
check(abs(number(r"PGA ([0-9.]+) g", line) - 0.3) < 5e-4, "PGA 0.3 g as asked")
factor = 0.3 / pga
check(abs(number(r"scale factor ([0-9.]+)", line) / factor - 1) < 1e-3, f"scale factor {factor:.4f} = 0.3 g / {pga:.4f} g")
check(abs(number(r"the record's ([0-9.]+) g", line) / pga - 1) < 1e-3, f"the record's PGA after baseline correction {pga:.4f} g")
check("outcrop motion" in line, "outcrop by default")
line = report("incident")
check(abs(number(r"PGV ([0-9.]+) m/s", line) / pgv - 1) < 1e-3 and "the incident wave itself" in line,
      f"PGV {pgv:.4f} m/s (baseline-corrected), incident")
line = report("raw")
check(abs(number(r"PGV ([0-9.]+) m/s", line) / pgv_raw - 1) < 1e-3 and "baseline-corrected" not in line,
      f"PGV {pgv_raw:.4f} m/s without baseline correction")
sys.exit(1 if fail else 0)
PY

# Convergence in time at spectral-element degree p > 1 (issue 14): central differences
# (-ts_cd_order 2; the fourth-order integrator's rate is tests/unit/test_fourth_order.cpp) with
# the GLL (diagonal) mass are second order, so at a fixed mesh the error of the displacement
# field at a fixed time falls 4x per halving of dt. Problem, exact solution and error: those of
# sem_convergence_space.sh (SV column, incident + reflected Ricker, compared at t = 0.8 s,
# tests/tools/column_field_error.py). Meshes fine enough that the space error is small against
# the time errors: p = 6 with 16 elements (space error 2.0e-7, sem_convergence_space.sh) and
# p = 4 with 28 (2.8e-6); dt = 4e-4, 2e-4, 1e-4 s at p = 6 and 8e-4, 4e-4, 2e-4 s at p = 4
# (the stable limits are 7.6e-4 and 1.15e-3 s), time errors ~4e-4 .. 6e-6, so the space error
# is at most 1/9 of the smallest (at p = 4 with dt down to 1e-4 it is 1/2, and the last rate
# falls to 1.88). Bound: every observed rate within 2 +- 0.1.
set -eu
. tests/tools/lib.sh
column="$COLUMN -mesh_box_upper 5,100 -input_wave sv -constrain_components y -input_t0 0.4 -ts_max_time 0.8
 -output_fields 1 -output_interval 0.8 -energy_interval 1000000 -progress_interval 1e7 -ts_cd_order 2"
# degree:elements:time steps [s]
cases="6:16:4e-4,2e-4,1e-4 4:28:8e-4,4e-4,2e-4"
for c in $cases; do
  IFS=: read -r p n dts <<<"$c"
  for dt in ${dts//,/ }; do
    $SW $column -element_degree $p -mesh_box_faces 1,$n -ts_dt $dt -output_dir "$WORK/p${p}_dt$dt" > "$WORK/p${p}_dt$dt.log"
  done
done
$PY - "$WORK" $cases <<'PY'
import sys
sys.path.insert(0, "tests/tools")
from column_field_error import column_exact, l2_distance, profile
from convergence_rates import rates
work, ok = sys.argv[1], True
for case in sys.argv[2:]:
    p, _, dts = case.split(":")
    p, dts, errs = int(p), dts.split(","), []
    for dt in dts:
        t, ys, us, _ = profile(f"{work}/p{p}_dt{dt}")
        exact = lambda y: column_exact(y, t, 100.0, 200.0, 0.1, 5.0, 0.4)
        errs.append(l2_distance(ys, us, p, exact) / l2_distance(ys, 0 * us, p, exact))
        ok &= abs(t - 0.8) < 1e-9
    observed = rates(errs, [1 / float(dt) for dt in dts])
    good = all(abs(r - 2) <= 0.1 for r in observed)
    print(f"p = {p}: dt {', '.join(dts)} s: L2 errors {' '.join(f'{e:.3e}' for e in errs)}; rates {' '.join(f'{r:.3f}' for r in observed)} (bound 2 +- 0.1) {'ok' if good else 'FAIL'}")
    ok &= good
sys.exit(0 if ok else 1)
PY

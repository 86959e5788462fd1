# Convergence in space of spectral elements (issue 14): the L2 error of the displacement FIELD
# falls at order p + 1 for p = 1..6. Problem: the SV column of $COLUMN (100 m, absorbing base
# with the incident Ricker wave, free top, y held so the column is exactly 1D, 5 m wide, one
# element across), its Ricker centred at t0 = 0.4 s so the wavelet starts at exp(-(2 pi)^2) =
# 7e-18 of its peak (no start-up kink), compared at t = 0.8 s, when the incident pulse is
# being reflected at the top and nothing has come back to the base (the reflection reaches it
# after t0 + 2 H / vs - 1.67 / f0 = 1.07 s): there the exact field is incident + reflected wave
# (tests/tools/column_field_error.py, with the error integral in the element basis on a rule
# finer than GLL). Theory: the L2 error of degree-p elements is O(h^(p+1)) (interpolation
# order; the phase error of GLL spectral elements is O((kh)^(2p)), faster, so the rate
# approaches p + 1 from above). Bound: every observed rate >= p + 1 - 0.3.
# The shear stress slipwave writes per output cell (at the sub-cell centre, by the element
# basis at p > 1; src/fem/bulk_operator.cpp) against mu du/dy of the closed form, relative RMS
# over the cells: a derivative, order p (2 at p = 1, where the centre of a linear cell
# superconverges); bound: every rate >= max(p, 2) - 0.3.
# Meshes: three per degree, in the asymptotic range (measured at commit: at p = 4 the pair
# 10 -> 20 elements is still in the transition where the phase and interpolation errors
# partly cancel, rate 4.70; 14, 20, 28 give 5.04, 5.00; at p = 5, 8 -> 12 -> 16 give 5.35,
# 5.34, and 16, 20, 24 give 6.0).
# Time step: small enough that the time error is negligible, and checked: the finest mesh runs
# also at 2 dt; the field difference is 3x the time error at dt (central differences are
# second order, see sem_convergence_time.sh), and it must stay below 0.1 of the space error,
# so the time error is at most 3 % of it and moves a rate by at most 0.05.
# SEM_DIM=3 runs the column as hexahedra (5 m x 5 m x 100 m, y and z held) at p = 2, 3, 4
# (tests/cases/sem_convergence_hex.sh); the errors equal the 2D ones to 4 digits.
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
common="$COLUMN -input_wave sv -input_t0 0.4 -ts_max_time 0.8 -output_fields 1 -output_interval 0.8 -energy_interval 1000000 -progress_interval 1e7"
# degree: element counts along the column; dt [s]
if [ "${SEM_DIM:-2}" = 3 ]; then
  column="$common -mesh_dim 3 -mesh_box_upper 5,5,100 -constrain_components y,z"; across=1,1; vertical=2
  cases="2:20,40,80:4e-5 3:10,20,40:2e-5 4:14,20,28:8e-6"
else
  column="$common -mesh_box_upper 5,100 -constrain_components y"; across=1; vertical=1
  cases="1:100,200,400:1e-4 2:20,40,80:4e-5 3:10,20,40:2e-5 4:14,20,28:8e-6 5:16,20,24:3e-6 6:8,12,16:2.5e-6"
fi
# The runs two at a time (tests/tools/together.sh), the longest first (the highest degree, its
# finest mesh: the smallest step), so that no long run is left alone at the end.
for c in $(tr ' ' '\n' <<<"$cases" | tac); do
  IFS=: read -r p meshes dt <<<"$c"
  finest=${meshes##*,}
  for n in $(tr ',' '\n' <<<"$meshes" | tac); do
    together $SW $column -element_degree $p -mesh_box_faces $across,$n -ts_dt $dt -output_dir "$WORK/p${p}_n$n" > "$WORK/p${p}_n$n.log"
    if [ "$n" = "$finest" ]; then
      dt2=$($PY -c "print(2 * $dt)")
      together $SW $column -element_degree $p -mesh_box_faces $across,$n -ts_dt $dt2 -output_dir "$WORK/p${p}_n${n}_2dt" > "$WORK/p${p}_n${n}_2dt.log"
    fi
  done
done
together_wait
$PY - "$WORK" $vertical $cases <<'PY'
import sys
sys.path.insert(0, "tests/tools")
from column_field_error import column_exact, column_strain_exact, l2_distance, profile, shear_stress_error
from convergence_rates import cases, space_ok
work, vertical, ok = sys.argv[1], int(sys.argv[2]), True
column = (100.0, 200.0, 0.1, 5.0, 0.4)   # H, vs, A, f0, t0
for p, meshes, dt in cases(sys.argv[3:]):
    meshes = [int(n) for n in meshes]
    errs, stress_errs = [], []
    for n in meshes:
        t, ys, us, spread = profile(f"{work}/p{p}_n{n}", vertical=vertical)
        exact = lambda y: column_exact(y, t, *column)
        norm = l2_distance(ys, 0 * us, p, exact)
        errs.append(l2_distance(ys, us, p, exact) / norm)
        stress_errs.append(shear_stress_error(f"{work}/p{p}_n{n}", 2000.0 * 200.0**2, lambda y: column_strain_exact(y, t, *column), vertical=vertical))
        ok &= abs(t - 0.8) < 1e-9 and spread <= 1e-12 * max(abs(us))
    _, _, us2, _ = profile(f"{work}/p{p}_n{meshes[-1]}_2dt", vertical=vertical)
    ok &= space_ok(f"displacement L2, elements {meshes}, dt {dt} s", p, meshes, errs, l2_distance(ys, us - us2, p, lambda y: 0 * y) / norm)
    ok &= space_ok("shear stress at the cell centres, relative RMS", p, meshes, stress_errs, order=max(p, 2))
sys.exit(0 if ok else 1)
PY

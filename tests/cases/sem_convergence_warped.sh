# Convergence in space of spectral elements on non-affine quadrilaterals (issue 14: geometry
# from the mesh's Q1 map): the problem, exact solution and time of sem_convergence_space.sh
# (SV column, incident + reflected Ricker at t = 0.8 s, y held) on
# tests/data/meshes/column_quad_warped.geo (10 m x 100 m cut into four macro quadrilaterals
# meeting at the off-centre point (6, 56), each nx x ny cells; every cell a bilinear image of
# a square that is no parallelogram), refined in both directions by the same factor. The error
# of the displacement field is integrated in the element basis over the true cells
# (tests/tools/quad_field_error.py: GLL nodes found as images of the GLL points under each
# cell's bilinear map, a Gauss rule of p + 6 points per direction, |det J| weights).
# Theory: isoparametric degree-p elements on such a family keep the order p + 1 (Ciarlet &
# Raviart 1972: the cells tend to parallelograms under uniform refinement of the macro cells).
# Bound: every observed rate >= p + 1 - 0.3. Measured at commit: p = 2: 3.27, 3.71 (approaching
# 3 from above, as on rectangles); p = 3: 4.97; p = 4: 6.20, 5.64. The time step makes the time
# error negligible, checked as in sem_convergence_space.sh: the finest mesh at 2 dt changes the
# field by less than 0.1 of its error.
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
column="$COLUMN -input_wave sv -constrain_components y -input_t0 0.4 -ts_max_time 0.8
 -output_fields 1 -output_interval 0.8 -energy_interval 1000000 -progress_interval 1e7"
# degree: macro-cell divisions nx/ny, one mesh per comma: dt [s]
cases="2:3/9,6/18,12/36:4e-5 3:2/6,4/12:2e-5 4:2/6,3/9,4/12:8e-6"
# The meshes first; then the runs, independent, two at a time (tests/tools/together.sh).
for c in $cases; do
  IFS=: read -r p meshes dt <<<"$c"
  for m in ${meshes//,/ }; do
    name="${m/\//x}"
    [ -f "$WORK/$name.msh" ] || gmsh -2 tests/data/meshes/column_quad_warped.geo -setnumber nx "${m%/*}" -setnumber ny "${m#*/}" -format msh41 \
      -o "$WORK/$name.msh" > "$WORK/gmsh_$name.log" 2>&1 || { cat "$WORK/gmsh_$name.log"; exit 1; }
  done
done
for c in $cases; do
  IFS=: read -r p meshes dt <<<"$c"
  for m in ${meshes//,/ }; do
    name="${m/\//x}"
    together $SW $column -mesh_file "$WORK/$name.msh" -element_degree $p -ts_dt $dt -output_dir "$WORK/p${p}_$name" > "$WORK/p${p}_$name.log"
  done
  dt2=$($PY -c "print(2 * $dt)")
  together $SW $column -mesh_file "$WORK/$name.msh" -element_degree $p -ts_dt $dt2 -output_dir "$WORK/p${p}_${name}_2dt" > "$WORK/p${p}_${name}_2dt.log"
done
together_wait
$PY - "$WORK" $cases <<'PY'
import sys
sys.path.insert(0, "tests/tools")
from column_field_error import column_exact
from convergence_rates import cases, space_ok
from frames import Frames
from quad_field_error import l2_distance
work, ok = sys.argv[1], True
for p, meshes, dt in cases(sys.argv[2:]):
    names = [m.replace("/", "x") for m in meshes]
    errs = []
    for name in names:
        f = Frames(f"{work}/p{p}_{name}")
        t, u = f.times[-1], f.field("displacement", -1)[:, 0]
        exact = lambda x, y: column_exact(y, t, 100.0, 200.0, 0.1, 5.0, 0.4)
        norm = l2_distance(f"{work}/{name}.msh", p, f.geometry, 0 * u, exact)
        errs.append(l2_distance(f"{work}/{name}.msh", p, f.geometry, u, exact) / norm)
        ok &= abs(t - 0.8) < 1e-9
    u2 = Frames(f"{work}/p{p}_{names[-1]}_2dt").field("displacement", -1)[:, 0]
    time_change = l2_distance(f"{work}/{names[-1]}.msh", p, f.geometry, u - u2, lambda x, y: 0 * y) / norm
    ny = [int(m.split("x")[1]) for m in names]
    ok &= space_ok(f"displacement L2, cells nx x ny per macro cell {names}, dt {dt} s", p, ny, errs, time_change)
sys.exit(0 if ok else 1)
PY

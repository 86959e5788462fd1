# Terzaghi consolidation (saturated_terzaghi.sh: 10 m column, 100 kPa on its drained top,
# impervious fixed base, lateral strain held, the same damping) with spectral elements of
# degree 2 and 4 (pressure at the GLL nodes, docs/saturated-soil.md "At element degree
# p > 1"): p at 2.5 m and 7.5 m and the settlement at T_v = 0.1, 0.3, 0.6 within 1 % of the
# closed-form series (tests/tools/poroelastic.py terzaghi), with fewer unknowns than p = 1
# needs for the same discretisation error.
# Elements are square (width = height; the 1D solution does not depend on the width, and the
# GLL spacing across a narrow column would set the diffusion limit). Unknowns are nodes x 3
# (u_x, u_y, p): p = 2, 4 elements: 3 x 9 nodes, 81; p = 4, 2 elements: 5 x 9 nodes, 135;
# p = 1, 20 cells (saturated_terzaghi.sh's mesh): 2 x 21 nodes, 126; 40 cells: 246.
# The discretisation error is the distance from p = 4 with 3 elements (itself ~5e-6 of the
# load from 4 elements): against the series every mesh keeps ~1e-3 from the damping's drag on
# the consolidation (poroelastic.py terzaghi-discretisation). Every run takes the same step,
# 5e-5 s (below every mesh's limit), at which the time error no longer enters these
# distances (2.5e-5 s gives the same three digits). Measured (2026-11-29), p and settlement:
# p = 2: 1.45e-4 of the load, 2.4e-5 (bounds 3e-4, 5e-5); p = 4: 1.95e-5, 2.7e-7 (bounds 5e-5,
# 1e-6); p = 1 with 126 unknowns: 8.1e-4, 2.0e-4; with 246: 2.1e-4, 5.1e-5. Each p > 1 run
# must be nearer than both p = 1 runs on both, with 81 and 135 unknowns against 126 and 246;
# p = 1 converges as h^2 (40 -> 80 cells: 2.2e-4 -> 5.4e-5), so it would need ~48 cells (294
# unknowns) for p = 2's pressure error and ~130 (786) for p = 4's.
set -eu
. tests/tools/lib.sh
MAT="-material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -material_soil_saturated -material_soil_porosity 0.4 -material_soil_hydraulic_conductivity 3.8e-4"
LOAD="-regions soil $MAT -constrain_components x -bc_bottom_type fixed -bc_top_type traction -bc_top_traction 0,-1e5 -bc_top_fluid drained -damping_ratio 0.16
 -damping_frequencies 10,1e6 -ts_max_time 5.2 -station_coordinates 0,7.5,0,2.5,0,10 -station_names d2_5,d7_5,top -output_fields 0 -progress_interval 100000"
GEO="--height 10 --load 1e5 --stations d2_5:2.5,d7_5:7.5 --top top --rho 2000 --vp 400 --porosity 0.4 --hydraulic-conductivity 3.8e-4"
# run NAME DEGREE ELEMENTS WIDTH
run() {
  $SW $LOAD -ts_dt 5e-5 -element_degree "$2" -mesh_box_faces "1,$3" -mesh_box_upper "$4,10" -output_dir "$WORK/$1" > "$WORK/$1.log"
  echo "$1: $(grep -E '^done' "$WORK/$1.log")"
}
run p4_ref 4 3 3.333333333333333
run p4 4 2 5
run p2 2 4 2.5
run p1_126 1 20 0.5
run p1_246 1 40 0.5
grep -E "sub-cycled|counts the undrained" "$WORK/p2.log" "$WORK/p4.log"
for d in p2 p4; do $PY tests/tools/poroelastic.py terzaghi "$WORK/$d" $GEO; done
$PY tests/tools/poroelastic.py terzaghi-discretisation "$WORK/p2" --reference "$WORK/p4_ref" --coarser "$WORK/p1_126" --coarser "$WORK/p1_246" --p-tol 3e-4 --s-tol 5e-5 $GEO
$PY tests/tools/poroelastic.py terzaghi-discretisation "$WORK/p4" --reference "$WORK/p4_ref" --coarser "$WORK/p1_126" --coarser "$WORK/p1_246" --p-tol 5e-5 --s-tol 1e-6 $GEO

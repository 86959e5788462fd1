# The dynamic u-p column of saturated_up_column.sh (50 m, base Ricker 10 Hz, k = 0.04 m/s
# between the drained and undrained regimes, drained top) with spectral elements of degree 2
# and 4, square (width = height: the 1D solution does not depend on the width, and the GLL
# spacing across a 1 m column would set the diffusion limit).
# 1. At the default step (diffusion sub-cycled) with the nodes of the p = 1 test (p = 2: 25
#    elements; p = 4: 13): top displacement and p at 25 m and 40 m depth within 1 % relative L2
#    of the semi-analytic solution (tests/tools/up_column.py compare). Measured (2026-11-29):
#    p = 2: 5.2e-3, 6.5e-3, 4.9e-3; p = 4: 2.3e-3, 2.9e-3, 2.2e-3, mostly the split step's
#    time error, which falls with the step (p = 1: 0.8-1.0 %).
# 2. The observed spatial order from three element sizes h, h/2, h/4 at one step
#    (up_column.py convergence): p = 2 with 5, 10, 20 elements (stations top, 25 m, 40 m: GLL
#    nodes on every mesh), p = 4 with 2, 4, 8 (stations top, 25 m, 37.5 m: nodes; 40 m lies
#    inside the p = 4 elements, where the element basis interpolates), the step within half
#    the finest mesh's diffusion limit so that every mesh takes one diffusion sub-step (the
#    same time discretisation; at a step 2x smaller the distances agree to 3 digits).
#    Measured: p = 2 orders 4.17, 3.58, 3.80; p = 4 8.20, 7.43, 6.10, both at least p + 1
#    (the bound; L2 of the node values, which converge faster than the L2 in space).
set -eu
. tests/tools/lib.sh
MAT="-material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -material_soil_saturated -material_soil_porosity 0.4 -material_soil_hydraulic_conductivity 0.04 -fluid_cavitation_pressure none"
COL="-regions soil $MAT -constrain_components x -bc_bottom_type velocity -bc_bottom_components y -bc_bottom_stf ricker -bc_bottom_f0 10 -bc_bottom_t0 0.12
 -bc_bottom_amplitude 0.1 -bc_top_fluid drained -ts_max_time 0.4 -output_fields 0 -progress_interval 100000"
SOL="--height 50 --rho 2000 --vp 400 --porosity 0.4 --hydraulic-conductivity 0.04 --f0 10 --t0 0.12 --amplitude 0.1 --t-end 0.4"
# run NAME DEGREE ELEMENTS STATION_DEPTHS(y of the two pressure stations) [options]
run() {
  local name=$1 degree=$2 n=$3 ys=$4; shift 4
  $SW $COL -element_degree "$degree" -mesh_box_faces "1,$n" -mesh_box_upper "$($PY -c "print(50 / $n)"),50" -station_coordinates "0,50,0,${ys/,/,0,}" \
    -station_names top,s1,s2 -output_dir "$WORK/$name" "$@" > "$WORK/$name.log"
  echo "$name: $(grep -E '^done' "$WORK/$name.log")"
}
for case in "2 25" "4 13"; do
  set -- $case
  run "p$1" "$1" "$2" 25,10
  grep -E "sub-cycled|counts the undrained" "$WORK/p$1.log"
  $PY tests/tools/up_column.py compare "$WORK/p$1" --stations top,s1,s2 --depths 0,25,40 $SOL --tol 0.01
done
for n in 5 10 20; do run "p2_h$n" 2 $n 25,10 -ts_dt 4.3e-6; done
$PY tests/tools/up_column.py convergence "$WORK/p2_h5,$WORK/p2_h10,$WORK/p2_h20" --stations top:u,s1:p,s2:p --t-end 0.4 --min-rate 3
for n in 2 4 8; do run "p4_h$n" 4 $n 25,12.5 -ts_dt 2.6e-6; done
$PY tests/tools/up_column.py convergence "$WORK/p4_h2,$WORK/p4_h4,$WORK/p4_h8" --stations top:u,s1:p,s2:p --t-end 0.4 --min-rate 5

# Equal order at element degree p > 1 (docs/saturated-soil.md "At element degree p > 1"): the
# pressure at the GLL nodes, with the same lumped (here exactly diagonal) storage, keeps the
# spurious pressure modes out as at p = 1, and the split step's energy balance closes.
# 1. saturated_no_checkerboard.sh's wet/dry box (k = 0, alpha^2 M / G = 69, 40 Hz P pulse) with
#    the same GLL nodes as its 80 x 40 cells: p = 2 on 40 x 20 elements, p = 4 on 20 x 10. The
#    node-alternating part of p per GLL sub-cell stays below 5 % of max |p| (p = 1: 1.1 %; a
#    checkerboard gives ~100 %). Measured: 1.2 % at p = 2, 1.2 % at p = 4.
# 2. saturated_energy_ranks.sh's box (k = 0.08 m/s, drained top, inflow base, sub-cycled) at
#    p = 2 (8 x 8 elements) and p = 4 (4 x 4): the balance with the fluid storage, the Darcy
#    dissipation and the inflow work closes to 1e-12 of the largest energy, Darcy takes at
#    least 10 % of the input, and 2 ranks give the 1-rank station records (pore pressure
#    included) to 1e-10. Measured: balance 8.4e-16 (p = 2) and 1.5e-15 (p = 4), Darcy 21 % of
#    the input (p = 1: 20 %), 2 ranks as 1 to 5.4e-14 (accelerations 6.7e-13).
set -eu
. tests/tools/lib.sh
SK="-material_X_rho 2000 -material_X_vp 400 -material_X_vs 200"
for case in "2 40,20" "4 20,10"; do
  set -- $case
  $SW -regions wet,dry -region_wet_box 0,20,0,20 -region_dry_box 20,40,0,20 ${SK//X/wet} ${SK//X/dry} -material_wet_saturated -material_wet_porosity 0.4 \
    -fluid_cavitation_pressure none -material_wet_hydraulic_conductivity 0 -element_degree "$1" -mesh_box_faces "$2" -mesh_box_upper 40,20 -bc_bottom_type absorbing \
    -bc_left_type absorbing -bc_right_type absorbing -input_wave p -input_boundary bottom -input_stf ricker -input_f0 40 -input_t0 0.03 -input_amplitude 0.1 \
    -ts_max_time 0.05 -output_interval 0.005 -output_dir "$WORK/board_p$1" -progress_interval 100000 | grep -E "^done"
  $PY tests/tools/poroelastic.py checkerboard "$WORK/board_p$1" --box 0,20,0,20 --max-ratio 0.05
done
MAT="-material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -material_soil_saturated -material_soil_porosity 0.4 -material_soil_hydraulic_conductivity 0.08"
OPTS="-regions soil $MAT -mesh_box_upper 32,32 -bc_bottom_type absorbing -bc_left_type absorbing -bc_right_type absorbing -input_wave p
 -input_boundary bottom -input_stf ricker -input_f0 10 -input_t0 0.12 -input_amplitude 0.1 -bc_top_fluid drained -bc_bottom_fluid flux -bc_bottom_fluid_flux 1e-5
 -ts_max_time 0.3 -station_coordinates 16,16,16,32,5,30 -station_names mid,top,off -output_fields 0 -progress_interval 100000"
for case in "2 8,8" "4 4,4"; do
  set -- $case
  $SW $OPTS -element_degree "$1" -mesh_box_faces "$2" -output_dir "$WORK/p$1_np1" | grep -E "counts the undrained|sub-cycled|^done"
  $MPIEXEC -n 2 $SW $OPTS -element_degree "$1" -mesh_box_faces "$2" -output_dir "$WORK/p$1_np2" | grep -E "^done"
  $PY tests/tools/poroelastic.py energy "$WORK/p$1_np1/energy.csv" --max-error 1e-12 --min-darcy-fraction 0.1
  $PY tests/tools/poroelastic.py energy "$WORK/p$1_np2/energy.csv" --max-error 1e-12 --min-darcy-fraction 0.1
  $CHECK stations-equal "$WORK/p$1_np1" "$WORK/p$1_np2" --names mid,top,off --tol 1e-10
done

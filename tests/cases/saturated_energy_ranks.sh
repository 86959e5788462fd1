# A 2D saturated box (32 m, 16 x 16 cells, k = 0.08 m/s: the 10 Hz P pulse is between the
# drained and undrained regimes, where Biot flow dissipates most) with absorbing sides and
# base, the pulse entering through the base, a drained top and a prescribed inflow on the
# base. The energy budget with the fluid storage in the stored energy and the Darcy
# dissipation and inflow work booked closes to round-off (bound 1e-12 of the largest energy;
# the discrete identity is exact, docs/saturated-soil.md), Darcy takes at least 10 % of the
# input (so a missing column would show), and 1 and 2 ranks give the same station records,
# pore pressure included, to 1e-10.
set -eu
. tests/tools/lib.sh
MAT="-material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -material_soil_saturated -material_soil_porosity 0.4 -material_soil_hydraulic_conductivity 0.08"
OPTS="-regions soil $MAT -mesh_box_faces 16,16 -mesh_box_upper 32,32 -bc_bottom_type absorbing -bc_left_type absorbing -bc_right_type absorbing -input_wave p
 -input_boundary bottom -input_stf ricker -input_f0 10 -input_t0 0.12 -input_amplitude 0.1 -bc_top_fluid drained -bc_bottom_fluid flux -bc_bottom_fluid_flux 1e-5
 -ts_max_time 0.3 -station_coordinates 16,16,16,32,5,30 -station_names mid,top,off -output_fields 0 -progress_interval 100"
$SW $OPTS -output_dir "$WORK/np1" | grep -E "pore pressure step|done"
$MPIEXEC -n 2 $SW $OPTS -output_dir "$WORK/np2" | grep -E "done"
$PY tests/tools/poroelastic.py energy "$WORK/np1/energy.csv" --max-error 1e-12 --min-darcy-fraction 0.1
$PY tests/tools/poroelastic.py energy "$WORK/np2/energy.csv" --max-error 1e-12 --min-darcy-fraction 0.1
$CHECK stations-equal "$WORK/np1" "$WORK/np2" --names mid,top,off --tol 1e-10

# Free-field sides on 1 and 2 ranks (issue 5 item 2): the columns are replicated on every rank
# and each boundary node's force is the same sum in a different order, so the station records
# agree to round-off: 1e-10 of the peak of each quantity (the bound of tests/cases/mpi_ranks.sh).
# The site has a stiff footing (so the motion is 2D), 2 % Rayleigh damping and a P-SV mix:
# an SV wave, and a second run with a P wave.
set -eu
. tests/tools/lib.sh
site="-regions rock,soil,footing -material_soil_rho 1900 -material_soil_vp 500 -material_soil_vs 200 -material_rock_rho 2400 -material_rock_vp 1600
 -material_rock_vs 800 -material_footing_rho 2400 -material_footing_vp 2000 -material_footing_vs 1200 -region_footing_box -2,2,28,30
 -mesh_box_faces 20,40 -mesh_box_lower -10,-10 -mesh_box_upper 10,30 -region_soil_box -10,10,0,30 -bc_bottom_type absorbing
 -bc_left_type freefield -bc_right_type freefield -input_boundary bottom -input_stf ricker -input_f0 2 -input_t0 0.6 -input_amplitude 0.1
 -damping_ratio 0.02 -damping_frequencies 1,8 -ts_max_time 1.5 -output_fields 0 -progress_interval 100000
 -station_coordinates -10,30,0,30,10,30,-10,0 -station_names left,centre,right,left_base"
for wave in sv p; do
  $SW $site -input_wave $wave -output_dir "$WORK/${wave}1"
  $MPIEXEC -n 2 $SW $site -input_wave $wave -output_dir "$WORK/${wave}2"
  $CHECK stations-equal "$WORK/${wave}1" "$WORK/${wave}2" --names left,centre,right,left_base --tol 1e-10
done

# Free-field sides beside constant-Q damped soil (issue 8): the lateral columns carry the same
# memory variables as their side's cells, so a scatterer-free narrow model with free-field
# sides must move exactly like a 1D column of the same layers (the test of
# tests/cases/free_field_reflection.sh, part 1, with damping): station records equal to 1e-10
# of each quantity's peak (round-off). Soil xi = 0.05, rock xi = 0.02 (both damped, different
# weights, one band), SV and P waves (the P column holds x instead of y).
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
site="-regions rock,soil -material_soil_rho 1900 -material_soil_vp 500 -material_soil_vs 200 -material_soil_damping_ratio 0.05
 -material_rock_rho 2400 -material_rock_vp 1600 -material_rock_vs 800 -material_rock_damping_ratio 0.02 -bc_bottom_type absorbing
 -input_boundary bottom -input_stf ricker -input_f0 2 -input_t0 0.6 -input_amplitude 0.1 -ts_max_time 2.5 -ts_dt 3e-4 -output_fields 0
 -progress_interval 100000"
narrow="-mesh_box_faces 20,40 -mesh_box_lower -10,-10 -mesh_box_upper 10,30 -region_soil_box -10,10,0,30 -bc_left_type freefield -bc_right_type freefield
 -station_coordinates -10,30,-9,30,0,30,10,30,0,10 -station_names left,edge,centre,right,centre_10"
column="-mesh_box_faces 1,40 -mesh_box_lower -2,-10 -mesh_box_upper -1,30 -region_soil_box -10,10,0,30
 -station_coordinates -2,30,-2,30,-2,30,-2,30,-2,10 -station_names left,edge,centre,right,centre_10"
# The four runs are independent (one rank each): two at a time (tests/tools/together.sh).
for wave in sv p; do
  held=y; [ $wave = p ] && held=x
  together $SW $site $narrow -input_wave $wave -output_dir "$WORK/free_$wave" > "$WORK/free_$wave.log"
  together $SW $site $column -input_wave $wave -constrain_components $held -output_dir "$WORK/column_$wave" > "$WORK/column_$wave.log"
done
together_wait
for wave in sv p; do
  $CHECK stations-equal "$WORK/column_$wave" "$WORK/free_$wave" --names left,edge,centre,right,centre_10 --tol 1e-10
done

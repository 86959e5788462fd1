# Free-field sides beside constant-Q damped soil at element degree 4 (issue 14):
# constant_q_free_field.sh (soil xi = 0.05, rock xi = 0.02, SV and P waves) with elements of
# 4 m x 2 m (4x and 2x fewer than its 1 m cells). The degree-4 column keeps its memory
# variables at the element's GLL points, as the 2D elements do (physics/free_field_column), so
# the scatterer-free narrow model must move exactly like the 1D column of the same layers:
# station records equal to 1e-10 of each quantity's peak (round-off). The accelerations carry
# the round-off of K u over m, eps (omega_max/omega_0)^2 of their peak: omega_max = 2/dt_limit
# ~ 1.4e4 rad/s at p = 4 (1.39e-4 s), omega_0 = 2 pi 2 Hz, so ~2.7e-10: bound 1e-9 for a
# (measured 1.3e-10 SV, 1.9e-10 P; u and v 1.8e-12).
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
site="-regions rock,soil -material_soil_rho 1900 -material_soil_vp 500 -material_soil_vs 200 -material_soil_damping_ratio 0.05
 -material_rock_rho 2400 -material_rock_vp 1600 -material_rock_vs 800 -material_rock_damping_ratio 0.02 -bc_bottom_type absorbing
 -input_boundary bottom -input_stf ricker -input_f0 2 -input_t0 0.6 -input_amplitude 0.1 -ts_max_time 2.5 -ts_dt 1.2e-4 -output_fields 0
 -progress_interval 100000 -element_degree 4"
narrow="-mesh_box_faces 5,20 -mesh_box_lower -10,-10 -mesh_box_upper 10,30 -region_soil_box -10,10,0,30 -bc_left_type freefield -bc_right_type freefield
 -station_coordinates -10,30,-9,30,0,30,10,30,0,10 -station_names left,edge,centre,right,centre_10"
column="-mesh_box_faces 1,20 -mesh_box_lower -2,-10 -mesh_box_upper 2,30 -region_soil_box -10,10,0,30
 -station_coordinates -2,30,-2,30,-2,30,-2,30,-2,10 -station_names left,edge,centre,right,centre_10"
# The four runs are independent (one rank each): two at a time (tests/tools/together.sh).
for wave in sv p; do
  held=y; [ $wave = p ] && held=x
  together $SW $site $narrow -input_wave $wave -output_dir "$WORK/free_$wave" > "$WORK/free_$wave.log"
  together $SW $site $column -input_wave $wave -constrain_components $held -output_dir "$WORK/column_$wave" > "$WORK/column_$wave.log"
done
together_wait
for wave in sv p; do
  $CHECK stations-equal "$WORK/column_$wave" "$WORK/free_$wave" --names left,edge,centre,right,centre_10 --tol 1e-10 --tol-a 1e-9
done

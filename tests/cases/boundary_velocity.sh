# Prescribed velocity: a 100 m SV column whose base moves with a Ricker velocity v_b(t)
# (rigid base). The wave reaches the free surface doubled, v_s(t) = 2 v_b(t - H/c), until the
# surface reflection has travelled down, reflected at the rigid base and come back, at
# t = t0 + 3H/c minus the half-width 1.5/f0 of the pulse: 0.24 + 1.5 - 0.3 = 1.44 s. Same
# mesh and bound as the absorbing-base column (20 points per wavelength, L2 <= 1.5 %).
set -eu
. tests/tools/lib.sh
$SW -mesh_box_faces 1,139 -mesh_box_upper 1,100 -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 \
  -bc_bottom_type velocity -bc_bottom_components x -bc_bottom_stf ricker -bc_bottom_f0 5 -bc_bottom_t0 0.24 -bc_bottom_amplitude 0.1 \
  -constrain_components y -ts_max_time 1.44 -output_fields 0 -progress_interval 100 \
  -station_coordinates 0.5,100 -station_names top -output_dir "$WORK"
$CHECK column "$WORK/stations/top.csv" --component x --height 100 --speed 200 --amplitude 0.1 --f0 5 --t0 0.24 --l2-max 0.015 --late-max 0

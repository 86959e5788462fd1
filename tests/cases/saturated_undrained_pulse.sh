# Undrained limit (k = 0): a Ricker P pulse (10 Hz) entering a 200 m saturated column through
# its absorbing base travels at the undrained speed sqrt((E + alpha^2 M)/rho) = 1705.9 m/s
# (not the drained 400 m/s) within 1 %, measured by cross-correlation between stations 80 m
# apart, and carries p = gamma (-sigma_yy) with the loading efficiency gamma = 0.945 within
# 2 % (Wang 2000 sec. 3.5; values recomputed by tests/tools/poroelastic.py). Both ends are
# absorbing with the undrained impedance: the top must not send the pulse back (checked as
# late motion at the upper station, below 1 % of the peak). Run in 2D (quadrilaterals) and 3D.
set -eu
. tests/tools/lib.sh
# The linear u-p model that the closed form solves: no cavitation limit (its tension
# phases reach beyond -100 kPa, where the default limit would hold the pressure).
MAT="-material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -material_soil_saturated -material_soil_porosity 0.4 -material_soil_hydraulic_conductivity 0 -fluid_cavitation_pressure none"
$SW -regions soil $MAT -mesh_box_faces 1,100 -mesh_box_upper 2,200 -constrain_components x -bc_bottom_type absorbing -bc_top_type absorbing -input_wave p \
  -input_boundary bottom -input_stf ricker -input_f0 10 -input_t0 0.12 -input_amplitude 0.1 -ts_max_time 0.6 -station_coordinates 1,60,1,140 \
  -station_names lower,upper -output_dir "$WORK" -output_fields 0 -progress_interval 100 | tee "$WORK/log" | grep -E "saturated|stable step|done"
$PY tests/tools/poroelastic.py pulse "$WORK" --lower lower --upper upper --distance 80 --limit undrained --rho 2000 --vp 400 --porosity 0.4 \
  --hydraulic-conductivity 0 --late-after 0.4 --late-max 0.01
# The same column in 3D (hexahedra, x and y held): the Hex8 coupling and storage.
$SW -mesh_dim 3 -regions soil $MAT -mesh_box_faces 1,1,100 -mesh_box_upper 2,2,200 -constrain_components x,y -bc_bottom_type absorbing -bc_top_type absorbing \
  -input_wave p -input_boundary bottom -input_stf ricker -input_f0 10 -input_t0 0.12 -input_amplitude 0.1 -ts_max_time 0.6 -station_coordinates 1,1,60,1,1,140 \
  -station_names lower,upper -output_dir "$WORK/3d" -output_fields 0 -progress_interval 100 | grep -E "done"
$PY tests/tools/poroelastic.py pulse "$WORK/3d" --component z --lower lower --upper upper --distance 80 --limit undrained --rho 2000 --vp 400 --porosity 0.4 \
  --hydraulic-conductivity 0 --late-after 0.4 --late-max 0.01

# Geostatic stage with a water table: a 20 m column, dry sand (rho 1800) above y = 12 m and
# saturated soil (rho 2000, the mixture) below, water table at y = 12 m, gravity 9.81, fixed
# base, lateral strain held. After the static solve the effective vertical stress is the
# total overburden minus the hydrostatic pore pressure (Terzaghi's effective stress;
# alpha = 1), sigma'_yy = -g int rho dy + rho_f g (12 - y)+, to round-off (the FE solution of
# a linearly varying stress is exact at cell centroids; bound 1e-9); the stations' total p is
# rho_f g (12 - y) and the column then stays at rest for 0.2 s with zero excess pressure
# (bounds 1e-9 of rho_f g z_w, 1e-9 m/s). Run with the water table at the surface too.
set -eu
. tests/tools/lib.sh
SAT="-material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -material_soil_saturated -material_soil_porosity 0.4 -material_soil_hydraulic_conductivity 1e-5"
COMMON="-element_degree $DEGREE -mesh_box_faces 1,$(elements 20) -mesh_box_upper 1,20 -constrain_components x -bc_bottom_type fixed -gravity 9.81 -geostatic_stage -ts_max_time 0.2
 -output_interval 0.1 -station_coordinates 0.5,15,0.5,5 -station_names y15,y5 -progress_interval 100"
$SW -regions dry,soil -region_dry_box 0,1,12,20 -material_dry_rho 1800 -material_dry_vp 400 -material_dry_vs 200 $SAT -water_table 12 $COMMON \
  -output_dir "$WORK/inside" | grep -E "geostatic|pore fluid|done"
$PY tests/tools/poroelastic.py geostatic "$WORK/inside" --layers 20:12:1800,12:0:2000 --water-table 12 --stations y15:15,y5:5 --stress-tol 1e-9 --v-max 1e-9
$SW -regions soil $SAT -water_table 20 -bc_top_fluid drained $COMMON -output_dir "$WORK/surface" | grep -E "geostatic|done"
$PY tests/tools/poroelastic.py geostatic "$WORK/surface" --layers 20:0:2000 --water-table 20 --stations y15:15,y5:5 --stress-tol 1e-9 --v-max 1e-9

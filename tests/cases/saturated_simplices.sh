# The undrained P pulse (k = 0, 10 Hz) on unstructured simplices: the Gmsh columns of
# gmsh_meshes.sh (triangles 4 x 100 m, tetrahedra 2 x 2 x 100 m, target size 1 m; lateral
# components held, both ends absorbing). As saturated_undrained_pulse.sh: the speed between
# stations 40 m apart within 1 % of the undrained 1705.9 m/s and p = gamma (-sigma_yy) with
# gamma = 0.945 within 2 % (Wang 2000 sec. 3.5). Measured when written: 0.03 % and 0.01 %
# (triangles), 0.03 % and 0.01 % (tetrahedra).
set -eu
. tests/tools/lib.sh
command -v gmsh >/dev/null || { echo "FAIL: gmsh is not installed"; exit 1; }
gmsh -2 tests/data/meshes/column_tri.geo -format msh41 -o "$WORK/tri.msh" > "$WORK/gmsh.log" 2>&1
gmsh -3 tests/data/meshes/column_tet.geo -format msh41 -o "$WORK/tet.msh" >> "$WORK/gmsh.log" 2>&1
# The linear u-p model that the closed form solves: no cavitation limit (its tension
# phases reach beyond -100 kPa, where the default limit would hold the pressure).
MAT="-material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -material_soil_saturated -material_soil_porosity 0.4 -material_soil_hydraulic_conductivity 0 -fluid_cavitation_pressure none"
RUN="-regions soil $MAT -bc_bottom_type absorbing -bc_top_type absorbing -input_wave p -input_boundary bottom -input_stf ricker -input_f0 10 -input_t0 0.12
 -input_amplitude 0.1 -ts_max_time 0.3 -station_names lower,upper -output_fields 0 -progress_interval 100"
$SW -mesh_file "$WORK/tri.msh" $RUN -constrain_components x -station_coordinates 2,30,2,70 -output_dir "$WORK/tri" | grep done
$PY tests/tools/poroelastic.py pulse "$WORK/tri" --lower lower --upper upper --distance 40 --limit undrained --rho 2000 --vp 400 --porosity 0.4 --hydraulic-conductivity 0
$SW -mesh_file "$WORK/tet.msh" $RUN -constrain_components x,y -station_coordinates 1,1,30,1,1,70 -output_dir "$WORK/tet" | grep done
$PY tests/tools/poroelastic.py pulse "$WORK/tet" --component z --lower lower --upper upper --distance 40 --limit undrained --rho 2000 --vp 400 --porosity 0.4 \
  --hydraulic-conductivity 0

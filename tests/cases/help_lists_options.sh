# -help documents every option group of the default scene (PetscOptionsBegin blocks with
# help text; -region_<r>_box included: it is read in its own block "Region <r>"), prints
# units, and stops before the first step.
set -eu
. tests/tools/lib.sh
$SW -options_file config/scenes/site_response_2d.yaml -help > "$WORK/help.txt"
if grep -q "^step " "$WORK/help.txt"; then echo "-help ran time steps"; exit 1; fi
missing=0
for opt in -mesh_file -mesh_dim -element_degree -mesh_box_faces -regions -region_soil_box -void_regions -interfaces -material_soil_rho -material_rock_vs -bc_bottom_type -bc_left_components \
           -bc_top_traction -gravity -constrain_components -input_wave -input_boundary -input_stf -input_f0 -damping_ratio \
           -damping_frequencies -station_file -station_coordinates -output_dir -output_interval -time_step_safety -dry_run \
           -initial_velocity -energy_growth_limit -ts_max_time -petscpartitioner_type; do
  grep -q -- "^ *$opt[ <:]" "$WORK/help.txt" || { echo "-help lacks $opt"; missing=1; }
done
grep -q "mass density \[kg/m^3\]" "$WORK/help.txt" || { echo "-help lacks units"; missing=1; }
exit $missing

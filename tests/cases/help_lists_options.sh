# -help documents every option group of the default scene (PetscOptionsBegin blocks with
# help text; -region_<r>_box included: it is read in its own block "Region <r>"), prints
# units, and stops before the first step. `slipwave -help` alone exits 0 too, reaches the
# material block (a stand-in material lets the listing go on), writes nothing in the working
# folder, and opens with slipwave's own text: PETSc's generic options (version, debugger,
# malloc) come after slipwave's, under their own heading.
set -eu
. tests/tools/lib.sh
$SW -options_file config/scenes/site_response_2d.yaml -help > "$WORK/help.txt"
if grep -q "^step " "$WORK/help.txt"; then echo "-help ran time steps"; exit 1; fi
missing=0
for opt in -mesh_file -mesh_dim -element_degree -mesh_box_faces -regions -region_soil_box -void_regions -interfaces -material_soil_rho -material_rock_vs -bc_bottom_type -bc_left_components \
           -bc_top_traction -gravity -constrain_components -input_wave -input_boundary -input_stf -input_f0 -damping_ratio \
           -damping_frequencies -station_file -station_coordinates -output_dir -output_interval -time_step_safety -ts_cd_order -dry_run \
           -initial_velocity -energy_growth_limit -ts_max_time -petscpartitioner_type; do
  grep -q -- "^ *$opt[ <:]" "$WORK/help.txt" || { echo "-help lacks $opt"; missing=1; }
done
grep -q "mass density \[kg/m^3\]" "$WORK/help.txt" || { echo "-help lacks units"; missing=1; }
WORK=$(cd "$WORK" && pwd)
mkdir "$WORK/empty"
sw_abs=$(cd "$(dirname "$SLIPWAVE_BINARY")" && pwd)/slipwave
(cd "$WORK/empty" && "$sw_abs" -help > "$WORK/alone.txt" 2> "$WORK/alone.err") || { echo "-help alone: exit status $?"; cat "$WORK/alone.err"; missing=1; }
[ ! -s "$WORK/alone.err" ] || { echo "-help alone wrote to stderr:"; cat "$WORK/alone.err"; missing=1; }
[ -z "$(ls -A "$WORK/empty")" ] || { echo "-help alone wrote in the working folder: $(ls -A "$WORK/empty")"; missing=1; }
head -1 "$WORK/alone.txt" | grep -q "^slipwave: " || { echo "-help alone does not open with slipwave's text: $(head -1 "$WORK/alone.txt")"; missing=1; }
mine=$(grep -n -- "-material_soil_rho" "$WORK/alone.txt" | head -1 | cut -d: -f1)
petsc=$(grep -n "^PETSc's own options" "$WORK/alone.txt" | cut -d: -f1)
generic=$(grep -n -- "-on_error_attach_debugger" "$WORK/alone.txt" | head -1 | cut -d: -f1)
[ -n "$mine" ] && [ -n "$petsc" ] && [ -n "$generic" ] && [ "$mine" -lt "$petsc" ] && [ "$petsc" -lt "$generic" ] ||
  { echo "-help alone: slipwave's options (line ${mine:-none}) must come before PETSc's heading (${petsc:-none}) and generic options (${generic:-none})"; missing=1; }
exit $missing

# The run report warns when a boundary other than the input boundary is fixed in the
# component the incident wave moves (a vertically incident SV wave moves x, a P wave the
# vertical y): such a side reflects the wave back instead of letting the free-field motion
# pass. Dry runs of a 20 x 10 m soil box with the wave through the absorbing bottom:
#   SV, left and right fixed in x        -> one warning per side, naming it and x;
#   SV, left and right fixed in y        -> none (y is not what SV moves);
#   P,  left and right fixed in y        -> one warning per side, naming y;
#   P,  left and right fixed in x        -> none;
#   SV, free-field sides, top fixed in x -> a warning for the top only.
set -eu
. tests/tools/lib.sh
BOX="-mesh_box_faces 20,10 -mesh_box_upper 20,10 -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200
 -bc_bottom_type absorbing -input_boundary bottom -input_stf ricker -input_f0 5 -ts_max_time 0.1 -output_fields false -dry_run -output_dir $WORK/out"
run() { # name expected-count args...
  local name=$1 expected=$2; shift 2
  $SW $BOX "$@" > "$WORK/$name.log"
  local n; n=$(grep -c "warning: boundary '.*' is fixed in" "$WORK/$name.log" || true)
  grep "warning: boundary" "$WORK/$name.log" || true
  [ "$n" = "$expected" ] || { echo "FAIL: $name: $n warnings, expected $expected"; exit 1; }
  echo "ok $name: $n warning(s)"
}
SIDES_X="-bc_left_type fixed -bc_left_components x -bc_right_type fixed -bc_right_components x"
SIDES_Y="-bc_left_type fixed -bc_left_components y -bc_right_type fixed -bc_right_components y"
run sv_rollers 2 -input_wave sv $SIDES_X
grep -q "warning: boundary 'left' is fixed in x, the component the incident SV wave moves: it holds back the free-field motion; use -bc_left_type freefield (or tied with the opposite side)" "$WORK/sv_rollers.log"
grep -q "warning: boundary 'right' is fixed in x" "$WORK/sv_rollers.log"
run sv_vertical_rollers 0 -input_wave sv $SIDES_Y
run p_vertical_rollers 2 -input_wave p $SIDES_Y
grep -q "warning: boundary 'left' is fixed in y, the component the incident P wave moves" "$WORK/p_vertical_rollers.log"
run p_rollers 0 -input_wave p $SIDES_X
run sv_freefield_top 1 -input_wave sv -bc_left_type freefield -bc_right_type freefield -bc_top_type fixed -bc_top_components x
grep -q "warning: boundary 'top' is fixed in x" "$WORK/sv_freefield_top.log"
echo PASS

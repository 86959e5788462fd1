#!/usr/bin/env bash
# The files that options name are parsed before the heavy work: a malformed ground-motion
# record (-input_record), load-factor record (-point_force_<n>_record, -bc_<b>_record of a
# traction side) or station file (-station_file) stops the run with its one-line message
# before the mesh is read, and before the output folder exists. The order is shown without
# timing: the bad-file runs name a mesh file that is not a Gmsh mesh (garbage.msh), so a run
# that read the mesh before the files would stop on the mesh's message instead of the file's
# (checked: with valid files the garbage mesh is what stops the run). The error must also
# precede every line of the set-up report (stdout empty), and on 2 ranks the message is the
# same single line. The same options with valid files set up on a box. With a Gmsh mesh
# (dimension unknown before it is read) the station rows must agree with the first one.
set -u
. tests/tools/lib.sh
fail=0
expect() { # $1 description, $2 0 = must hold
  if [ "$2" -eq 0 ]; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi
}
box="-mesh_dim 3 -mesh_box_faces 6,6,3 -mesh_box_upper 100,100,50"
scene="-regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200
 -bc_bottom_type absorbing -input_boundary bottom -input_wave sv -input_stf record
 -point_forces src -point_force_src_location 50,50,25 -point_force_src_force 0,0,1e6 -point_force_src_stf record
 -bc_top_type traction -bc_top_traction 0,0,-1e3 -bc_top_stf record -ts_max_time 0.05 -output_fields false -dry_run"
printf 'time,acceleration\n0,0\n0.01,0.5\n0.02,0.5\n0.03,0\n' > "$WORK/quake.csv"
printf 'time,acceleration\n0,0\n0.01,0.5\n0.02,nan\n0.03,0\n' > "$WORK/quake_nan.csv"
printf 'time,factor\n0,0\n0.01,1\n0.02,0\n' > "$WORK/factor.csv"
printf 'time,factor\n0,0\n0.01,1e999\n0.02,0\n' > "$WORK/factor_overflow.csv"
printf 'time,factor\n0,0\n' > "$WORK/factor_one_sample.csv"
printf 'name,x,y,z\nS1,50,50,50\n' > "$WORK/stations.csv"
printf 'name,x,y,z\nS1,50,50,50\nS2,50,50\n' > "$WORK/stations_short_row.csv"
files() { # $1 record, $2 point-force record, $3 traction record, $4 stations
  echo "-input_record $WORK/$1 -point_force_src_record $WORK/$2 -bc_top_record $WORK/$3 -station_file $WORK/$4"
}

printf 'this is not a mesh\n' > "$WORK/garbage.msh"
"$SW" $box $scene $(files quake.csv factor.csv factor.csv stations.csv) -output_dir "$WORK/good" > "$WORK/good.log" 2>&1; rc=$?
expect "the valid scene sets up on a box (exit $rc)" $rc
"$SW" -mesh_file "$WORK/garbage.msh" $scene $(files quake.csv factor.csv factor.csv stations.csv) -output_dir "$WORK/garbage" > /dev/null 2> "$WORK/garbage.err"
grep -q "^slipwave: error: -mesh_file = .*garbage\.msh: not a valid Gmsh mesh" "$WORK/garbage.err"; expect "with valid files the garbage mesh stops the run: $(cat "$WORK/garbage.err")" $?

bad() { # $1 name, $2 file arguments, $3 regex of the one stderr line
  local err out rc
  out=$("$SW" -mesh_file "$WORK/garbage.msh" $scene $2 -output_dir "$WORK/out_$1" 2> "$WORK/$1.err"); rc=$?
  err=$(cat "$WORK/$1.err")
  [ $rc -ne 0 ] && [ $rc -lt 128 ]; expect "$1: plain non-zero exit ($rc)" $?
  [ "$(grep -c '' <<<"$err")" -eq 1 ] && grep -Eq "^slipwave: error: $3" <<<"$err"; expect "$1: one line, the file's (not the mesh's): $err" $?
  [ -z "$out" ]; expect "$1: the error precedes the whole set-up report (stdout empty)" $?
  [ ! -e "$WORK/out_$1" ]; expect "$1: no output folder created" $?
}
bad record_nan "$(files quake_nan.csv factor.csv factor.csv stations.csv)" \
  '-input_record \(CSV\): .*/quake_nan\.csv:4: acceleration "nan" is not a number; allowed: a CSV file of lines "time,acceleration"'
bad load_record_overflow "$(files quake.csv factor_overflow.csv factor.csv stations.csv)" \
  '-point_force_src_record \(CSV\): .*/factor_overflow\.csv:3: factor "1e999" is not a number; allowed: a CSV file of lines "time,factor"'
bad traction_record_one_sample "$(files quake.csv factor.csv factor_one_sample.csv stations.csv)" \
  '-bc_top_record \(CSV\): .*/factor_one_sample\.csv: needs at least 2 samples, found 1; allowed: a CSV file of lines "time,factor"'
bad station_short_row "$(files quake.csv factor.csv factor.csv stations_short_row.csv)" \
  '-station_file = .*/stations_short_row\.csv, line 3: 3 columns; allowed: name,x,y,z as on the rows before$'

# With a Gmsh mesh the dimension is known only once the file is read: before it, the first
# station row sets the number of coordinates (here 3) and every row must have as many.
printf '$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n2 1 "soil"\n$EndPhysicalNames\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n$Elements\n1\n1 3 2 1 1 1 2 3 4\n$EndElements\n' > "$WORK/one_quad.msh"
out=$("$SW" -mesh_file "$WORK/one_quad.msh" -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -ts_max_time 0.01 -dry_run \
  -station_file "$WORK/stations_short_row.csv" -output_dir "$WORK/gmsh" 2>&1); rc=$?
[ $rc -ne 0 ] && [ "$out" = "slipwave: error: -station_file = $WORK/stations_short_row.csv, line 3: 3 columns; allowed: name,x,y,z as on the rows before" ]
expect "Gmsh mesh: the rows must agree before the mesh is read: $out" $?

# mpiexec adds its own lines about the failed job; slipwave's are the ones it prefixes.
err=$($MPIEXEC -n 2 "$SW" -mesh_file "$WORK/garbage.msh" $scene $(files quake_nan.csv factor.csv factor.csv stations.csv) -output_dir "$WORK/two" 2>&1 >/dev/null | grep '^slipwave:')
[ "$err" = "$(cat "$WORK/record_nan.err")" ]; expect "2 ranks: the same single line" $?
exit $fail

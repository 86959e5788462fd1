#!/usr/bin/env bash
# The files that options name are parsed before the heavy work: a malformed ground-motion
# record (-input_record), load-factor record (-point_force_<n>_record, -bc_<b>_record of a
# traction side) or station file (-station_file) stops a run on a 3D box of 108 000 hexahedra
# with its one-line message before the mesh is built, and before the output folder exists.
# Measured: the same scene with valid files (dry run: mesh, operators, stable step, report)
# takes T_setup; each bad-file run must end in under T_setup / 3 (about 4.8 s vs 0.5 s on the
# reference machine; the files are read after the mesh and bulk operator only if a bad run
# takes about T_setup, so the bound separates the two orders with a factor of 3 to spare on
# either side). The error must also precede every line of the set-up report (stdout empty),
# and on 2 ranks the message is the same single line. With a Gmsh mesh (dimension unknown
# before it is read) the station rows must agree with the first one.
set -u
. tests/tools/lib.sh
fail=0
expect() { # $1 description, $2 0 = must hold
  if [ "$2" -eq 0 ]; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi
}
now() { date +%s.%N; }
scene="-mesh_dim 3 -mesh_box_faces 60,60,30 -mesh_box_upper 100,100,50 -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200
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

t0=$(now)
"$SW" $scene $(files quake.csv factor.csv factor.csv stations.csv) -output_dir "$WORK/good" > "$WORK/good.log" 2>&1; rc=$?
t_setup=$($PY -c "print($(now) - $t0)")
expect "the valid scene sets up (exit $rc, $t_setup s)" $rc
grep -q "mesh: box 60 x 60 x 30 hexahedra, 108000 cells" "$WORK/good.log"; expect "the report names the 108000-cell box" $?

bad() { # $1 name, $2 file arguments, $3 regex of the one stderr line
  local t0 t err out rc
  t0=$(now)
  out=$("$SW" $scene $2 -output_dir "$WORK/out_$1" 2> "$WORK/$1.err"); rc=$?
  t=$($PY -c "print($(now) - $t0)")
  err=$(cat "$WORK/$1.err")
  [ $rc -ne 0 ] && [ $rc -lt 128 ]; expect "$1: plain non-zero exit ($rc)" $?
  [ "$(grep -c '' <<<"$err")" -eq 1 ] && grep -Eq "^slipwave: error: $3" <<<"$err"; expect "$1: one line: $err" $?
  [ -z "$out" ]; expect "$1: the error precedes the whole set-up report (stdout empty)" $?
  $PY -c "import sys; sys.exit(0 if $t < $t_setup / 3 else 1)"; expect "$1: fails in $t s < T_setup/3 = $t_setup/3 s" $?
  [ ! -e "$WORK/out_$1" ]; expect "$1: no output folder created" $?
}
bad record_nan "$(files quake_nan.csv factor.csv factor.csv stations.csv)" \
  '-input_record \(CSV\): .*/quake_nan\.csv:4: acceleration "nan" is not a number; allowed: a CSV file of lines "time,acceleration"'
bad load_record_overflow "$(files quake.csv factor_overflow.csv factor.csv stations.csv)" \
  '-point_force_src_record \(CSV\): .*/factor_overflow\.csv:3: acceleration "1e999" is not a number; allowed: a CSV file of lines "time,factor"'
bad traction_record_one_sample "$(files quake.csv factor.csv factor_one_sample.csv stations.csv)" \
  '-bc_top_record \(CSV\): .*/factor_one_sample\.csv: needs at least 2 samples, found 1; allowed: a CSV file of lines "time,factor"'
bad station_short_row "$(files quake.csv factor.csv factor.csv stations_short_row.csv)" \
  '-station_file = .*/stations_short_row\.csv, line 3: 3 columns; allowed: name,x,y,z$'

# With a Gmsh mesh the dimension is known only once the file is read: before it, the first
# station row sets the number of coordinates (here 3) and every row must have as many.
printf '$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n2 1 "soil"\n$EndPhysicalNames\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n$Elements\n1\n1 3 2 1 1 1 2 3 4\n$EndElements\n' > "$WORK/one_quad.msh"
out=$("$SW" -mesh_file "$WORK/one_quad.msh" -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -ts_max_time 0.01 -dry_run \
  -station_file "$WORK/stations_short_row.csv" -output_dir "$WORK/gmsh" 2>&1); rc=$?
[ $rc -ne 0 ] && [ "$out" = "slipwave: error: -station_file = $WORK/stations_short_row.csv, line 3: 3 columns; allowed: name,x,y,z as on the rows before" ]
expect "Gmsh mesh: the rows must agree before the mesh is read: $out" $?

# mpiexec adds its own lines about the failed job; slipwave's are the ones it prefixes.
err=$($MPIEXEC -n 2 "$SW" $scene $(files quake_nan.csv factor.csv factor.csv stations.csv) -output_dir "$WORK/two" 2>&1 >/dev/null | grep '^slipwave:')
[ "$err" = "$(cat "$WORK/record_nan.err")" ]; expect "2 ranks: the same single line" $?
exit $fail

#!/usr/bin/env bash
# What tests/errors/cases.txt cannot show with one failing run each:
#  - a distorted mesh runs with -mesh_quality_check warn (one warning line naming the cell and
#    its aspect) or off (silent), or with a raised -mesh_quality_max_aspect; an inverted mesh
#    stops even with warn, and on 2 ranks with the same single line as on 1 (the cell's owner
#    tells rank 0);
#  - the .petscrc PETSc reads from the working directory is scanned for options that run
#    programs, and -skip_petscrc (PETSc then does not read it) lets the run go on;
#  - a valid option file with comments, an alias and a nested -options_file is accepted.
# Meshes: two quadrilaterals in the Gmsh physical group "soil"; the second one 100 m x 1 m
# (aspect 100, above the default limit 50) or folded (nodes 3 and 4 of it swapped).
set -u
. tests/tools/lib.sh
bin="$(cd "$(dirname "$SLIPWAVE_BINARY")" && pwd)/slipwave"
soil="-material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -ts_max_time 0.01 -output_fields false -dry_run -output_dir out"
two_quads() { # $1 x of nodes 3 and 6, $2 the second element's nodes
  printf '$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n2 1 "soil"\n$EndPhysicalNames\n'
  printf '$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 %s 0 0\n4 0 1 0\n5 1 1 0\n6 %s 1 0\n$EndNodes\n' "$1" "$1"
  printf '$Elements\n2\n1 3 2 1 1 1 2 5 4\n2 3 2 1 1 %s\n$EndElements\n' "$2"
}
two_quads 101 "2 3 6 5" > "$WORK/slender.msh"
two_quads 2 "2 3 5 6" > "$WORK/bowtie.msh"
fail=0
expect() { # $1 description, $2 0 = must hold
  if [ "$2" -eq 0 ]; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi
}

out=$("$SW" -mesh_file "$WORK/slender.msh" $soil -output_dir "$WORK/o1" -mesh_quality_check warn 2>&1); rc=$?
expect "warn: a distorted mesh runs (exit $rc)" $rc
grep -q "^warning: mesh: 1 distorted cell(s), the first: cell 1 at (1, 0) (101, 0) (101, 1) (1, 1) is distorted (aspect 100," <<<"$out"
expect "warn: one warning line names cell 1, its corners and aspect 100" $?
out=$("$SW" -mesh_file "$WORK/slender.msh" $soil -output_dir "$WORK/o2" -mesh_quality_check off 2>&1); rc=$?
expect "off: a distorted mesh runs (exit $rc)" $rc
! grep -q "distorted" <<<"$out"; expect "off: no warning" $?
"$SW" -mesh_file "$WORK/slender.msh" $soil -output_dir "$WORK/o3" -mesh_quality_max_aspect 101 > /dev/null 2>&1
expect "aspect 100 passes -mesh_quality_max_aspect 101" $?

err1=$("$SW" -mesh_file "$WORK/bowtie.msh" $soil -output_dir "$WORK/o4" 2>&1 >/dev/null); rc1=$?
err2=$($MPIEXEC -n 2 "$SW" -mesh_file "$WORK/bowtie.msh" $soil -output_dir "$WORK/o5" 2>&1 >/dev/null | grep '^slipwave: error'); 
[ $rc1 -ne 0 ] && [ "$(grep -c '' <<<"$err1")" -eq 1 ] && grep -q "^slipwave: error: mesh: cell 1 at (1, 0) (2, 0) (1, 1) (2, 1) is inverted" <<<"$err1"
expect "bow-tie: one line naming cell 1 and its corners" $?
[ "$err1" = "$err2" ]; expect "bow-tie: the same single line on 2 ranks ($err2)" $?
"$SW" -mesh_file "$WORK/bowtie.msh" $soil -output_dir "$WORK/o6" -mesh_quality_check off > /dev/null 2>&1
[ $? -ne 0 ]; expect "bow-tie: -mesh_quality_check off does not let an inverted cell through" $?

base="-mesh_box_faces 1,10 -mesh_box_upper 1,10 -regions soil $soil"
rcdir="$WORK/rc"; mkdir -p "$rcdir"
printf -- '-start_in_debugger noxterm\n' > "$rcdir/.petscrc"
err=$(cd "$rcdir" && "$bin" $base 2>&1 >/dev/null); rc=$?
[ $rc -ne 0 ] && [ "$err" = "slipwave: error: .petscrc:1: -start_in_debugger runs a program; allowed in an option file: options that run no program (give debugger options on the command line)" ]
expect "./.petscrc with -start_in_debugger refused in one line ($err)" $?
(cd "$rcdir" && "$bin" $base -skip_petscrc > /dev/null 2>&1)
expect "-skip_petscrc: PETSc does not read it, the run goes on" $?

printf -- '-output_fields false\n' > "$WORK/inner.opts"
printf -- '# scene\n-dry_run  # stop after the report\nalias -dt -ts_dt\n-options_file %s\n-dt 1e-3\n' "$(pwd)/$WORK/inner.opts" > "$WORK/scene.opts"
out=$(cd "$WORK" && "$bin" -mesh_box_faces 1,10 -mesh_box_upper 1,10 -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 \
  -ts_max_time 0.01 -output_dir out -options_file scene.opts 2>&1); rc=$?
[ $rc -eq 0 ] && grep -q "time step 1.0000e-03 s" <<<"$out"
expect "a valid option file (comments, alias, nested file) is read: dt 1e-3 through the alias" $?
exit $fail

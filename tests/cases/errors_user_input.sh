#!/usr/bin/env bash
# Bad user input stops slipwave with ONE stderr line "slipwave: error: <message>" that names
# the option, the value and what is allowed. Cases: tests/errors/cases.txt (one per line:
# name | extra arguments | regex). A control run with the same base options and a valid
# material must succeed, so no case passes because of a mistake in the base command.
# Expected messages come from the checks at their sources (src/medium/materials.cpp,
# src/meshing/mesh_builder.cpp, src/input/boundary_conditions.cpp, src/input/time_function.cpp,
# src/app/simulation.cpp, src/app/initial_conditions.cpp, src/core/options_check.cpp,
# src/problem/elastodynamics.cpp, src/input/free_field.cpp); the stable limit 0.00204124 s is the Gershgorin bound the dry
# run of the control reports.
# Each case runs in its own empty working directory with -output_dir inside it: afterwards
# nothing may exist there but the output folder, the input directory must be unchanged, the
# exit must be a plain non-zero status (no signal: no abort, no uncaught exception), and no
# PETSc traceback may appear on either stream.
set -u
BUILD=${BUILD:-build}
bin="$(cd "$(dirname "$BUILD/slipwave")" && pwd)/slipwave"
[ -x "$bin" ] || { echo "missing $bin: run make build-only"; exit 1; }
tmp=$(mktemp -d); runs=$(mktemp -d); trap 'rm -rf "$tmp" "$runs"' EXIT
base="-mesh_box_faces 1,100 -mesh_box_upper 1,100 -regions soil -bc_bottom_type absorbing -input_wave sv -input_boundary bottom -input_stf ricker
 -constrain_components y -ts_max_time 0.1 -output_fields false -dry_run -output_dir out"
soil="-material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200"
printf 'garbage\nthis is not a mesh\n' > "$tmp/garbage.msh"
printf 'time,acceleration\n0,0\n0.01,0.5\n0.02,0.5\n0.03,0\n' > "$tmp/good.csv"
cp "$tmp/good.csv" "$tmp/good.txt"
printf 'time,acceleration\n0,0\n0.01,0.5\n0.02,abc\n' > "$tmp/bad.csv"
printf 'time_s,acceleration_g\n0,0\n0.01,0.05\n0.02,0\n' > "$tmp/in_g.csv"
printf 'time_s,acceleration_cm_s2\n0,0\n0.01,50\n0.02,0\n' > "$tmp/in_cm_s2.csv"
printf 'time_s,acceleration_ft_s2\n0,0\n0.01,1\n0.02,0\n' > "$tmp/in_ft.csv"
printf 'time,acceleration\n0,0\n0.01,1e200\n0.02,0\n' > "$tmp/huge.csv"
printf 'PEER\nevent\nACCELERATION TIME SERIES IN UNITS OF INCHES\nNPTS= 3, DT= .01 SEC\n0 1 0\n' > "$tmp/inches.at2"
printf 'header 1\nheader 2\nheader 3\nNPTS=    5, DT=   .0100 SEC\n 0.0 0.01 0.02\n' > "$tmp/short.at2"
# Option files: PETSc's format is one '-option [value]' per line.
printf -- '-dry_run\n' > "$tmp/good.opts"
head -c 64 "$bin" > "$tmp/binary.opts"
printf 'dry_run true\n' > "$tmp/malformed.opts"
printf -- '-ts_max_time 0.1 0.2\n' > "$tmp/extra_token.opts"
printf -- '-start_in_debugger noxterm\n' > "$tmp/debugger.opts"
printf -- '# attach gdb on error\n-on_error_attach_debugger gdb\n' > "$tmp/attach.opts"
printf -- '-display evil.example:0\n' > "$tmp/display.opts"
printf -- '-on_error_emacs evil.example\n' > "$tmp/emacs.opts"
printf -- '-options_file %s/debugger.opts\n' "$tmp" > "$tmp/nested.opts"
printf -- '-options_file %s/loop.opts\n' "$tmp" > "$tmp/loop.opts"
printf -- '-log_view :../escaped.txt\n' > "$tmp/log_view.opts"
printf 'dry_run: [\n' > "$tmp/broken.yaml"
printf '$NOD\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$ENDNOD\n$ELM\n1\n1 2 1 1 3 1 2 3\n$ENDELM\n' > "$tmp/v1.msh"
printf '$MeshFormat\n3.0 0 8\n$EndMeshFormat\n' > "$tmp/v3.msh"
# A unit after a number, keys given twice (flat, nested, in a text file), a misspelled key.
printf '# the soil, in a file\nmaterial_soil_vs: 200 m/s\n' > "$tmp/units.yaml"
printf 'material_soil_vs: 200\nmaterial_soil_vp: 400\nmaterial_soil_vs: 250\n' > "$tmp/dup.yaml"
printf 'material_soil_vs: 200\nmaterial:\n  soil_vs: 250\n' > "$tmp/dup_nested.yaml"
printf -- '-ts_max_time 0.1\n-ts_max_time 0.2\n' > "$tmp/dup.opts"
printf 'material_soil_rhoo: 2100\n' > "$tmp/typo.yaml"
printf 'start_in_debugger: noxterm\n' > "$tmp/debugger.yaml"
printf 'stop:\n  for_debugger: true\n' > "$tmp/nested_debugger.yaml"
mkdir "$tmp/adir"
: > "$tmp/empty.csv"
printf 'name,x,y\n../../x,0.5,50\n' > "$tmp/st_dotdot.csv"
# Backbone tables (-material_<r>_backbone_file): without a source, without a header, a ratio above 1.
printf 'strain_percent,G/Gmax\n0.0001,1\n0.1,0.5\n' > "$tmp/table_nosource.csv"
printf '# source: a test\n0.0001,1\n0.1,0.5\n' > "$tmp/table_noheader.csv"
printf '# source: a test\nstrain,G/Gmax\n1e-6,1\n1e-3,1.5\n' > "$tmp/table_ratio.csv"
printf 'name,x,y\nS1,0.5,50abc\n' > "$tmp/st_trailing.csv"
printf 'name,x,y\nS1,0.5,inf\n' > "$tmp/st_inf.csv"
printf 'name,x,y\nS1,0.5,50\nS1,0.5,60\n' > "$tmp/st_twice.csv"
printf 'name,x,y\n' > "$tmp/st_header_only.csv"
# Gmsh 2.2 meshes of two quadrilaterals in the physical group "soil": nodes 1-3 along y = 0,
# 4-6 along y = 1. bowtie: the second cell's last two nodes swapped (a folded map);
# zero_area: nodes 3 and 6 moved onto 2 and 5 (the second cell has no area); slender: the
# second cell 100 m long and 1 m high (aspect 100 > the default limit 50).
gmsh_two_quads() { # $1 x of nodes 3 and 6, $2 the second element's node list
  printf '$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n2 1 "soil"\n$EndPhysicalNames\n'
  printf '$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 %s 0 0\n4 0 1 0\n5 1 1 0\n6 %s 1 0\n$EndNodes\n' "$1" "$1"
  printf '$Elements\n2\n1 3 2 1 1 1 2 5 4\n2 3 2 1 1 %s\n$EndElements\n' "$2"
}
gmsh_two_quads 2 "2 3 5 6" > "$tmp/bowtie.msh"
gmsh_two_quads 1 "2 3 6 5" > "$tmp/zero_area.msh"
gmsh_two_quads 101 "2 3 6 5" > "$tmp/slender.msh"
# Two quadrilaterals side by side, "soil" (x 0..1) and "block" (x 1..2), their common edge
# (nodes 2, 5) the line group "base".
printf '$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n3\n1 3 "base"\n2 1 "soil"\n2 2 "block"\n$EndPhysicalNames\n' > "$tmp/two_regions.msh"
printf '$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 2 0 0\n4 0 1 0\n5 1 1 0\n6 2 1 0\n$EndNodes\n' >> "$tmp/two_regions.msh"
printf '$Elements\n3\n1 1 2 3 1 2 5\n2 3 2 1 1 1 2 5 4\n3 3 2 2 2 2 3 6 5\n$EndElements\n' >> "$tmp/two_regions.msh"
printf '$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2000000000\n1 0 0 0\n' > "$tmp/huge_22.msh"
printf '$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 0 1\n$EndEntities\n$Nodes\n1 1000000000 1 1000000000\n' > "$tmp/huge_41.msh"
# One hexahedron, the unit cube, in the physical group "soil", with node 7 (1,1,1) moved to
# z = $1: -1 pushes it through the bottom face (inverted), and with all of z = 0 it is flat.
gmsh_hex() {
  printf '$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n3 1 "soil"\n$EndPhysicalNames\n$Nodes\n8\n'
  printf '1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 0 %s\n6 1 0 %s\n7 1 1 %s\n8 0 1 %s\n$EndNodes\n' "$2" "$2" "$1" "$2"
  printf '$Elements\n1\n1 5 2 1 1 1 2 3 4 5 6 7 8\n$EndElements\n'
}
gmsh_hex -1 1 > "$tmp/hex_inverted.msh"
# One triangle in the physical group "soil" (for -element_degree > 1, which needs quads/hexes).
printf '$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n2 1 "soil"\n$EndPhysicalNames\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n$Elements\n1\n1 2 2 1 1 1 2 3\n$EndElements\n' > "$tmp/one_tri.msh"
gmsh_hex 0 0 > "$tmp/hex_flat.msh"
# 151 stations at 2 coordinates each: 302 values, beyond the 300 -station_coordinates holds.
stations151=$(seq 1 151 | awk '{printf "%s0.5,%g", (NR > 1 ? "," : ""), 0.5 + 0.5 * $1}')

control=$(cd "$runs" && "$bin" $base $soil 2>&1) || { echo "FAIL: the control run (base options + valid material) exits non-zero:"; echo "$control"; exit 1; }
grep -q "stable step: 2.0412e-03 s" <<<"$control" || { echo "FAIL: the control's stable step changed; update dt_above_stable_limit:"; echo "$control"; exit 1; }
echo "ok: control run succeeds"
# A word where a number belongs is caught before anything is written: a real run (no
# -dry_run) stops with its line and leaves no output folder behind.
for word in "-ts_max_time abc" "-mesh_box_faces 1,x" "-material_soil_rho heavy"; do
  rm -rf "$runs/word"; mkdir "$runs/word"
  (cd "$runs/word" && "$bin" ${base/-dry_run/} $soil $word > /dev/null 2>&1) && { echo "FAIL: $word accepted"; exit 1; }
  [ -z "$(ls -A "$runs/word")" ] || { echo "FAIL: $word left $(ls -A "$runs/word") behind"; exit 1; }
done
echo "ok: a word for a number stops before the output folder is made"
rm -rf "$runs/out"
inputs_before=$(cd "$tmp" && find . | sort)

# Each case: one line "ok: ..." or "FAIL: ..." (and its detail lines) into $runs/result.N.
run_case() { # N NAME ARGS REGEX
  local n=$1 name=$2 args=$3 regex=$4 cwd err rc lines stray inputs_after
  cwd="$runs/$n"; mkdir "$cwd"
  err=$(cd "$cwd" && "$bin" $base $args 2>&1 >"$runs/stdout.$n"); rc=$?
  lines=$(printf '%s' "$err" | grep -c '')
  stray=$(cd "$cwd" && find . -mindepth 1 -not -path './out' -not -path './out/*')
  inputs_after=$(cd "$tmp" && find . | sort)
  if [ $rc -eq 0 ]; then
    echo "FAIL: $name: exit 0 (expected an error)"
  elif [ $rc -ge 128 ]; then
    echo "FAIL: $name: killed by signal $((rc - 128)) (abort or crash):"; echo "$err" | head -4 | sed 's/^/    /'
  elif [ -n "$stray" ]; then
    echo "FAIL: $name: wrote outside -output_dir: $stray"
  elif [ "$inputs_after" != "$inputs_before" ]; then
    echo "FAIL: $name: changed the input directory:"; diff <(echo "$inputs_before") <(echo "$inputs_after") | sed 's/^/    /'
  elif [ "$lines" -ne 1 ]; then
    echo "FAIL: $name: $lines stderr lines (expected exactly one):"; echo "$err" | head -8 | sed 's/^/    /'
  elif ! grep -Eq "^slipwave: error: $regex" <<<"$err"; then
    echo "FAIL: $name: stderr does not match /^slipwave: error: $regex/:"; echo "    $err"
  elif grep -q 'PETSC ERROR\|terminate called' "$runs/stdout.$n"; then
    echo "FAIL: $name: PETSc traceback on stdout"
  else
    echo "ok: $name: $err"
  fi > "$runs/result.$n"
}
# The cases are independent (each its own working directory and output folder; the inputs
# are only read): two at a time, one per core (the 2-core machine of make test), by two
# workers taking the odd and the even cases; the results are printed in the file's order.
fail=0; n=0
cases=()
while IFS= read -r line; do
  [[ -z "${line// }" || "$line" == \#* ]] && continue
  cases+=("$line")
done < tests/errors/cases.txt
worker() { # FIRST: cases FIRST, FIRST + 2, ... (numbered from 1)
  local k line name args regex
  # Its own Open MPI session directory (as tests/tools/together.sh gives each run): two
  # isolated singletons would share one, and the first to end would remove it under the other.
  export OMPI_MCA_orte_tmpdir_base="$runs/session.$1"; mkdir "$OMPI_MCA_orte_tmpdir_base"
  for ((k = $1; k <= ${#cases[@]}; k += 2)); do
    line=${cases[k - 1]}
    IFS='|' read -r name args regex <<<"$line"
    name=$(xargs <<<"$name"); args=$(xargs <<<"$args"); regex=$(sed -e 's/^ *//' -e 's/ *$//' <<<"$regex")
    args=${args//@SOIL@/$soil}; args=${args//@TMP@/$tmp}; args=${args//@STATIONS151@/$stations151}
    run_case "$k" "$name" "$args" "$regex"
  done
}
worker 1 & w1=$!
worker 2 & w2=$!
wait $w1; wait $w2
for ((n = 1; n <= ${#cases[@]}; n++)); do
  [ -s "$runs/result.$n" ] || { echo "FAIL: case $n gave no result"; fail=1; continue; }
  cat "$runs/result.$n"
  grep -q '^FAIL: ' "$runs/result.$n" && fail=1
done
n=${#cases[@]}
[ $n -ge 80 ] || { echo "FAIL: only $n cases read from tests/errors/cases.txt"; fail=1; }
echo "$n cases"
exit $fail

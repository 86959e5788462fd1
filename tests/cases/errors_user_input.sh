#!/usr/bin/env bash
# Bad user input stops slipwave with ONE stderr line "slipwave: error: <message>" that names
# the option, the value and what is allowed. Cases: tests/errors/cases.txt (one per line:
# name | extra arguments | regex). A control run with the same base options and a valid
# material must succeed, so no case passes because of a mistake in the base command.
# Expected messages come from the checks at their sources (src/model/materials.cpp,
# src/mesh/mesh_builder.cpp, src/model/boundary_conditions.cpp, src/model/time_function.cpp,
# src/app/simulation.cpp, src/app/initial_conditions.cpp, src/core/options_check.cpp,
# src/model/elastodynamics.cpp); the stable limit 0.00204124 s is the Gershgorin bound the dry
# run of the control reports.
set -u
BUILD=${BUILD:-build}
bin="$BUILD/slipwave"
[ -x "$bin" ] || { echo "missing $bin: run make build-only"; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
base="-mesh_box_faces 1,100 -mesh_box_upper 1,100 -regions soil -bc_bottom_type absorbing -input_wave sv -input_boundary bottom -input_stf ricker
 -constrain_components y -ts_max_time 0.1 -output_fields false -dry_run -output_dir $tmp/out"
soil="-material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200"
printf 'garbage\nthis is not a mesh\n' > "$tmp/garbage.msh"
printf 'time,acceleration\n0,0\n0.01,0.5\n0.02,0.5\n0.03,0\n' > "$tmp/good.csv"
cp "$tmp/good.csv" "$tmp/good.txt"
printf 'time,acceleration\n0,0\n0.01,0.5\n0.02,abc\n' > "$tmp/bad.csv"
printf 'time_s,acceleration_g\n0,0\n0.01,0.05\n0.02,0\n' > "$tmp/in_g.csv"
printf 'time_s,acceleration_cm/s^2\n0,0\n0.01,50\n0.02,0\n' > "$tmp/in_cm.csv"
printf 'header 1\nheader 2\nheader 3\nNPTS=    5, DT=   .0100 SEC\n 0.0 0.01 0.02\n' > "$tmp/short.at2"

control=$("$bin" $base $soil 2>&1) || { echo "FAIL: the control run (base options + valid material) exits non-zero:"; echo "$control"; exit 1; }
grep -q "stable step: 2.0412e-03 s" <<<"$control" || { echo "FAIL: the control's stable step changed; update dt_above_stable_limit:"; echo "$control"; exit 1; }
echo "ok: control run succeeds"

fail=0; n=0
while IFS= read -r line; do
  [[ -z "${line// }" || "$line" == \#* ]] && continue
  IFS='|' read -r name args regex <<<"$line"
  name=$(xargs <<<"$name"); args=$(xargs <<<"$args"); regex=$(sed -e 's/^ *//' -e 's/ *$//' <<<"$regex")
  args=${args//@SOIL@/$soil}; args=${args//@TMP@/$tmp}
  n=$((n + 1))
  err=$("$bin" $base $args 2>&1 >"$tmp/stdout"); rc=$?
  lines=$(printf '%s' "$err" | grep -c '')
  if [ $rc -eq 0 ]; then
    echo "FAIL: $name: exit 0 (expected an error)"; fail=1
  elif [ "$lines" -ne 1 ]; then
    echo "FAIL: $name: $lines stderr lines (expected exactly one):"; echo "$err" | head -8 | sed 's/^/    /'; fail=1
  elif ! grep -Eq "^slipwave: error: $regex" <<<"$err"; then
    echo "FAIL: $name: stderr does not match /^slipwave: error: $regex/:"; echo "    $err"; fail=1
  elif grep -q 'PETSC ERROR' "$tmp/stdout"; then
    echo "FAIL: $name: PETSc traceback on stdout"; fail=1
  else
    echo "ok: $name: $err"
  fi
done < tests/errors/cases.txt
[ $n -ge 25 ] || { echo "FAIL: only $n cases read from tests/errors/cases.txt"; fail=1; }
echo "$n cases"
exit $fail

#!/usr/bin/env bash
# Paths in a scene file are read from the scene file's folder; paths on the command line from
# the working folder (src/core/option_files.cpp, OptionFilePathsResolve). The default scene
# and its record are copied to another folder (elsewhere/config/scenes, .../records) and run
# (-dry_run, 61 x 30 cells: about a second each) from an empty working folder:
# 1. -options_file by its absolute path: the record is found beside it (the report names
#    elsewhere/config/records/el_centro_1940_ns.csv; before, config/records/... was looked
#    for in the working folder and the run failed).
# 2. -options_file by a relative path (../elsewhere/...): the same record, by that relative path.
# 3. -input_record on the command line: a record in the working folder, by its bare name.
# 4. A record missing from the command line: the line says which folder was searched.
# 5. A record missing from a scene file: the line names the scene file and line, and the path
#    it looked for (the scene's folder).
set -eu
. tests/tools/lib.sh
W=$(cd "$WORK" && pwd)
sw=$(cd "$(dirname "$SLIPWAVE_BINARY")" && pwd)/slipwave
mkdir -p "$W/elsewhere/config/scenes" "$W/elsewhere/config/records" "$W/run"
cp config/scenes/default.yaml config/scenes/default.msh "$W/elsewhere/config/scenes/"
cp config/records/el_centro_1940_ns.csv "$W/elsewhere/config/records/"
cp config/records/el_centro_1940_ns.csv "$W/run/mine.csv"
dry="-dry_run -output_dir out -output_overwrite"
cd "$W/run"
"$sw" -options_file "$W/elsewhere/config/scenes/default.yaml" $dry > abs.log
grep -q "record $W/elsewhere/config/records/el_centro_1940_ns.csv (CSV in g, 2688 samples" abs.log || { echo "FAIL: absolute scene path: record not found beside the scene"; grep record abs.log; exit 1; }
grep -q "mesh: $W/elsewhere/config/scenes/default.msh, " abs.log || { echo "FAIL: absolute scene path: mesh not found beside the scene"; grep mesh: abs.log; exit 1; }
echo "ok: absolute scene path: the record is read from $W/elsewhere/config/records, the mesh from $W/elsewhere/config/scenes"
"$sw" -options_file ../elsewhere/config/scenes/default.yaml $dry > rel.log
grep -q "record ../elsewhere/config/records/el_centro_1940_ns.csv (CSV in g" rel.log || { echo "FAIL: relative scene path"; grep record rel.log; exit 1; }
echo "ok: relative scene path: ../elsewhere/config/records/el_centro_1940_ns.csv"
"$sw" -options_file ../elsewhere/config/scenes/default.yaml -input_record mine.csv $dry > cmd.log
grep -q "record mine.csv (CSV in g" cmd.log || { echo "FAIL: a command-line record is not read from the working folder"; grep record cmd.log; exit 1; }
echo "ok: a command-line path stays relative to the working folder"
err() { # expected regex, arguments
  local regex=$1; shift
  if "$sw" "$@" > /dev/null 2> err.txt; then echo "FAIL: accepted: $*"; exit 1; fi
  [ "$(grep -c '' err.txt)" -eq 1 ] && grep -Eq "^slipwave: error: $regex" err.txt || { echo "FAIL: expected /$regex/:"; cat err.txt; exit 1; }
  cat err.txt
}
err "-input_record \(CSV\): nothere\.csv: cannot open the file \(looked for it in $W/run\); allowed" \
  -options_file ../elsewhere/config/scenes/default.yaml -input_record nothere.csv $dry
sed 's|^input_record: .*|input_record: gone.csv|' "$W/elsewhere/config/scenes/default.yaml" > "$W/elsewhere/config/scenes/gone.yaml"
line=$(grep -n "^input_record: gone.csv" "$W/elsewhere/config/scenes/gone.yaml" | cut -d: -f1)
err "$W/elsewhere/config/scenes/gone\.yaml:$line: -input_record \(CSV\): $W/elsewhere/config/scenes/gone\.csv: cannot open the file; allowed" \
  -options_file "$W/elsewhere/config/scenes/gone.yaml" $dry

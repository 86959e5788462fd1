# The setup report reads in seconds: on the default scene the compact report (the default)
# is at most 10 lines plus one per region from its header to the first line after it
# (16 for the default scene's six regions; mesh, the regions with their soil models,
# resolution, input, damping, interface, stable step, its warning, time step, output with
# the sampling, memory and run-time estimate) and holds those; -report_verbose adds the
# details (boundaries, rigid body, interface penalty, station on the interface, set-up
# cost). The progress line says how far the run is (percent of -ts_max_time, 100.0 % at the
# last step) and the interface's stick/slip/open counts (13 pairs, all in stick in the first
# 0.2 s); the ETA is "-" before any step was timed and 0 at the end.
set -eu -o pipefail
. tests/tools/lib.sh
scene="-options_file config/scenes/default.yaml"
"$SLIPWAVE_BINARY" $scene -dry_run -output_dir "$WORK/dry" > "$WORK/compact.log"
"$SLIPWAVE_BINARY" $scene -dry_run -output_dir "$WORK/dry" -report_verbose > "$WORK/verbose.log"
cat "$WORK/compact.log"
n=$(sed -n '/^slipwave: explicit/,/^dry run/p' "$WORK/compact.log" | grep -vc "^dry run")
regions=$(grep -c "^  region " "$WORK/compact.log")
echo "compact report: $n lines (bound 10 + $regions regions); verbose: $(grep -vc '^dry run' "$WORK/verbose.log")"
[ "$n" -le $((10 + regions)) ]
for line in "^  mesh: .*default.msh, 7048 cells" "^  region rock " "^  region soil " "^  region block " "^  resolution: " "^  input: sv wave" \
            "^  interface base between soil" "^  stable step: " "^  time step " "^  output: .*6 stations every" "estimated run time"; do
  grep -q "$line" "$WORK/compact.log" || { echo "compact report lacks /$line/"; exit 1; }
done
for line in "^  boundaries: " "^  rigid body block" "penalty rule physical" "station block_base at (0, 30) lies on interface" "^  set-up: "; do
  ! grep -q "$line" "$WORK/compact.log" || { echo "compact report has the detail /$line/"; exit 1; }
  grep -q "$line" "$WORK/verbose.log" || { echo "verbose report lacks /$line/"; exit 1; }
done
"$SLIPWAVE_BINARY" $scene -ts_max_time 0.2 -progress_interval 0 -output_fields 0 -output_dir "$WORK/run" > "$WORK/run.log"
grep "^step" "$WORK/run.log" > "$WORK/progress.txt"
sed -n '1p;$p' "$WORK/progress.txt"
head -1 "$WORK/progress.txt" | grep "(  0.0 %).*ETA       - s  stick/slip/open 13/0/0" > /dev/null
tail -1 "$WORK/progress.txt" | grep "(100.0 %).*ETA     0.0 s  stick/slip/open 13/0/0" > /dev/null
[ "$(grep -c '^step' "$WORK/run.log")" -gt 100 ]

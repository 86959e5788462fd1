#!/usr/bin/env bash
# Ctrl-C (SIGINT) stops a run as cleanly as SIGTERM (output_kill.sh) and says how to resume.
# The 2D site-response scene is interrupted once its first checkpoint exists (every 200 steps):
# exit status non-zero and not a signal's (128 + n: a plain error exit), one stderr line
# "stopped by SIGINT (Ctrl-C) after step N, ..." naming the last checkpoint (the largest
# multiple of 200 <= N) and -restart <folder>/checkpoint.bin; the stations and energy.csv hold
# every step 0..N (flushed at the stop), and the run resumes from that checkpoint to its end.
# Without -checkpoint_interval the line says to give it.
set -eu
. tests/tools/lib.sh
O="-options_file config/scenes/site_response_2d.yaml -ts_max_time 10 -output_interval 0.2 -progress_interval 100 -energy_interval 1 -output_fields 0"
interrupt() {  # folder, extra options: runs until $1/$2 exists, then sends SIGINT
  local dir=$1 wait_for=$2; shift 2
  $SW $O -output_dir "$dir" "$@" > "$dir.log" 2> "$dir.err" &
  local pid=$!
  for _ in $(seq 1200); do [ -e "$dir/$wait_for" ] && break; sleep 0.05; done
  kill -s INT "$pid"
  rc=0; wait "$pid" || rc=$?
  [ "$rc" -ne 0 ] && [ "$rc" -lt 128 ] || { echo "FAIL: exit status $rc after SIGINT (expected a plain error exit)"; cat "$dir.err"; exit 1; }
  [ "$(grep -c '' "$dir.err")" -eq 1 ] || { echo "FAIL: not one stderr line:"; cat "$dir.err"; exit 1; }
  cat "$dir.err"
}
interrupt "$WORK/C" checkpoint.bin -checkpoint_interval 200
line=$(cat "$WORK/C.err")
step=$(sed -E 's/.*after step ([0-9]+),.*/\1/' <<<"$line")
last=$((step / 200 * 200))
grep -Eq "^slipwave: error: stopped by SIGINT \(Ctrl-C\) after step $step, t = .*; to resume from the last checkpoint \(step $last\): -restart $WORK/C/checkpoint.bin$" <<<"$line" ||
  { echo "FAIL: the line does not name the checkpoint of step $last"; exit 1; }
rows=$(($(grep -c '' "$WORK/C/energy.csv") - 1))
[ "$rows" -eq $((step + 1)) ] || { echo "FAIL: energy.csv holds $rows rows, expected steps 0..$step"; exit 1; }
$SW $O -ts_max_time 1 -restart "$WORK/C/checkpoint.bin" -output_dir "$WORK/R" > "$WORK/R.log"
echo "ok: resumed from step $last to t = 1 s"
interrupt "$WORK/N" energy.csv
grep -q "to be able to resume, run with -checkpoint_interval <steps>, then -restart <output_dir>/checkpoint.bin$" "$WORK/N.err" || { echo "FAIL: no resume hint"; exit 1; }
echo "ok: SIGINT stops in one line with the resume hint"

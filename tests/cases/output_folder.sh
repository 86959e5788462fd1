#!/usr/bin/env bash
# The output folder (issue 9): checked before the heavy work, never mixed with an earlier run,
# and the closing line names exactly what was written. Scene: the default scene coarsened to
# 60x30 cells and 0.1 s (an interface, stations, a few hundred steps).
# Expected (src/app/output_dir.cpp, src/app/output_frames.cpp):
# - -output_fields false: no volume.xmf/h5/frame folder, but interface_base.xmf/h5/frame folder, stations, energy.csv
#   (the option's help: "write volume fields"); the closing line lists the folder's files, no more.
# - A second run into the same folder is refused in one line naming -output_dir, before the
#   set-up (no "geostatic stage" line); -output_overwrite deletes the earlier run's files and
#   only those (a user's notes.txt stays).
# - A folder path that is too long, under a file, in a place that cannot hold folders, or
#   empty, stops in one line, exit non-zero (1, not an abort's 134), before the set-up.
set -eu
. tests/tools/lib.sh
O="-options_file config/scenes/default_linear.yaml -mesh_box_faces 61,30 -ts_max_time 0.1 -output_interval 0.05 -progress_interval 100"
$SW $O -output_fields false -output_dir "$WORK/a" > "$WORK/a.log"
closing=$(grep "^output in" "$WORK/a.log")
echo "$closing"
listed=$(sed -e 's/^output in [^ ]*: //' -e 's/ (open.*//' -e 's|stations/\*.csv|stations|' -e 's|/\*.h5||g' -e 's/, /\n/g' <<<"$closing" | sort)
present=$(ls -A "$WORK/a" | sort)
[ "$listed" = "$present" ] || { echo "FAIL: the closing line lists"; echo "$listed"; echo "but the folder holds"; echo "$present"; exit 1; }
[ ! -e "$WORK/a/volume.xmf" ] && [ ! -e "$WORK/a/volume.h5" ] && [ ! -e "$WORK/a/volume" ] || { echo "FAIL: -output_fields false wrote the volume grid"; exit 1; }
$PY scripts/check_output.py "$WORK/a" --grid interface_base --expect-steps 3
echo "ok: -output_fields false keeps the interface output and drops the volume grid; the closing line lists the folder's files"

echo "my notes" > "$WORK/a/notes.txt"
if $SW $O -output_dir "$WORK/a" > "$WORK/b.log" 2> "$WORK/b.err"; then echo "FAIL: a reused folder was accepted"; exit 1; fi
[ "$(grep -c '' "$WORK/b.err")" -eq 1 ] || { echo "FAIL: not one stderr line:"; cat "$WORK/b.err"; exit 1; }
grep -E "^slipwave: error: -output_dir = .*/a: holds the output of an earlier run \(energy.csv, input_motion.csv, interface_base, interface_base.h5, \.\.\.\); allowed: a new or empty folder, or -output_overwrite" "$WORK/b.err"
! grep -q "geostatic\|mesh:" "$WORK/b.log" || { echo "FAIL: the reused folder was refused only after the set-up"; exit 1; }
$SW $O -output_dir "$WORK/a" -output_overwrite > "$WORK/c.log"
[ -e "$WORK/a/notes.txt" ] || { echo "FAIL: -output_overwrite deleted a file that is not the run's"; exit 1; }
$PY scripts/check_output.py "$WORK/a" --expect-steps 3
echo "ok: a reused folder is refused before the set-up; -output_overwrite deletes only the earlier run's files"

long="$WORK/$(printf 'd%.0s' $(seq 3900))"
# 219 characters from the root: Open MPI 4.1's MPI-IO aborted the run (buffer overflow) on
# volume/.000000.h5.partial under such a folder, 218 ran (measured); the limit is 180.
abs=$(cd "$WORK" && pwd)/
mpi_long=$abs$(printf 'm%.0s' $(seq $((219 - ${#abs}))))
# /proc/1 refuses new folders even to root (the tests may run as root, for whom permissions
# alone do not make a folder unwritable).
for dir in "$long" "$mpi_long" "$WORK/a/notes.txt/out" /proc/1/slipwave_out ""; do
  rc=0; $SW $O -output_dir "$dir" > "$WORK/d.out" 2> "$WORK/d.err" || rc=$?
  [ $rc -eq 1 ] && [ "$(grep -c '' "$WORK/d.err")" -eq 1 ] || { echo "FAIL: -output_dir = ${dir:0:60}...: exit $rc, stderr:"; cat "$WORK/d.err"; exit 1; }
  grep -E "^slipwave: error: -output_dir = .*: .*; allowed: " "$WORK/d.err"
  ! grep -q "mesh:" "$WORK/d.out" || { echo "FAIL: -output_dir = ${dir:0:60}... refused only after the set-up"; exit 1; }
done

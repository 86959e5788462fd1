#!/bin/bash
# Convergence study of the default scene (docs/convergence-study.md): one run.
# usage: bench/study/study_run.sh TAG NP OPTIONS...   (from the slipwave directory)
# Runs config/scenes/default.yaml with OPTIONS on NP ranks into $STUDY_DIR/TAG (default
# /tmp/study), times it, writes TAG.json with bench/study/study_metrics.py and appends
# "TAG|np=NP|rc=RC|wall=S|OPTIONS" to $STUDY_DIR/index.txt. SWBIN: the executable (build/slipwave).
set -u
tag=$1; np=$2; shift 2
dir=${STUDY_DIR:-/tmp/study}
out=$dir/$tag
mkdir -p "$dir"
MPIEXEC="mpiexec --oversubscribe"
[ "$(id -u)" = 0 ] && MPIEXEC="$MPIEXEC --allow-run-as-root"
t0=$(date +%s.%N)
$MPIEXEC -n "$np" "${SWBIN:-build/slipwave}" -options_file config/scenes/default.yaml -output_dir "$out" -output_overwrite -progress_interval 1000 "$@" > "$dir/$tag.log" 2>&1
rc=$?
t1=$(date +%s.%N)
wall=$(/usr/bin/python3 -c "print(round($t1 - $t0, 1))")
/usr/bin/python3 bench/study/study_metrics.py "$out" --json "$dir/$tag.json" > "$dir/$tag.metrics" 2>&1
echo "$tag|np=$np|rc=$rc|wall=$wall|$*" >> "$dir/index.txt"
echo "$tag rc=$rc wall=$wall"

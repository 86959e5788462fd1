# The part of a batch job that does not depend on the scheduler: the executable, the scene,
# the output folder and the launch command, provenance, a dry run, the run and the plots.
# Sourced by slurm_job.sh and pbs_job.sh after they have set SELF, MODE, JOBID, NODES, NP,
# SCENE, EXTRA, OUT, SLIPWAVE_BIN, MPIEXEC, SLIPWAVE_HOME, die and SCHEDULER_LAUNCH (the
# scheduler's launcher with its rank count; empty for a local run).
BIN=${SLIPWAVE_BIN:-$SLIPWAVE_HOME/build/slipwave}
[ -x "$BIN" ] || die "no executable $BIN (run 'make build-only' in $SLIPWAVE_HOME, or set SLIPWAVE_BIN)"

if [ -f "$SCENE" ]; then SCENE=$(cd "$(dirname "$SCENE")" && pwd)/$(basename "$SCENE")
elif [ -f "$SLIPWAVE_HOME/$SCENE" ]; then SCENE=$SLIPWAVE_HOME/$SCENE
else die "scene file $SCENE not found (in $START_DIR or $SLIPWAVE_HOME)"; fi

OUT=${OUT:-${SCRATCH:-$START_DIR}/run-$JOBID}
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
read -r -a EXTRA_ARGS <<<"$EXTRA"

if [ -n "$MPIEXEC" ]; then
  read -r -a LAUNCH <<<"$MPIEXEC"
  LAUNCH+=(-n "$NP")
elif [ ${#SCHEDULER_LAUNCH[@]} -gt 0 ]; then
  LAUNCH=("${SCHEDULER_LAUNCH[@]}")
else
  LAUNCH=(mpiexec -n "$NP")
  if mpiexec --version 2>&1 | grep -qi 'open mpi\|openrte'; then
    LAUNCH+=(--oversubscribe)
    [ "$(id -u)" = 0 ] && LAUNCH+=(--allow-run-as-root)
  fi
fi
RUN=("${LAUNCH[@]}" "$BIN" -options_file "$SCENE" ${EXTRA_ARGS[@]+"${EXTRA_ARGS[@]}"})

# Provenance: the scene, the version, where and how it ran.
cp "$SCENE" "$OUT/"
{
  echo "date:      $(date -Iseconds)"
  echo "mode:      $MODE (job $JOBID)"
  echo "host:      $(hostname)"
  echo "nodes:     $NODES"
  echo "user:      ${USER:-$(id -un)}"
  echo "ranks:     $NP"
  echo "scene:     $SCENE (copied as $(basename "$SCENE"))"
  echo "extra:     $EXTRA"
  echo "slipwave:  $(git -C "$SLIPWAVE_HOME" describe --always --dirty --tags 2>/dev/null || echo 'unknown (not a git checkout)')"
  echo "binary:    $BIN"
  echo "command:   ${RUN[*]} -output_dir $OUT"
  echo "modules:"
  if type module >/dev/null 2>&1; then module list 2>&1 | sed 's/^/  /'; else echo "  (no module command)"; fi
} >"$OUT/provenance.txt"
echo "$SELF: $MODE run, job $JOBID, $NP ranks, scene $SCENE, output $OUT"

# Dry run: the report (mesh, materials, points per wavelength, stable step) without stepping.
if ! "${RUN[@]}" -dry_run -output_dir "$OUT" >"$OUT/dry_run.txt" 2>&1; then
  cat "$OUT/dry_run.txt" >&2
  die "the dry run failed (report in $OUT/dry_run.txt)"
fi
grep -E 'stable step|time step' "$OUT/dry_run.txt" || true

# The run. Its output also goes to OUT/run.log.
set +e
"${RUN[@]}" -output_dir "$OUT" 2>&1 | tee "$OUT/run.log"
rc=${PIPESTATUS[0]}
set -e
[ "$rc" -eq 0 ] || echo "$SELF: the run failed (exit $rc); see $OUT/run.log" >&2

# Plots (also of a run that stopped early, from what it wrote).
if [ -f "$OUT/energy.csv" ] && [ -x /usr/bin/python3 ] && /usr/bin/python3 -c 'import matplotlib, numpy, h5py' 2>/dev/null; then
  /usr/bin/python3 "$SLIPWAVE_HOME/scripts/plot_results.py" "$OUT" || echo "$SELF: warning: plotting failed" >&2
else
  echo "$SELF: no plots (no energy.csv, or /usr/bin/python3 without matplotlib/numpy/h5py)"
fi
echo "$SELF: output in $OUT (open volume.xmf and interface_<name>.xmf in ParaView)"
exit "$rc"

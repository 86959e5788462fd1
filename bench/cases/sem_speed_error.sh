# Speed against error of elements of degree p (issue 14's benchmark), through the real
# executable: Lamb's line load on an elastic half-space (half model, rollers on x = 0,
# absorbing right side and base, Ricker f0 10 Hz), six surface receivers at 8-28 minimum S
# wavelengths, relative L2 error of their velocity traces against the frequency-wavenumber
# solution (tests/tools/lamb_line_load.py). The domain, window and error are set out in
# bench/sem_speed_error.py, which also plans the refinement series and analyses the runs.
# Per p in SEM_BENCH_DEGREES (default "1 2 4 6") a series of meshes (SEM_BENCH_PPW_<p>: target
# GLL nodes per lambda_min; SEM_BENCH_FULL=1 adds the finest p = 1 mesh); per run: wall time of
# the time loop (the run report's "done:" line: TSSolve only, no set-up), best of
# SEM_BENCH_REPEATS (1) on SEM_BENCH_RANKS (1) ranks. Degrees above 1 are skipped, with a note,
# by a build without -element_degree. Rows to $BENCH_CSV; table and PNG plot to
# docs/spectral-elements.md (SEM_BENCH_DOC) and the PNG beside it.
# Each p > 1 runs in two modes (SEM_BENCH_MODES): central differences tuned to 0.45 of the
# stable step, and the defaults (the fourth-order integrator where it pays); the analysis
# gives the time to 1 % and to 0.1 % error per (p, mode).
# Default series: ~15 min on one idle core (p = 1 at 48 nodes per wavelength is ~4-5 min).
set -eu
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
SW="$BUILD/slipwave"
PY=/usr/bin/python3
MPIEXEC="mpiexec --oversubscribe"
[ "$(id -u)" = 0 ] && MPIEXEC="$MPIEXEC --allow-run-as-root"
RANKS=${SEM_BENCH_RANKS:-1}
REPEATS=${SEM_BENCH_REPEATS:-1}
WORK=${SEM_BENCH_WORK:-$BUILD/bench/work/sem_speed_error}
mkdir -p "$WORK"
rm -f "$WORK/manifest.txt"

eval "$($PY bench/sem_speed_error.py geometry)" # L, H, ..., and LAMB: the run's options but mesh and degree
launch="$SW"
[ "$RANKS" -gt 1 ] && launch="$MPIEXEC -n $RANKS $SW"
has_degree=0
"$SW" -help 2>/dev/null | grep -q -- "-element_degree" && has_degree=1

# Integrators (SEM_BENCH_MODES, default "tuned default"), at p > 1 (p = 1 runs once, at the
# defaults, which keep central differences there):
#   tuned:   central differences at 0.45 of the stable limit (-ts_cd_order 2 -time_step_safety
#            0.45), the best tuned setting before the fourth-order integrator (issue 14's table:
#            at p = 4, 8 nodes per wavelength, 3.1 % error at 0.9, 0.83 % at 0.45, 0.27 % at
#            0.225; its dispersion (omega dt)^2 / 24 dominated the elements');
#   default: no option: the integrator and step the code chooses (docs/spectral-elements.md:
#            the fourth-order scheme where it pays, the step that accuracy needs).
# SEM_BENCH_SAFETY_<p> still overrides the tuned mode's 0.45.
MODES=${SEM_BENCH_MODES:-tuned default}
while read -r p m nx ny; do
  degree=""
  if [ "$p" != 1 ]; then
    if [ "$has_degree" = 0 ]; then
      [ "${skipped:-}" = "$p" ] || echo "sem_speed_error: p = $p skipped: $SW has no -element_degree"
      skipped=$p; continue
    fi
    degree="-element_degree $p"
  fi
  for mode in $MODES; do
    [ "$p" = 1 ] && [ "$mode" != default ] && continue
    options=""
    if [ "$mode" = tuned ]; then
      safety_var="SEM_BENCH_SAFETY_$p"
      options="-ts_cd_order 2 -time_step_safety ${!safety_var:-0.45}"
    fi
    best=""
    for k in $(seq 1 "$REPEATS"); do
      out="$WORK/p${p}_${nx}x${ny}_${mode}_np${RANKS}_$k"
      $launch $LAMB $degree $options -mesh_box_faces "$nx,$ny" -output_dir "$out" -output_overwrite > "$out.log"
      loop=$(sed -n 's/^done: [0-9]* steps in \([0-9.]*\) s wall.*/\1/p' "$out.log")
      echo "p = $p, $nx x $ny elements, $mode: time loop $loop s"
      if [ -z "$best" ] || $PY -c "import sys; sys.exit(0 if $loop < $best else 1)"; then best=$loop; keep=$out; fi
    done
    echo "$p $m $nx $ny $RANKS $keep.log $keep/stations $mode" >> "$WORK/manifest.txt"
  done
done < <($PY bench/sem_speed_error.py plan)

$PY bench/sem_speed_error.py analyse "$WORK/manifest.txt"

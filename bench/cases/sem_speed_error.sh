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
# SEM_BENCH_2D=0 skips this 2D series.
#
# The 3D series (issue 25; SEM_BENCH_3D=0 skips it): a vertical point force (Ricker f0 10 Hz) in
# an elastic whole space, its octant meshed (three planes of symmetry), six receivers at 2-4
# minimum S wavelengths, relative L2 error of their velocity traces against a reference run
# (degree 8, 10^3 elements, fourth order at 0.45 of the stable step; its own error is measured
# against the closed form), set out in bench/sem_speed_error_3d.py. Per p in
# SEM_BENCH_3D_DEGREES (default "2 4") a series of meshes (SEM_BENCH_3D_PPW_<p>: target GLL
# nodes per lambda_min, default p = 2: "4 5 6 8", p = 4: "3 4 5 6 8"), each in
# the modes SEM_BENCH_MODES; SEM_BENCH_3D_REF="p m safety" replaces the reference run, which is
# kept in the work folder and rerun only when its options, the ranks or the executable change.
# Table to the 3D section of SEM_BENCH_DOC; CSV rows "sem_speed_error_3d,...". ~8 min on one
# core of a loaded 2-core machine (load 3.5-4), of which the reference 2 min.
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
#            the fourth-order scheme where it pays, the step that accuracy needs);
#   order4:  -ts_cd_order 4 at the code's step (for a case where the default keeps order 2);
#   reference (3D only): -ts_cd_order 4 at SEM_BENCH_3D_REF's fraction of the stable step.
# SEM_BENCH_SAFETY_<p> still overrides the tuned mode's 0.45.
MODES=${SEM_BENCH_MODES:-tuned default}

# run_mode P M FACES MODE REPEATS MANIFEST WORKDIR OPTIONS...: the run of degree P on FACES
# ("nx,ny" or "nx,ny,nz") elements in MODE, REPEATS times; the fastest time loop is kept and
# its line "P M <FACES, spaces for commas> RANKS LOG STATIONS MODE" goes to MANIFEST.
run_mode() {
  local p=$1 m=$2 faces=$3 mode=$4 repeats=$5 manifest=$6 dir=$7
  shift 7
  local degree="" options="" best="" keep="" k out loop safety_var
  [ "$p" != 1 ] && degree="-element_degree $p"
  case $mode in
    tuned) safety_var="SEM_BENCH_SAFETY_$p"; options="-ts_cd_order 2 -time_step_safety ${!safety_var:-0.45}" ;;
    default) ;;
    order4) options="-ts_cd_order 4" ;;
    reference) options="-ts_cd_order 4 -time_step_safety $REF_SAFETY" ;;
    *) echo "sem_speed_error: unknown mode $mode" >&2; return 1 ;;
  esac
  for k in $(seq 1 "$repeats"); do
    out="$dir/p${p}_${faces//,/x}_${mode}_np${RANKS}_$k"
    $launch "$@" $degree $options -mesh_box_faces "$faces" -output_dir "$out" -output_overwrite > "$out.log"
    loop=$(sed -n 's/^done: [0-9]* steps in \([0-9.]*\) s wall.*/\1/p' "$out.log")
    echo "p = $p, ${faces//,/ x } elements, $mode: time loop $loop s"
    if [ -z "$best" ] || $PY -c "import sys; sys.exit(0 if $loop < $best else 1)"; then best=$loop; keep=$out; fi
  done
  echo "$p $m ${faces//,/ } $RANKS $keep.log $keep/stations $mode" >> "$manifest"
}

# The 2D series (SEM_BENCH_2D=0 skips it): Lamb's line load.
if [ "${SEM_BENCH_2D:-1}" != 0 ]; then
  rm -f "$WORK/manifest.txt"
  while read -r p m nx ny; do
    if [ "$p" != 1 ] && [ "$has_degree" = 0 ]; then
      [ "${skipped:-}" = "$p" ] || echo "sem_speed_error: p = $p skipped: $SW has no -element_degree"
      skipped=$p; continue
    fi
    for mode in $MODES; do
      [ "$p" = 1 ] && [ "$mode" != default ] && continue
      run_mode "$p" "$m" "$nx,$ny" "$mode" "$REPEATS" "$WORK/manifest.txt" "$WORK" $LAMB
    done
  done < <($PY bench/sem_speed_error.py plan)
  $PY bench/sem_speed_error.py analyse "$WORK/manifest.txt"
fi

# The 3D series (SEM_BENCH_3D=0 skips it): a point force in a whole space, its octant meshed,
# errors against a reference run at a higher degree on a finer mesh (bench/sem_speed_error_3d.py).
if [ "${SEM_BENCH_3D:-1}" != 0 ]; then
  if [ "$has_degree" = 0 ]; then
    echo "sem_speed_error: 3D series skipped: $SW has no -element_degree"
  else
    eval "$($PY bench/sem_speed_error_3d.py geometry)" # WHOLE: the runs' options but mesh, degree, integrator; REF_P, REF_M, REF_SAFETY
    dir3="$WORK/3d"
    mkdir -p "$dir3"
    # The reference (1.5-4 min) is kept between runs of the script and run again only when its
    # options, the ranks or the executable change.
    key="$REF_P $REF_M $REF_SAFETY $RANKS $(md5sum < "$SW") $WHOLE"
    if [ -s "$dir3/reference.txt" ] && [ "$(cat "$dir3/reference.key" 2>/dev/null)" = "$key" ]; then
      echo "3D reference: kept from an earlier run ($(cut -d' ' -f7 "$dir3/reference.txt"))"
    else
      rm -f "$dir3/reference.txt" "$dir3/reference.key"
      run_mode "$REF_P" "$REF_M" "$REF_M,$REF_M,$REF_M" reference 1 "$dir3/reference.txt" "$dir3" $WHOLE
      echo "$key" > "$dir3/reference.key"
    fi
    cp "$dir3/reference.txt" "$dir3/manifest.txt"
    while read -r p m; do
      for mode in $MODES; do
        run_mode "$p" "$m" "$m,$m,$m" "$mode" "$REPEATS" "$dir3/manifest.txt" "$dir3" $WHOLE
        # Where the defaults keep central differences (the coarsest meshes, where the elements'
        # error leaves the step free) the fourth order runs too, at the code's step: with the
        # default runs that chose it, it makes the series "order4" (the analysis).
        if [ "$mode" = default ] && grep -q -- "(-ts_cd_order 2, the default)" "$(tail -n 1 "$dir3/manifest.txt" | cut -d' ' -f7)"; then
          run_mode "$p" "$m" "$m,$m,$m" order4 "$REPEATS" "$dir3/manifest.txt" "$dir3" $WHOLE
        fi
      done
    done < <($PY bench/sem_speed_error_3d.py plan)
    $PY bench/sem_speed_error_3d.py analyse "$dir3/manifest.txt"
  fi
fi

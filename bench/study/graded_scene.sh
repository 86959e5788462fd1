# Shared by the graded-cell studies of the default scene (bench/cases/default_scene_graded.sh,
# bench/cases/default_scene_mass_scaling.sh), sourced from the repository's root after WORK
# and REGIONS are set: the studies' settings (GRADED_NP ranks per run, default 1; the first
# GRADED_TIME s, default 4; GRADED_FINE, the finest cells of the graded levels), a fresh
# $WORK, $WORK/graded.yaml, the scene less its mesh, its regions and its mass scaling (each study says it; a Gmsh mesh replaces
# them; REGIONS: the mesh's regions, passed as -regions; without soil_far the scene's
# material_soil_far_* lines go too, and region soil is then the whole top sublayer, at its
# Gauss points: the scene's split gives the same answers to 0.2 %, docs/default-scene.md),
# and run TAG OPTIONS..., which runs the scene's first T s on NP ranks into $WORK/TAG, appends
# "TAG seconds" to $WORK/walls.txt and writes $WORK/TAG.json (bench/study/study_metrics.py).
set -eu
BUILD=${BUILD:-build}
PY=/usr/bin/python3
CSV=${BENCH_CSV:-}
NP=${GRADED_NP:-1}
T=${GRADED_TIME:-4}
FINE=${GRADED_FINE:-0.25 0.125 0.0625}
rm -rf "$WORK"; mkdir -p "$WORK"
MPIEXEC="mpiexec --oversubscribe"
[ "$(id -u)" = 0 ] && MPIEXEC="$MPIEXEC --allow-run-as-root"
strip="mesh_file|mesh_box|region_|regions|void_regions|mesh_dim|time_step_mass_scaling"
case ",$REGIONS," in *,soil_far,*) ;; *) strip="$strip|material_soil_far_" ;; esac
grep -vE "^($strip)" config/scenes/default.yaml > "$WORK/graded.yaml"
GRADED_OPTIONS="-options_file $WORK/graded.yaml -input_record config/records/el_centro_1940_ns.csv -regions $REGIONS"
run() { # TAG OPTIONS...
  local tag=$1; shift
  local t0; t0=$(date +%s)
  $MPIEXEC -n "$NP" "$BUILD/slipwave" "$@" -ts_max_time "$T" -output_fields 0 -progress_interval 1e7 -output_dir "$WORK/$tag" > "$WORK/$tag.log"
  echo "$tag $(( $(date +%s) - t0 ))" >> "$WORK/walls.txt"
  $PY bench/study/study_metrics.py "$WORK/$tag" --json "$WORK/$tag.json" > /dev/null
}

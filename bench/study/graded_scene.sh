# Shared by the graded-cell studies of the default scene (bench/cases/default_scene_graded.sh,
# bench/cases/default_scene_mass_scaling.sh), sourced after BUILD, PY, NP, T, WORK are set:
# $WORK/graded.yaml, the scene less its box and regions (a Gmsh mesh replaces them: region soil
# is then the whole top sublayer, at its Gauss points; the scene's split soil / soil_far gives
# the same answers to 0.2 %, docs/default-scene.md), and run TAG OPTIONS..., which runs the
# scene's first T s on NP ranks into $WORK/TAG, appends "TAG seconds" to $WORK/walls.txt and
# writes $WORK/TAG.json (bench/study/study_metrics.py).
MPIEXEC="mpiexec --oversubscribe"
[ "$(id -u)" = 0 ] && MPIEXEC="$MPIEXEC --allow-run-as-root"
grep -vE "^(mesh_box|region_|regions|void_regions|material_soil_far_|mesh_dim)" config/scenes/default.yaml > "$WORK/graded.yaml"
GRADED_OPTIONS="-options_file $WORK/graded.yaml -input_record config/records/el_centro_1940_ns.csv -regions rock,soil_low,soil_mid,soil,block"
run() { # TAG OPTIONS...
  local tag=$1; shift
  local t0; t0=$(date +%s)
  $MPIEXEC -n "$NP" "$BUILD/slipwave" "$@" -ts_max_time "$T" -output_fields 0 -progress_interval 1e7 -output_dir "$WORK/$tag" > "$WORK/$tag.log"
  echo "$tag $(( $(date +%s) - t0 ))" >> "$WORK/walls.txt"
  $PY bench/study/study_metrics.py "$WORK/$tag" --json "$WORK/$tag.json" > /dev/null
}

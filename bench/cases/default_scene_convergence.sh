# Mesh convergence of what an engineer reads from the default scene (config/scenes/default.yaml,
# El Centro 1940 N-S at 0.3 g, 15 s), and the time to its answer. scripts/convergence_check.py
# runs the scene at its own resolution and at its make-run companion's (its mesh's .geo,
# config/scenes/default.geo, at Gmsh's size factors 1 and 2: 1 m cells graded to 0.125 m at the
# block's edges, and 2 m graded to 0.25 m), and with STUDY_LEVELS=3 at the factor 1/2 too (0.5 m
# graded to 0.0625 m: some 12 times the main run), and reports every answer of
# scripts/scene_metrics.py with Roache's grid-convergence band of the main value (with three
# levels the observed order and the Richardson estimate; the table, and convergence.json in the
# main run's folder). The first 4 s against the converged estimates of the structured study:
# bench/cases/default_scene_window.sh. The wall time of the default setting is taken on 1 and 2
# ranks (the 2-rank one from the study's main level), beside the uniform 0.5 m cells' 223 s
# (issue 21). Settings: STUDY_NP (ranks per level, default 2), STUDY_LEVELS (2 or 3, default 2),
# STUDY_EXTRA (options for every run, e.g. "-ts_max_time 3" for a quick look). Rows go to
# $BENCH_CSV (benchmark,case,metric,value,unit).
set -eu
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
PY=/usr/bin/python3
CSV=${BENCH_CSV:-}
NP=${STUDY_NP:-2}
EXTRA=${STUDY_EXTRA:-}
LEVELS=${STUDY_LEVELS:-2}
WORK="$BUILD/bench/work/default_scene_convergence"
rm -rf "$WORK"; mkdir -p "$WORK"
MPIEXEC="mpiexec --oversubscribe"
[ "$(id -u)" = 0 ] && MPIEXEC="$MPIEXEC --allow-run-as-root"
t0=$(date +%s)
$MPIEXEC -n 1 "$BUILD/slipwave" -options_file config/scenes/default.yaml $EXTRA -output_fields 0 -progress_interval 1e7 -output_dir "$WORK/one_rank" > "$WORK/one_rank.log"
wall1=$(( $(date +%s) - t0 ))
$PY scripts/convergence_check.py config/scenes/default.yaml --np "$NP" --out "$WORK" --levels "$LEVELS" --companion coarser --third finer -- $EXTRA | tee "$WORK/table.txt"
$PY - "$CSV" "$WORK" "$wall1" "$NP" <<'PY'
import json, re, sys
csv, work, wall1, np_ = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
walls = {}
for level in json.load(open(f"{work}/main/convergence.json"))["levels"]:
    m = re.search(r"done: \d+ steps in ([0-9.]+) s wall", open(f"{work}/{level['name']}.log").read())
    walls[level["name"]] = float(m.group(1)) if m else float("nan")
print(f"wall time of the stepping on {np_} ranks: " + ", ".join(f"{k} {v:.1f} s" for k, v in walls.items()) +
      f"; the default scene (main) on 1 rank, whole run: {wall1} s (the old h/2 run of the elastic block: 223 s on 2 ranks)")
if csv:
    bands = json.load(open(f"{work}/main/convergence.json"))["answers"]
    with open(csv, "a") as out:
        out.write(f"default_scene_convergence,default,wall_time_1_rank,{wall1},s\n")
        for level, w in walls.items():
            out.write(f"default_scene_convergence,{level},wall_time_{np_}_ranks,{w},s\n")
        for key, b in bands.items():
            out.write(f"default_scene_convergence,{key},value,{b['value']:.6g},-\n")
            out.write(f"default_scene_convergence,{key},relative_band,{b['relative_band'] if b['relative_band'] is not None else 'nan'},1\n")
PY

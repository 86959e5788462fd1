# How far the default scene's 1 m answers are from converged (docs/convergence-study.md, "How
# far the 1 m answers are from converged"): the scene's first GRADED_TIME s (default 4: the
# first large rocking cycle at 2.7 s, the largest angle at 3.2 s) on uniform 1 m and 0.5 m
# cells, then on cells graded from 1 m to GRADED_FINE m at the block's edges and base
# (bench/study/graded_mesh.py; default 0.25 0.125 0.0625). Every block answer converges on the
# graded cells, so their three levels give each answer's observed order and Richardson estimate
# (scripts/convergence_check.py's grid_band, the same rule as make run's bands), and the table
# says each run's distance from it. About 20 minutes on one core (the 0.0625 m run: 570 s).
# One rank per run (GRADED_NP). Rows go to $BENCH_CSV (benchmark,case,metric,value,unit).
set -eu
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
PY=/usr/bin/python3
CSV=${BENCH_CSV:-}
NP=${GRADED_NP:-1}
T=${GRADED_TIME:-4}
FINE=${GRADED_FINE:-0.25 0.125 0.0625}
WORK="$BUILD/bench/work/default_scene_graded"
rm -rf "$WORK"; mkdir -p "$WORK"
MPIEXEC="mpiexec --oversubscribe"
[ "$(id -u)" = 0 ] && MPIEXEC="$MPIEXEC --allow-run-as-root"
# The graded meshes replace the scene's box and its regions: region soil is then the whole top
# sublayer (at the Gauss points; the scene's split soil / soil_far gives the same answers to
# 0.2 %, docs/default-scene.md), and the record is named from here.
grep -vE "^(mesh_box|region_|regions|void_regions|material_soil_far_|mesh_dim)" config/scenes/default.yaml > "$WORK/graded.yaml"
run() { # TAG OPTIONS...
  local tag=$1; shift
  local t0; t0=$(date +%s)
  $MPIEXEC -n "$NP" "$BUILD/slipwave" "$@" -ts_max_time "$T" -output_fields 0 -progress_interval 1e7 -output_dir "$WORK/$tag" > "$WORK/$tag.log"
  echo "$tag $(( $(date +%s) - t0 ))" >> "$WORK/walls.txt"
  $PY bench/study/study_metrics.py "$WORK/$tag" --json "$WORK/$tag.json" > /dev/null
}
run uniform_1m -options_file config/scenes/default.yaml
run uniform_0.5m -options_file config/scenes/default.yaml -mesh_box_faces 244,120
for f in $FINE; do
  $PY bench/study/graded_mesh.py "$f" > "$WORK/g$f.geo"
  gmsh -2 "$WORK/g$f.geo" -format msh41 -o "$WORK/g$f.msh" > "$WORK/g$f.gmsh.log"
  run "graded_$f" -options_file "$WORK/graded.yaml" -input_record config/records/el_centro_1940_ns.csv -mesh_file "$WORK/g$f.msh" -regions rock,soil_low,soil_mid,soil,block
done
$PY - "$WORK" "$CSV" "$NP" $FINE <<'PY'
import json, sys
import numpy as np
sys.path.insert(0, "scripts")
from convergence_check import grid_band
work, csv, np_, fine = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
tags = ["uniform_1m", "uniform_0.5m"] + [f"graded_{f}" for f in fine]
walls = dict(line.split() for line in open(f"{work}/walls.txt"))
def first_cycle(tag):
    # the largest angle of the first large cycle, 2.3-2.8 s (docs/default-scene.md)
    a = np.genfromtxt(f"{work}/{tag}/rigid_block.csv", delimiter=",", names=True)
    w = (a["t"] >= 2.3) & (a["t"] <= 2.8)
    return float(a["theta_z"][w].max()) if w.any() else float("nan")
answers = {t: json.load(open(f"{work}/{t}.json")) for t in tags}
for t in tags:
    answers[t]["first_cycle"] = first_cycle(t)
keys = [("peak_rocking_angle", 1e3, "largest angle [mrad]"), ("first_cycle", 1e3, "first large cycle [mrad]")] + \
       [(f"block_top_psa_{p}s", 1, f"block-top PSA {p} s [m/s2]") for p in ("0.1", "0.3", "0.5", "1", "2")] + \
       [(f"free_field_psa_{p}s", 1, f"free-field PSA {p} s [m/s2]") for p in ("0.3", "1")]
graded = [f"graded_{f}" for f in fine]
print("wall [s]: " + ", ".join(f"{t} {walls[t]}" for t in tags))
print("| answer | " + " | ".join(tags) + " | order | estimate | " + " | ".join(f"{t} from it" for t in tags) + " |")
print("|---" * (2 * len(tags) + 3) + "|")
rows = []
for key, scale, label in keys:
    v = [answers[t][key] * scale for t in tags]
    g = [answers[t][key] * scale for t in reversed(graded)]  # finest first
    band = grid_band(g, [2.0, 2.0], 2.0) if len(g) == 3 else None
    est = band["extrapolated"] if band else float("nan")
    order = f"{band['order_observed']:.2f}" if band and band["order_observed"] is not None else (band["note"] if band else "")
    dev = [100 * (x - est) / abs(est) if est == est and est != 0 else float("nan") for x in v]
    print(f"| {label} | " + " | ".join(f"{x:.4g}" for x in v) + f" | {order} | {est:.4g} | " + " | ".join(f"{d:+.1f} %" for d in dev) + " |")
    rows += [(key, t, x) for t, x in zip(tags, v)] + [(key, "estimate", est)]
if csv:
    with open(csv, "a") as out:
        for key, case, x in rows:
            out.write(f"default_scene_graded,{case},{key},{x},\n")
        for t in tags:
            out.write(f"default_scene_graded,{t},wall_time_{np_}_ranks,{walls[t]},s\n")
PY

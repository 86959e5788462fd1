# How far the default scene's 1 m answers are from converged (docs/convergence-study.md, "How
# far the 1 m answers are from converged"): the scene's first GRADED_TIME s (default 4: the
# first large rocking cycle at 2.7 s, the largest angle at 3.2 s) on uniform 1 m and 0.5 m
# cells, then on cells graded from 1 m to GRADED_FINE m at the block's edges and base
# (bench/study/graded_mesh.py; default 0.25 0.125 0.0625). Every block answer converges on the
# graded cells, so their three levels give each answer's observed order and Richardson estimate
# (scripts/convergence_check.py's grid_band, the same rule as make run's bands), and the table
# says each run's distance from it. About 20 minutes on one core (the 0.0625 m run: 570 s).
# One rank per run (GRADED_NP). Rows go to $BENCH_CSV (benchmark,case,metric,value,unit).
cd "$(dirname "$0")/../.."
WORK=${BUILD:-build}/bench/work/default_scene_graded
REGIONS=rock,soil_low,soil_mid,soil,block
. bench/study/graded_scene.sh
run uniform_1m -options_file config/scenes/default.yaml
run uniform_0.5m -options_file config/scenes/default.yaml -mesh_box_faces 244,120
for f in $FINE; do
  $PY bench/study/graded_mesh.py "$f" > "$WORK/g$f.geo"
  gmsh -2 "$WORK/g$f.geo" -format msh41 -o "$WORK/g$f.msh" > "$WORK/g$f.gmsh.log"
  run "graded_$f" $GRADED_OPTIONS -mesh_file "$WORK/g$f.msh"
done
levels=$(printf "graded_%s," $FINE)
$PY bench/study/graded_table.py "$WORK" default_scene_graded "$CSV" "$NP" --tags "uniform_1m,uniform_0.5m,${levels%,}" --levels "${levels%,}"

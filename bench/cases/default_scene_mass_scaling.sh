# The default scene (its own regions: Gauss points within 14 m of the block) on cells graded
# toward the block's base without structured columns
# (bench/study/graded_unstructured.geo: FINE m at the base growing by GROW m per metre, at
# most 1 m; the fine cells stay in the clay, so the bulk's step is the clay's 0.125 m cells'
# and not the rock's) with the interface nodes' mass scaled (-time_step_mass_scaling
# interface: the penalty springs no longer set the step), docs/convergence-study.md "Cells
# graded toward the block, mass scaling". First GRADED_TIME s (default 4), one rank per run
# (GRADED_NP): FINE = 0.25, 0.125, 0.0625 (GRADED_FINE) with GROW = 0.1 (GRADED_GROW), and the
# 0.125 m cells once more without mass scaling (what it changes). The table gives each answer's
# Richardson estimate from the three scaled levels and each run's distance from it and from
# the structured study's estimates (bench/study/graded_estimates.json). About 15 minutes on
# one core. Rows to $BENCH_CSV.
cd "$(dirname "$0")/../.."
WORK=${BUILD:-build}/bench/work/default_scene_mass_scaling
REGIONS=rock,soil_low,soil_mid,soil_far,soil,block
GROW=${GRADED_GROW:-0.1}
. bench/study/graded_scene.sh
for f in $FINE; do
  gmsh -2 bench/study/graded_unstructured.geo -setnumber fine "$f" -setnumber grow "$GROW" -format msh41 -o "$WORK/u$f.msh" > "$WORK/u$f.gmsh.log"
  run "scaled_$f" $GRADED_OPTIONS -mesh_file "$WORK/u$f.msh" -time_step_mass_scaling interface
done
run own_mass_0.125 $GRADED_OPTIONS -mesh_file "$WORK/u0.125.msh"
for f in $FINE; do grep -hE "^  (mesh:|mass scaling|time step)" "$WORK/scaled_$f.log"; done
levels=$(printf "scaled_%s," $FINE)
$PY bench/study/graded_table.py "$WORK" default_scene_mass_scaling "$CSV" "$NP" --tags "${levels%,},own_mass_0.125" --levels "${levels%,}" \
  --reference bench/study/graded_estimates.json

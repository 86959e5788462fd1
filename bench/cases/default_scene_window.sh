# The default scene on cells graded as the structured study's (bench/study/graded_mesh.py) but
# only in a window around the block, x = -9..9 m, y = 24..30 m, 1 m unstructured cells
# elsewhere (bench/study/graded_patch.py), with the interface nodes' mass scaled
# (-time_step_mass_scaling interface): docs/convergence-study.md, "Which limit". First
# GRADED_TIME s (default 4), one rank per run (GRADED_NP), FINE = 0.25, 0.125, 0.0625
# (GRADED_FINE); region soil is the whole top sublayer at its Gauss points, as in the structured
# study, whose estimates (bench/study/graded_estimates.json) the table compares with. About
# 10 minutes on one core. Rows to $BENCH_CSV.
cd "$(dirname "$0")/../.."
WORK=${BUILD:-build}/bench/work/default_scene_window
REGIONS=rock,soil_low,soil_mid,soil,block
. bench/study/graded_scene.sh
for f in $FINE; do
  $PY bench/study/graded_patch.py "$f" > "$WORK/w$f.geo"
  gmsh -2 "$WORK/w$f.geo" -format msh41 -o "$WORK/w$f.msh" > "$WORK/w$f.gmsh.log"
  run "window_$f" $GRADED_OPTIONS -mesh_file "$WORK/w$f.msh" -time_step_mass_scaling interface
  grep -hE "^  (mesh:|mass scaling|time step)" "$WORK/window_$f.log"
done
levels=$(printf "window_%s," $FINE)
$PY bench/study/graded_table.py "$WORK" default_scene_window "$CSV" "$NP" --tags "${levels%,}" --levels "${levels%,}" --reference bench/study/graded_estimates.json

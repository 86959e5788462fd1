# Checkpoint/restart at element degree 2 (issue 14; restart.sh's pattern): the default scene
# (geostatic stage, a sliding and lifting interface on GLL node pairs, constant-Q damping,
# free-field sides, stations) on elements of degree 2 (40 x 12 elements of 3 m x 5 m, whose
# edges hold the block's and the layers' boundaries). Run C goes to the end; run A stops
# halfway with a checkpoint; B continues from it. The state is restored bit for bit and the
# same operations follow, so B must equal C byte for byte (energy.csv, every station file).
set -eu
. tests/tools/lib.sh
O="-options_file config/scenes/default_linear.yaml -mesh_box_faces 61,12 -element_degree 2 -ts_max_time 0.4 -output_fields 0 -progress_interval 1000"
$SW $O -output_dir "$WORK/C" > "$WORK/C.log"
steps=$(tail -1 "$WORK/C/energy.csv" | cut -d, -f1)
half=$((steps / 2))
$SW $O -ts_max_steps $half -checkpoint_interval $half -output_dir "$WORK/A" > "$WORK/A.log"
cp -r "$WORK/A" "$WORK/B"
$SW $O -restart "$WORK/B/checkpoint.bin" -output_dir "$WORK/B" | grep -E "^restart|^done"
cmp "$WORK/B/energy.csv" "$WORK/C/energy.csv"
n=0
for f in "$WORK"/C/stations/*.csv; do cmp "$f" "$WORK/B/stations/$(basename "$f")"; n=$((n + 1)); done
[ $n -ge 5 ]
echo "p = 2 restart at step $half of $steps: energy.csv and $n station files identical"

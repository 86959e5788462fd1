# Checkpoint/restart (issue 5): the default scene (geostatic stage, interface that slides and
# opens, stations, fields), coarsened and shortened. Run C goes straight to the end; run A
# stops halfway and writes a checkpoint there; run B continues from it in a copy of A's
# output. B must equal C exactly: energy.csv and station files byte for byte, and every
# volume and interface output frame with zero difference (the state is restored bit for bit
# and the same operations follow).
set -eu
. tests/tools/lib.sh
O="-options_file config/scenes/default_linear.yaml -mesh_box_faces 61,30 -ts_max_time 0.8 -output_interval 0.1 -progress_interval 100"
$SW $O -output_dir "$WORK/C" > "$WORK/C.log"
steps=$(tail -1 "$WORK/C/energy.csv" | cut -d, -f1)
half=$((steps / 2))
$SW $O -ts_max_steps $half -checkpoint_interval $half -output_dir "$WORK/A" > "$WORK/A.log"
cp -r "$WORK/A" "$WORK/B"
$SW $O -restart "$WORK/B/checkpoint.bin" -output_dir "$WORK/B" | grep -E "^restart|^done"
cmp "$WORK/B/energy.csv" "$WORK/C/energy.csv"
for s in block_top block_base_left block_base_right free_field bedrock; do cmp "$WORK/B/stations/$s.csv" "$WORK/C/stations/$s.csv"; done
$PY scripts/check_output.py "$WORK/B"
$PY - "$WORK" <<'PY'
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
from frames import Frames
work = sys.argv[1]
for grid in ("volume", "interface_base"):
    b, c = Frames(f"{work}/B", grid), Frames(f"{work}/C", grid)
    if b.times != c.times:
        sys.exit(f"{grid}: frame times differ: {b.times} vs {c.times}")
    worst, frames = 0.0, 0
    for field in c.field_names(0):
        for x, y in zip(b.series(field), c.series(field)):
            worst = max(worst, float(np.abs(x - y).max()))
            frames += 1
    print(f"{grid}: {frames} field frames, largest difference {worst}")
    if worst != 0.0:
        sys.exit(1)
PY
# A restart on another number of ranks is refused with one clear line.
if $MPIEXEC -n 2 $SW $O -restart "$WORK/B/checkpoint.bin" -output_dir "$WORK/D" 2> "$WORK/D.err" > /dev/null; then echo "2-rank restart of a 1-rank checkpoint accepted"; exit 1; fi
grep -q "^slipwave: error: -restart = .* was written on 1 ranks; allowed: restart on the same number of ranks" "$WORK/D.err"
# The same with free-field lateral boundaries: the replicated columns are part of the state.
O="-options_file config/scenes/free_field_site.yaml -ts_max_time 0.6 -output_interval 0.1 -progress_interval 100"
$SW $O -output_dir "$WORK/FC" > "$WORK/FC.log"
steps=$(tail -1 "$WORK/FC/energy.csv" | cut -d, -f1)
half=$((steps / 2))
$SW $O -ts_max_steps $half -checkpoint_interval $half -output_dir "$WORK/FA" > "$WORK/FA.log"
cp -r "$WORK/FA" "$WORK/FB"
$SW $O -restart "$WORK/FB/checkpoint.bin" -output_dir "$WORK/FB" | grep -E "^restart|^done"
cmp "$WORK/FB/energy.csv" "$WORK/FC/energy.csv"
for f in "$WORK"/FC/stations/*.csv; do cmp "$f" "$WORK/FB/stations/$(basename "$f")"; done
echo "free-field restart: energy.csv and $(ls "$WORK"/FC/stations/*.csv | wc -l) station files identical"
# The same with constant-Q damping: the committed memory variables are part of the
# state, and the continued run must be bit-identical.
O="-regions rock,soil -material_soil_rho 1900 -material_soil_vp 500 -material_soil_vs 200 -material_soil_damping_ratio 0.05 -material_rock_rho 2400
 -material_rock_vp 1600 -material_rock_vs 800 -region_soil_box -10,10,0,30 -mesh_box_faces 10,20 -mesh_box_lower -10,-10 -mesh_box_upper 10,30
 -bc_bottom_type absorbing -bc_left_type absorbing -bc_right_type absorbing -input_boundary bottom -input_wave sv -input_stf ricker -input_f0 2
 -input_t0 0.6 -input_amplitude 0.1 -ts_max_time 1.0 -output_fields 0 -progress_interval 100 -station_coordinates 0,30 -station_names top"
$SW $O -output_dir "$WORK/QC" > "$WORK/QC.log"
steps=$(tail -1 "$WORK/QC/energy.csv" | cut -d, -f1)
half=$((steps / 2))
$SW $O -ts_max_steps $half -checkpoint_interval $half -output_dir "$WORK/QA" > "$WORK/QA.log"
cp -r "$WORK/QA" "$WORK/QB"
$SW $O -restart "$WORK/QB/checkpoint.bin" -output_dir "$WORK/QB" | grep -E "^restart|^done"
cmp "$WORK/QB/energy.csv" "$WORK/QC/energy.csv"
cmp "$WORK/QB/stations/top.csv" "$WORK/QC/stations/top.csv"
echo "constant-Q restart: energy.csv and the station file identical"

#!/usr/bin/env bash
# Restart into a new folder, and checkpoints that must be refused (issue 9). Scene as in
# restart.sh (the default scene, 60x30 cells, 0.8 s: geostatic stage, an interface that slides
# and opens, stations, fields). Run C goes to the end in one go; run A stops halfway with a
# checkpoint; run N continues from A's checkpoint into a NEW folder.
# Expected:
# - N's folder is complete on its own: volume.xmf and interface_base.xmf pass
#   scripts/check_output.py (every reference resolves to a dataset of its shape there, no NaN)
#   with all 9 frames (t = 0, 0.1, ..., 0.8) also once A's HDF5 files are removed, the frames,
#   energy.csv and the station files equal C's bit for bit (the continued state is
#   bit-identical, restart.sh).
# - A changed material, an added scene option, or another mesh, is refused in one line naming
#   the option and both values.
# - A checkpoint cut short, or with one byte changed, is refused in one line (its seal).
set -eu
. tests/tools/lib.sh
O="-options_file config/scenes/default_linear.yaml -mesh_box_faces 61,30 -ts_max_time 0.8 -output_interval 0.1 -progress_interval 100"
$SW $O -output_dir "$WORK/C" > "$WORK/C.log"
steps=$(tail -1 "$WORK/C/energy.csv" | cut -d, -f1)
half=$((steps / 2))
$SW $O -ts_max_steps $half -checkpoint_interval $half -output_dir "$WORK/A" > "$WORK/A.log"
$SW $O -restart "$WORK/A/checkpoint.bin" -output_dir "$WORK/N" | grep -E "^restart|^done"
# The earlier frames are N's own (hard links or copies): A's HDF5 files removed, N still holds
# all 9 frames, equal to the uninterrupted run's bit for bit (the state continues bit-identical).
rm -rf "$WORK/A/volume" "$WORK/A/volume.h5" "$WORK/A/interface_base" "$WORK/A/interface_base.h5"
for grid in volume interface_base; do $PY scripts/check_output.py "$WORK/N" --grid $grid --expect-steps 9; done
$PY - "$WORK" <<'PY'
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
from frames import Frames
w = sys.argv[1]
for grid in ("volume", "interface_base"):
    n, c = Frames(f"{w}/N", grid), Frames(f"{w}/C", grid)
    assert n.times == c.times, (grid, n.times, c.times)
    for field in c.field_names(0):
        assert all(np.array_equal(x, y) for x, y in zip(n.series(field), c.series(field))), (grid, field)
print("ok: the new folder's frames equal the uninterrupted run's")
PY
cmp "$WORK/N/energy.csv" "$WORK/C/energy.csv"
for s in block_top block_base_left block_base_right free_field bedrock; do cmp "$WORK/N/stations/$s.csv" "$WORK/C/stations/$s.csv"; done
$PY - "$WORK" <<'PY'
import sys, h5py, numpy as np
w = sys.argv[1]
with h5py.File(f"{w}/N/stations.h5") as n, h5py.File(f"{w}/C/stations.h5") as c:
    for s in c:
        for q in c[s]:
            assert np.array_equal(n[s][q][:], c[s][q][:]), (s, q)
print("ok: the new folder's stations.h5 equals the uninterrupted run's")
PY
echo "ok: restart into a new folder: complete, self-contained output equal to the uninterrupted run"

refused() {  # name, expected message regex, arguments...
  local name=$1 regex=$2; shift 2
  if $SW "$@" > /dev/null 2> "$WORK/$name.err"; then echo "FAIL: $name: accepted"; exit 1; fi
  [ "$(grep -c '' "$WORK/$name.err")" -eq 1 ] || { echo "FAIL: $name: not one stderr line:"; head -5 "$WORK/$name.err"; exit 1; }
  grep -E "^slipwave: error: $regex" "$WORK/$name.err" || { echo "FAIL: $name:"; cat "$WORK/$name.err"; exit 1; }
}
refused scene "-restart = .*/A/checkpoint.bin was written with another scene: -material_soil_vs [0-9.]+ there, 180 here; allowed: the scene options" \
  $O -material_soil_vs 180 -restart "$WORK/A/checkpoint.bin" -output_dir "$WORK/S"
refused added "-restart = .*/A/checkpoint.bin was written with another scene: -station_side not given there, soil here; allowed: the scene options" \
  $O -station_side soil -restart "$WORK/A/checkpoint.bin" -output_dir "$WORK/S2"
# Another mesh is named as the checkpoint's mismatch before the mesh is built (not as a station
# outside the smaller mesh).
refused mesh "-restart = .*/A/checkpoint.bin was written with another scene: -mesh_box_upper 61,40 there, 61,30 here; allowed: the scene options" \
  $O -mesh_box_upper 61,30 -restart "$WORK/A/checkpoint.bin" -output_dir "$WORK/S3"
size=$(stat -c %s "$WORK/A/checkpoint.bin")
head -c $((size / 2)) "$WORK/A/checkpoint.bin" > "$WORK/cut.bin"
refused truncated "-restart = .*/cut.bin: no checkpoint seal at its end \(cut short, or not a slipwave checkpoint\); allowed: a complete checkpoint" \
  $O -restart "$WORK/cut.bin" -output_dir "$WORK/T"
cp "$WORK/A/checkpoint.bin" "$WORK/flip.bin"
printf '\x5a' | dd of="$WORK/flip.bin" bs=1 seek=$((size / 3)) conv=notrunc status=none
refused damaged "-restart = .*/flip.bin: its checksum does not match \(the file is damaged\); allowed: a complete checkpoint" \
  $O -restart "$WORK/flip.bin" -output_dir "$WORK/F"

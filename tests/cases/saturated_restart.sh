#!/usr/bin/env bash
# Checkpoint/restart with saturated regions: the committed pore pressure state (p_n, alpha Q u_n,
# H p_n, the previous step's mean H p and t_n) and the ledger's fluid terms are part of the
# checkpoint. Scene config/scenes/saturated_site.yaml (geostatic stage, water table at the
# surface, drained top) shaken by the P wave, which raises an excess pore pressure that then
# drains (so the diffusion and the Darcy dissipation are active at the restart); on 1 and on
# 2 ranks. Run C goes straight to the end; run A stops halfway and writes a checkpoint; run B
# continues from it in a copy of A's output. B must equal C byte for byte: energy.csv (with
# fluid_stored, darcy_dissipated) and every station file (with p and p_excess), and the
# volume output's pore pressure frames with zero difference.
set -eu
. tests/tools/lib.sh
O="-energy_interval 1 -options_file config/scenes/saturated_site.yaml -input_wave p -ts_max_time 0.8 -output_interval 0.2 -progress_interval 100"
for ranks in 1 2; do
  R="$MPIEXEC -n $ranks"
  $R $SW $O -output_dir "$WORK/C$ranks" > "$WORK/C$ranks.log"
  steps=$(tail -1 "$WORK/C$ranks/energy.csv" | cut -d, -f1)
  half=$((steps / 2))
  $R $SW $O -ts_max_steps $half -checkpoint_interval $half -output_dir "$WORK/A$ranks" > "$WORK/A$ranks.log"
  cp -r "$WORK/A$ranks" "$WORK/B$ranks"
  $R $SW $O -restart "$WORK/B$ranks/checkpoint.bin" -output_dir "$WORK/B$ranks" | grep -E "^restart|^done"
  cmp "$WORK/B$ranks/energy.csv" "$WORK/C$ranks/energy.csv"
  for f in "$WORK/C$ranks"/stations/*.csv; do cmp "$f" "$WORK/B$ranks/stations/$(basename "$f")"; done
  $PY - "$WORK/B$ranks" "$WORK/C$ranks" "$half" <<'PY'
import csv
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
from frames import Frames
b, c, half = sys.argv[1], sys.argv[2], int(sys.argv[3])
# The restart must happen while the fluid is active: an excess pressure at the stations and
# Darcy dissipation booked both before and after the checkpoint step.
rows = list(csv.DictReader(open(f"{c}/energy.csv")))
darcy = [float(r["darcy_dissipated"]) for r in rows]
pex = max(abs(float(r["p_excess"])) for r in csv.DictReader(open(f"{c}/stations/layer_mid.csv")))
print(f"excess pore pressure at layer_mid up to {pex:.0f} Pa; Darcy dissipation {darcy[half]:.3e} J/m at the checkpoint, {darcy[-1]:.3e} at the end")
assert pex > 1e3 and 0 < darcy[half] < darcy[-1], "the fluid is not active across the restart"
worst, frames = 0.0, 0
fb, fc = Frames(b), Frames(c)
assert fb.times == fc.times, "the restarted run lists other frames"
for field in ("pore_pressure", "excess_pore_pressure", "displacement"):
    for k in range(len(fc)):
        worst = max(worst, float(np.abs(fb.field(field, k) - fc.field(field, k)).max()))
        frames += 1
print(f"volume: {frames} frames of p, p_excess, u; largest difference {worst}")
sys.exit(0 if worst == 0.0 else 1)
PY
  echo "$ranks rank(s): restart at step $half of $steps: energy.csv and $(ls "$WORK/C$ranks"/stations/*.csv | wc -l) station files identical"
done
# The same with the diffusion sub-cycled (k = 0.3 m/s: 93 sub-steps per step), where the
# restart's first step must repeat the diffusion part with the checkpoint's step, 1 rank.
O="-energy_interval 1 -options_file config/scenes/saturated_site.yaml -input_wave p -ts_max_time 0.8 -output_interval 0.2 -progress_interval 100000 -material_soil_hydraulic_conductivity 0.3"
$SW $O -output_dir "$WORK/SC" > "$WORK/SC.log"
grep "sub-cycled" "$WORK/SC.log"
steps=$(tail -1 "$WORK/SC/energy.csv" | cut -d, -f1)
half=$((steps / 2))
$SW $O -ts_max_steps $half -checkpoint_interval $half -output_dir "$WORK/SA" > "$WORK/SA.log"
cp -r "$WORK/SA" "$WORK/SB"
$SW $O -restart "$WORK/SB/checkpoint.bin" -output_dir "$WORK/SB" | grep -E "^restart"
cmp "$WORK/SB/energy.csv" "$WORK/SC/energy.csv"
for f in "$WORK"/SC/stations/*.csv; do cmp "$f" "$WORK/SB/stations/$(basename "$f")"; done
echo "sub-cycled restart: energy.csv and the station files identical"
# The same with the scene config/scenes/foundation_saturated.yaml (coarsened as in
# earlier versions of foundation_saturated.sh: 2 m cells, 3 s): a rigid block on a gap
# interface on saturated soil that sticks, slides and opens (it reads the pore pressure of
# the trial state; open gaps drain), cavities under its edges from 1.39 s, free-field sides
# and constant-Q damping.
O="-options_file config/scenes/foundation_saturated.yaml -mesh_box_faces 60,30 -region_block_box -4,4,30,40 -ts_max_time 3 -output_interval 0.5 -progress_interval 100000"
$SW $O -output_dir "$WORK/FC" > "$WORK/FC.log"
steps=$(tail -1 "$WORK/FC/energy.csv" | cut -d, -f1)
half=$((steps / 2))
$SW $O -ts_max_steps $half -checkpoint_interval $half -output_dir "$WORK/FA" > "$WORK/FA.log"
cp -r "$WORK/FA" "$WORK/FB"
$SW $O -restart "$WORK/FB/checkpoint.bin" -output_dir "$WORK/FB" | grep -E "^restart|^done"
cmp "$WORK/FB/energy.csv" "$WORK/FC/energy.csv"
for f in "$WORK"/FC/stations/*.csv; do cmp "$f" "$WORK/FB/stations/$(basename "$f")"; done
$PY - "$WORK/FB" "$WORK/FC" <<'PY'
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
from frames import Frames
b, c = Frames(sys.argv[1], "interface_base"), Frames(sys.argv[2], "interface_base")
assert b.times == c.times, "the restarted run lists other interface frames"
slip = max(float(x.max()) for x in c.series("accumulated_slip"))
worst = max(float(np.abs(b.field(f, k) - c.field(f, k)).max()) for k in range(len(c)) for f in c.field_names(k))
print(f"foundation_saturated: largest slip {slip * 1000:.1f} mm; interface frames, largest difference {worst}")
sys.exit(0 if worst == 0.0 and slip > 0.01 else 1)
PY
echo "foundation_saturated restart at step $half of $steps: energy.csv, $(ls "$WORK"/FC/stations/*.csv | wc -l) station files and the interface output identical"

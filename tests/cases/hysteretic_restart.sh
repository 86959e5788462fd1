# Checkpoint and restart with hysteretic soil (issue 22, part 3): the yielding 2D box of
# tests/cases/hysteretic_energy.sh with stations. Run C goes straight to step 2000; run A
# stops at 1000 and writes a checkpoint; run B continues from it in a copy of A's output.
# The soil's committed states are restored as they are and the update is deterministic, so
# B must equal C byte for byte: energy.csv (with hysteretic_dissipated) and the stations, and
# every volume frame (with max_shear_strain and secant_modulus_ratio) with zero difference
# (as tests/cases/restart.sh). The stations record their cell's stress and strain
# (-station_stress): the checkpoint carries those columns with the rest of the rows. Then
# the same with free-field sides (below).
set -eu
. tests/tools/lib.sh
O="-mesh_box_faces 12,8 -mesh_box_upper 30,20 -regions soil,block -region_block_box 10,20,10,20 -material_soil_rho 1800 -material_soil_vp 600
  -material_soil_vs 250 -material_soil_model hysteretic -material_soil_backbone mkz -material_soil_reference_strain 3e-4 -material_soil_curvature 0.9
  -material_soil_strength 6e4 -material_block_rho 2500 -material_block_E 3e10 -material_block_nu 0.2 -initial_velocity 0.1,0.05
  -bc_bottom_type fixed -ts_max_time 1e9 -output_interval 0.1 -progress_interval 1000 -station_coordinates 5,20,15,20,25,10 -station_names a,b,c
  -station_stress true"
$SW $O -ts_max_steps 2000 -output_dir "$WORK/C" > /dev/null
$SW $O -ts_max_steps 1000 -checkpoint_interval 1000 -output_dir "$WORK/A" > /dev/null
cp -r "$WORK/A" "$WORK/B"
$SW $O -ts_max_steps 2000 -restart "$WORK/B/checkpoint.bin" -output_dir "$WORK/B" | grep -E "^restart|^done"
head -1 "$WORK/B/energy.csv" | grep -q ",hysteretic_dissipated$"
cmp "$WORK/B/energy.csv" "$WORK/C/energy.csv"
for s in a b c; do cmp "$WORK/B/stations/$s.csv" "$WORK/C/stations/$s.csv"; done
head -1 "$WORK/B/stations/a.csv" | grep -q ",s_xx,s_yy,s_zz,s_xy,e_xx,e_yy,e_xy$"
echo "restart: energy.csv and stations a, b, c byte for byte equal to the straight run"
$PY - "$WORK" <<'PY'
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
from frames import Frames
b, c = Frames(f"{sys.argv[1]}/B"), Frames(f"{sys.argv[1]}/C")
if b.times != c.times or len(c) < 10:
    sys.exit(f"frame times differ or too few: {b.times} vs {c.times}")
names = c.field_names(0)
for n in ("max_shear_strain", "secant_modulus_ratio"):
    if n not in names:
        sys.exit(f"volume frames lack {n}")
worst = max(np.max(np.abs(b.field(n, k) - c.field(n, k))) for k in range(len(c)) for n in names)
print(f"restart: {len(c)} volume frames, fields {', '.join(names)}: largest difference {worst:.1e} (bound 0)")
sys.exit(0 if worst == 0 else 1)
PY
# Free-field sides beside the hysteretic soil (the narrow site of hysteretic_free_field.sh,
# 1400 steps): the side columns' Iwan states, their stresses and lateral memory are in their
# checkpoint record, so the restart is byte for byte equal again.
F="-regions rock,soil -material_soil_rho 1900 -material_soil_vp 500 -material_soil_vs 200 -material_soil_damping_ratio 0.05
 -material_soil_model hysteretic -material_soil_backbone mkz -material_soil_reference_strain 5e-4 -material_rock_rho 2400 -material_rock_vp 1600
 -material_rock_vs 800 -bc_bottom_type absorbing -input_boundary bottom -input_wave sv -input_stf ricker -input_f0 2 -input_t0 0.3 -input_amplitude 0.3
 -ts_max_time 1e9 -ts_dt 3e-4 -output_fields 0 -progress_interval 100000 -mesh_box_faces 20,40 -mesh_box_lower -10,-10 -mesh_box_upper 10,30
 -region_soil_box -10,10,0,30 -bc_left_type freefield -bc_right_type freefield -station_coordinates -10,30,0,30 -station_names left,centre"
$SW $F -ts_max_steps 1400 -output_dir "$WORK/FC" > /dev/null
$SW $F -ts_max_steps 700 -checkpoint_interval 700 -output_dir "$WORK/FA" > /dev/null
cp -r "$WORK/FA" "$WORK/FB"
$SW $F -ts_max_steps 1400 -restart "$WORK/FB/checkpoint.bin" -output_dir "$WORK/FB" | grep -E "^restart|^done"
cmp "$WORK/FB/energy.csv" "$WORK/FC/energy.csv"
for s in left centre; do cmp "$WORK/FB/stations/$s.csv" "$WORK/FC/stations/$s.csv"; done
echo "restart with hysteretic free-field columns: energy.csv and stations byte for byte equal to the straight run"

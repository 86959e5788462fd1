# Traction: a uniform pressure p = 1e5 Pa applied suddenly on the top of a 1D P column whose
# base is absorbing (a half-space). A traction step on a half-space sends a plane P wave with
# particle velocity v = -p/(rho vp) (momentum balance across the front: p = rho c v), so the
# top moves down at 1e5/(2000*400) = 0.125 m/s, constant once the front has left. Bound 1 %
# on the mean over 0.1 .. 0.4 s (before the front reaches the base at 0.25 s nothing else
# acts; after, the dashpot absorbs it). A sudden step is not band-limited: the mesh rings at
# its cut-off frequency around that mean, so only the mean is compared. The energy ledger
# must also close (1e-9).
set -eu
. tests/tools/lib.sh
$SW -mesh_box_faces 1,100 -mesh_box_upper 1,100 -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 \
  -bc_bottom_type absorbing -bc_top_type traction -bc_top_traction 0,-1e5 -constrain_components x -ts_max_time 0.4 -output_fields 0 \
  -progress_interval 100 -station_coordinates 0.5,100 -station_names top -output_dir "$WORK"
$PY - "$WORK/stations/top.csv" <<'PY'
import sys
import numpy as np
d = np.genfromtxt(sys.argv[1], delimiter=",", names=True)
w = (d["t"] >= 0.1) & (d["t"] <= 0.4)
v = np.mean(d["v_y"][w])
print(f"top velocity, mean over 0.1 .. 0.4 s: {v:.6f} m/s (expected -0.125)")
sys.exit(0 if abs(v / -0.125 - 1) <= 0.01 else 1)
PY
$CHECK energy "$WORK/energy.csv" --max-error 1e-9

# Rayleigh damping: a 100 m shear column (vs = 200 m/s) on a fixed base, released with a
# uniform velocity, rings mainly in its fundamental mode f1 = vs/4H = 0.5 Hz. With
# -damping_ratio 0.05 at 0.5 and 1.5 Hz the fundamental has xi = 0.05 exactly (the Rayleigh
# curve passes through both frequencies). The logarithmic decrement of successive surface
# displacement peaks gives xi = delta / sqrt(4 pi^2 + delta^2) (Chopra, Dynamics of Structures,
# eq. 2.2.12). Higher modes (2.5 Hz and up) are damped faster and are gone after ~14 s; the
# peaks after that must give xi within 1 % of 0.05.
set -eu
. tests/tools/lib.sh
$SW -mesh_box_faces 1,50 -mesh_box_upper 1,100 -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 \
  -bc_bottom_type fixed -constrain_components y -initial_velocity 0.1,0 -damping_ratio 0.05 -damping_frequencies 0.5,1.5 \
  -ts_max_time 30 -output_fields 0 -progress_interval 100 -station_coordinates 0.5,100 -station_names top -output_dir "$WORK"
$PY - "$WORK/stations/top.csv" <<'PY'
import sys
import numpy as np
d = np.genfromtxt(sys.argv[1], delimiter=",", names=True)
t, u = d["t"], d["u_x"]
peaks = np.where((u[1:-1] > u[:-2]) & (u[1:-1] > u[2:]))[0] + 1
peaks = peaks[t[peaks] > 14]
delta = np.log(u[peaks][:-1] / u[peaks][1:])
xi = delta / np.sqrt(4 * np.pi ** 2 + delta ** 2)
period = np.mean(np.diff(t[peaks]))
print(f"damped period {period:.4f} s (undamped 2 s), xi from {len(xi)} decrements: {xi.min():.5f} .. {xi.max():.5f}")
sys.exit(0 if len(xi) >= 4 and np.all(np.abs(xi / 0.05 - 1) <= 0.01) else 1)
PY

# Convergence: the L2 error of the surface velocity of the SV column against the closed form
# 2 v_in(t - H/c) on three meshes (h = 2, 1, 0.5 m). Linear elements with lumped mass and
# central differences at a fixed fraction of the stable step are second order in space and
# time, so each halving must divide the error by about 4: the observed rate must be >= 1.8.
set -eu
. tests/tools/lib.sh
errs=()
for n in 50 100 200; do
  $SW $COLUMN -mesh_box_faces 1,$n -mesh_box_upper 1,100 -input_wave sv -constrain_components y -ts_max_time 1.2 \
    -station_coordinates 0.5,100 -station_names top -output_dir "$WORK/n$n" > "$WORK/n$n.log"
  errs+=("$($CHECK column-error "$WORK/n$n/stations/top.csv" --height 100 --speed 200 --amplitude 0.1 --f0 5 --t0 0.24)")
done
$PY - "${errs[@]}" <<'PY'
import math, sys
e = [float(x) for x in sys.argv[1:]]
rates = [math.log(e[i] / e[i + 1], 2) for i in range(len(e) - 1)]
print("errors", " ".join(f"{x:.3e}" for x in e), "rates", " ".join(f"{r:.2f}" for r in rates))
sys.exit(0 if min(rates) >= 1.8 else 1)
PY

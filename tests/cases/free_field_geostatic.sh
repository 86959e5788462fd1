# Geostatic stage with free-field sides (issue 5 item 2). During the stage a free-field side
# holds only its normal (horizontal) component, like a roller, and the absorbing base only the
# vertical; then both become their reactions. Soil 10 m wide, 10 m deep (0.5 m cells) (rho 2000, vp 600,
# vs 300), gravity 9.81, no input.
# Expected: sigma_yy = -rho g (H - y) (1D equilibrium: the free-field sides act as rollers, so
# the column is laterally confined), bound 1 % of rho g H; and at rest in the dynamic stage:
# |u| below 1.4e-6 m, 1e-3 of the column's static settlement rho g H^2 / (2 (lambda + 2 mu))
# (the bound of tests/cases/geostatic_stage.sh, same column). The free-field columns carry
# only the dynamic part and stay at rest.
set -eu
. tests/tools/lib.sh
$SW -mesh_box_faces 20,20 -mesh_box_upper 10,10 -regions soil -material_soil_rho 2000 -material_soil_vp 600 -material_soil_vs 300 \
  -bc_bottom_type absorbing -bc_left_type freefield -bc_right_type freefield -gravity 9.81 -geostatic_stage -ts_max_time 0.5 -output_interval 0.25 \
  -progress_interval 100 -output_dir "$WORK" | grep geostatic
$PY - "$WORK" <<'PY'
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
from frames import Frames
f = Frames(sys.argv[1])
xyz, cells = f.geometry, f.topology
s0 = f.field("stress", 0)
drift = max(np.abs(u).max() for u in f.series("displacement"))
y = xyz[cells][:, :, 1].mean(axis=1)
err = np.max(np.abs(s0[:, 4] + 2000 * 9.81 * (10 - y))) / (2000 * 9.81 * 10)
print(f"free-field geostatic: sigma_yy error {err:.2e} of rho g H (bound 1e-2); largest |u| in the dynamic stage {drift:.2e} m (bound 1.4e-6)")
sys.exit(0 if err <= 1e-2 and drift <= 1.4e-6 else 1)
PY

# Gravity: a 10 m column (rho 2000, vp 400; horizontal motion held) on a fixed base, loaded by
# gravity from rest and brought to rest by heavy Rayleigh damping (0.3 at 5 and 20 Hz; the
# fundamental at vp/4H = 10 Hz then has xi = 0.24 and decays as exp(-xi*2*pi*10*t), 3e-7 at 1 s).
# The static answer is sigma_yy(y) = -rho g (H - y). In 1D, linear elements with lumped
# gravity give the exact nodal displacements, and the constant strain of a cell equals the
# exact strain at its midpoint, so the cell stress matches at the centroids: bound 1e-4 of
# rho g H (the residual vibration). The energy ledger must close with the damping booked
# (balance error below 1e-9 of the largest energy). SEM_DEGREE: the same at another element
# degree with as many nodes (tests/cases/sem_gravity_column.sh).
set -eu
. tests/tools/lib.sh
$SW -mesh_box_faces 1,$(elements 20) -element_degree "$DEGREE" -mesh_box_upper 1,10 -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 \
  -bc_bottom_type fixed -constrain_components x -gravity 9.81 -damping_ratio 0.3 -damping_frequencies 5,20 -ts_max_time 1.0 \
  -output_interval 0.5 -progress_interval 1000000 -output_dir "$WORK" > "$WORK.log"
balance=$(sed -n 's/^done: .*energy balance error \([-0-9.e+]*\) of the largest energy.*/\1/p' "$WORK.log")
$PY -c "import sys; b = abs(float('$balance')); print(f'energy balance error {b:.2e} (bound 1e-9)'); sys.exit(0 if b <= 1e-9 else 1)"
$PY - "$WORK" <<'PY'
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
from frames import Frames
f = Frames(sys.argv[1])
xyz, cells = f.geometry, f.topology
stress = f.field("stress", -1)
y = xyz[cells][:, :, 1].mean(axis=1)
syy = stress[:, 4]  # row-major 3x3: index 4 is yy
exact = -2000 * 9.81 * (10 - y)
err = np.max(np.abs(syy - exact)) / (2000 * 9.81 * 10)
print(f"sigma_yy at {len(y)} centroids: largest error {err:.2e} of rho g H (bound 1e-4)")
sys.exit(0 if err <= 1e-4 else 1)
PY

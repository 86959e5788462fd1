# Closed systems with constant-Q damping (issue 8): a 2D two-material box (Quad4, both regions
# damped differently) and a 3D box (Hex8), bottom fixed, released with a uniform initial
# velocity, 2000 steps. The ledger books the memory forces' work as `anelastic`; the shadow-
# energy identity of central difference holds for any force history (energy_ledger.hpp), so
# the balance error stays at round-off: bound 1e-9 relative (as tests/cases/energy_closed.sh).
# With nothing put in, the mechanisms must have taken energy: anelastic > 0 at the end.
set -eu
. tests/tools/lib.sh
# -energy_interval 1: this test reads the ledger at every step (row count, per-step rows).
common="-bc_bottom_type fixed -ts_max_steps 2000 -ts_max_time 1e9 -output_fields 0 -progress_interval 100 -energy_interval 1"
$SW -mesh_box_faces 12,8 -mesh_box_upper 30,20 -regions soil,block -region_block_box 10,20,10,20 -material_soil_rho 1800 -material_soil_vp 600 \
  -material_soil_vs 250 -material_soil_damping_ratio 0.05 -material_block_rho 2500 -material_block_E 3e10 -material_block_nu 0.2 -material_block_damping_ratio 0.01 \
  -initial_velocity 0.1,0.05 $common -output_dir "$WORK/2d" > /dev/null
$CHECK energy "$WORK/2d/energy.csv" --max-error 1e-9 --min-rows 2001
$SW -mesh_dim 3 -mesh_box_faces 4,4,8 -mesh_box_upper 10,10,20 -regions soil -material_soil_rho 1800 -material_soil_vp 600 -material_soil_vs 250 \
  -material_soil_damping_ratio 0.05 -initial_velocity 0.1,0.05,0.02 $common -output_dir "$WORK/3d" > /dev/null
$CHECK energy "$WORK/3d/energy.csv" --max-error 1e-9 --min-rows 2001
$PY - "$WORK" <<'PY'
import sys
import numpy as np
ok = True
for case in ("2d", "3d"):
    d = np.genfromtxt(f"{sys.argv[1]}/{case}/energy.csv", delimiter=",", names=True)
    e0, e1, a = d["kinetic"][0] + d["strain"][0], d["kinetic"][-1] + d["strain"][-1], d["anelastic"][-1]
    print(f"{case}: kinetic + strain {e0:.4e} J at the start, {e1:.4e} J at the end; the mechanisms took {a:.4e} J")
    ok = ok and a > 0
sys.exit(0 if ok else 1)
PY

# Geostatic stage at element degree 4 (issue 14): the column of geostatic_stage.sh (10 m, rho
# 2000, vp 600, vs 300, rollers on the sides) with 5 elements of degree 4 instead of 20 cells.
# The static answer u_y(y) is quadratic, sigma_yy = -rho g (H - y) and, with no lateral strain,
# sigma_xx = lambda/(lambda + 2 mu) sigma_yy = 0.5 sigma_yy (K0 of plane strain). A quadratic lies
# in the degree-4 space and GLL quadrature with 5 points integrates the stiffness (degree 6)
# and the lumped gravity load (degree 4) exactly, so the Galerkin answer is the exact one, and
# the stress the element basis gives at the sub-cell centres is exact to round-off: bound 1e-10
# of rho g H, on 1 and 2 ranks. The solve's matrix is preallocated from the element pattern
# (static_equilibrium.cpp): a missing entry would stop the run (MAT_NEW_NONZERO_ALLOCATION_ERR).
set -eu
. tests/tools/lib.sh
soil="-material_soil_rho 2000 -material_soil_vp 600 -material_soil_vs 300 -bc_bottom_type absorbing -bc_left_type fixed -bc_left_components x
 -bc_right_type fixed -bc_right_components x -gravity 9.81 -geostatic_stage -ts_max_time 0.02 -output_interval 0.02 -progress_interval 100"
$SW -mesh_box_faces 1,5 -mesh_box_upper 1,10 -element_degree 4 -regions soil $soil -output_dir "$WORK/one" | grep "geostatic stage: static solve"
$MPIEXEC -n 2 $SW -mesh_box_faces 1,5 -mesh_box_upper 1,10 -element_degree 4 -regions soil $soil -output_dir "$WORK/two" | grep "geostatic stage: static solve"
$PY - "$WORK" <<'PY'
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
from frames import Frames
ok = True
for run in ("one", "two"):
    f = Frames(f"{sys.argv[1]}/{run}")
    y = f.geometry[f.topology][:, :, 1].mean(axis=1)
    s0 = f.field("stress", 0)
    exact = -2000 * 9.81 * (10 - y)
    err_v = np.max(np.abs(s0[:, 4] - exact)) / (2000 * 9.81 * 10)
    err_h = np.max(np.abs(s0[:, 0] - 0.5 * exact)) / (2000 * 9.81 * 10)
    print(f"{run} rank(s), p = 4, {len(y)} sub-cells: sigma_yy error {err_v:.2e}, sigma_xx = K0 sigma_yy error {err_h:.2e} of rho g H (bound 1e-10)")
    ok &= err_v <= 1e-10 and err_h <= 1e-10
sys.exit(0 if ok else 1)
PY
# Dynamic relaxation at p = 4 (geostatic_stage.sh's case 4, 4x fewer elements: 5 x 5 of 4 m):
# its step is the certified element bound's, shrunk for the local damping; it must converge.
$SW -mesh_box_faces 5,5 -mesh_box_upper 20,20 -element_degree 4 -regions soil -material_soil_rho 2000 -material_soil_vp 600 -material_soil_vs 300 \
  -bc_bottom_type fixed -bc_left_type fixed -bc_left_components x -bc_right_type fixed -bc_right_components x -gravity 9.81 -geostatic_stage \
  -geostatic_method relaxation -ts_max_time 0.05 -output_fields 0 -progress_interval 100 -output_dir "$WORK/relax" | grep "geostatic stage: at rest"

# Geostatic stage (issue 5): gravity equilibrium by dynamic relaxation before shaking.
# 1. A 10 m soil column (rho 2000) on an absorbing base with rollers on the sides: after the
#    stage the vertical stress is sigma_yy = -rho g (H - y) (1D equilibrium); bound 1 %.
# 2. A 4 m wide, 1 m high footing (rho 2400) resting on a 20 m wide soil surface through a
#    frictional interface: the area-weighted mean normal traction under it equals its weight
#    over its base area, -rho g h = -23544 Pa (vertical equilibrium of the footing); bound 1 %.
#    The weights are the lumped face integration of the pairs (trapezoid rule on the pair
#    positions).
# 3. Without input the dynamic stage stays at rest: |u| below 1e-3 of the column's static
#    settlement rho g H^2 / (2 (lambda + 2 mu)) = 1.36e-3 m, i.e. 1.4e-6 m. (The stage stops at
#    an unbalanced-force ratio of 1e-5; the bound allows 100 x that for the dynamic
#    amplification and the way the residual is spread.)
set -eu
. tests/tools/lib.sh
soil="-material_soil_rho 2000 -material_soil_vp 600 -material_soil_vs 300 -bc_bottom_type absorbing -bc_left_type fixed -bc_left_components x
 -bc_right_type fixed -bc_right_components x -gravity 9.81 -geostatic_stage -ts_max_time 0.5 -output_interval 0.25 -progress_interval 100"
$SW -mesh_box_faces 2,20 -mesh_box_upper 1,10 -regions soil $soil -output_dir "$WORK/column" | grep geostatic
$SW -mesh_box_faces 20,11 -mesh_box_upper 20,11 -regions soil,air,block -region_soil_box 0,20,0,10 -region_air_box 0,20,10,11 -region_block_box 8,12,10,11 \
  -void_regions air -material_block_rho 2400 -material_block_vp 3000 -material_block_vs 1800 -interfaces base -interface_base_regions soil,block $soil \
  -output_dir "$WORK/footing" | grep geostatic
$PY - "$WORK" <<'PY'
import sys
import h5py
import numpy as np
work = sys.argv[1]
ok = True
with h5py.File(f"{work}/column/volume.h5") as f:
    xyz, cells = f["/geometry"][:], f["/topology"][:]
    s0 = f["/fields/stress/000000"][:]
    steps = sorted(f["/fields/displacement"].keys())
    drift = max(np.abs(f["/fields/displacement/" + k][:]).max() for k in steps)
y = xyz[cells][:, :, 1].mean(axis=1)
exact = -2000 * 9.81 * (10 - y)
err = np.max(np.abs(s0[:, 4] - exact)) / (2000 * 9.81 * 10)
print(f"column: sigma_yy error {err:.2e} of rho g H (bound 1e-2); largest |u| in the dynamic stage {drift:.2e} m (bound 1.4e-6)")
ok &= err <= 1e-2 and drift <= 1.4e-6
with h5py.File(f"{work}/footing/interface_base.h5") as f:
    x = f["/geometry"][:, 0]
    sn = f["/fields/sigma_N/000000"][:, 0]
order = np.argsort(x)
x, sn = x[order], sn[order]
mean = np.trapz(sn, x) / (x[-1] - x[0])
rel = abs(mean / -23544.0 - 1)
print(f"footing: mean sigma_N {mean:.1f} Pa (weight/area -23544 Pa), relative error {rel:.2e} (bound 1e-2)")
ok &= rel <= 1e-2
sys.exit(0 if ok else 1)
PY
# 4. A coarse mesh (2 m cells, the relaxation step near the limit) converges: local damping
#    raises the effective stiffness by up to 1 + alpha, which the stage's step must allow for
#    (it diverged at step 940 before).
$SW -mesh_box_faces 10,10 -mesh_box_upper 20,20 -regions soil -material_soil_rho 2000 -material_soil_vp 600 -material_soil_vs 300 -bc_bottom_type fixed \
  -bc_left_type fixed -bc_left_components x -bc_right_type fixed -bc_right_components x -gravity 9.81 -geostatic_stage -ts_max_time 0.05 -output_fields 0 \
  -progress_interval 100 -output_dir "$WORK/coarse" | grep "geostatic stage: at rest"

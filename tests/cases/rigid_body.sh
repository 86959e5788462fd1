#!/usr/bin/env bash
# Rigid regions (-material_<r>_model rigid, problem/rigid_bodies.hpp) against closed forms.
# 1. Two rigid bodies on the interface springs: a base (2 m x 1 m, rho 3000: M2 = 6000 kg/m)
#    and a block on it (2 m x 1 m, rho 2000: M1 = 4000 kg/m), both free in space (no gravity,
#    free sides), joined by the interface (E = 1e9 Pa/m over the 2 m width: k = 2e9 N/m per m;
#    no contact damping), a constant force F = -1e6 N/m pushing the block down from t = 0.
#    The gap z = u1 - u2 obeys z'' = F/M1 - w^2 z, w^2 = k (1/M1 + 1/M2), and central
#    differences started from rest (v_1/2 = dt/2 a_0) solve it exactly as
#    z_n = F/(M1 w^2) (1 - cos(W t_n)), cos(W dt) = 1 - w^2 dt^2/2; the centre of mass moves
#    as F/(M1 + M2) t^2/2. Both to 1e-9 (round-off: 4e-12 measured), no horizontal motion,
#    the energy balance to 1e-10, and the same histories on 2 ranks to 1e-9. The automatic
#    step must be stable with no deforming region at all (the bodies' own bound).
# 2. One free rigid block (2 m x 1 m on 4 x 2 cells, rho 2000) under a constant moment
#    M = 1e5 N m/m and force (3e5, 0) N/m: theta = M/J t^2/2 and U = F/m t^2/2 exactly (constant
#    accelerations), J = sum m_i |r_i|^2 of the lumped masses (rho hx hy/4 per cell corner)
#    about their centroid, computed here from the grid; a station at (2, 1) (r = (1, 0.5) from
#    the centroid) moves U + theta x r (small rotations), to 1e-9; rigid_block.csv gives theta
#    and U (its mass centre) themselves, to 1e-9.
# 3. The sliding block of interface_newmark_block.sh with its block rigid: Newmark's permanent
#    slip within the same 2 % (the elastic block's flexibility term is gone).
set -eu
. tests/tools/lib.sh
two="-mesh_dim 2 -mesh_box_faces 4,4 -mesh_box_lower 0,0 -mesh_box_upper 2,2 -regions base,block -region_block_box 0,2,1,2
 -material_base_rho 3000 -material_base_vp 3000 -material_base_vs 1800 -material_base_model rigid
 -material_block_rho 2000 -material_block_vp 3000 -material_block_vs 1800 -material_block_model rigid
 -interfaces base -interface_base_regions base,block -interface_base_phi 30 -interface_base_psi 0 -interface_base_c 0
 -interface_base_E 1e9 -interface_base_G 1e9 -interface_base_contact_damping 0
 -structure_load_region block -structure_load_force 0,-1e6 -ts_max_time 0.05 -output_interval 0.01
 -station_coordinates 1,1.5,1,0.5 -station_names block,base -progress_interval 1000"
$SW $two -output_dir "$WORK/two" > "$WORK/two.log"
$MPIEXEC -n 2 $SW $two -output_dir "$WORK/two_np2" > "$WORK/two_np2.log"
grep -E "rigid body|stable step|energy balance" "$WORK/two.log"
one="-mesh_dim 2 -mesh_box_faces 4,2 -mesh_box_lower 0,0 -mesh_box_upper 2,1 -regions block
 -material_block_rho 2000 -material_block_vp 3000 -material_block_vs 1800 -material_block_model rigid
 -structure_load_region block -structure_load_force 3e5,0 -structure_load_moment 1e5 -ts_dt 1e-3 -ts_max_time 0.1 -output_interval 0.05
 -station_coordinates 2,1 -station_names corner -progress_interval 1000"
$SW $one -output_dir "$WORK/one" > "$WORK/one.log"
newmark_pulse "$WORK/pulse.csv"
$SW -options_file config/scenes/sliding_block.yaml -material_block_model rigid -bc_bottom_record "$WORK/pulse.csv" -output_dir "$WORK/newmark" > "$WORK/newmark.log"
$PY tests/tools/interface_checks.py newmark --out-dir "$WORK/newmark" --interface slide --base "$WORK/newmark/stations/base.csv" \
  --block "$WORK/newmark/stations/mid.csv" --energy "$WORK/newmark/energy.csv" --A 0.4 --N 0.2 --tp 0.2 --sigma-n 23544 --area 1 \
  --t-settled 0.45 --tol 0.02 --stuck-tol 1e-2
$PY - "$WORK" <<'PY'
import re, sys
import numpy as np
sys.path.insert(0, "python")
from slipwave import read_csv
work, ok = sys.argv[1], True
def check(label, value, bound):
    global ok
    good = value <= bound
    ok &= good
    print(f"{'ok' if good else 'FAIL'} {label}: {value:.2e} (bound {bound:.0e})")
def balance(log):
    return abs(float(re.search(r"energy balance error (\S+) of the largest energy", open(log).read()).group(1)))
# 1. two bodies on springs
M1, M2, k, F = 4000.0, 6000.0, 2e9, -1e6
b, s = read_csv(f"{work}/two/stations/block.csv"), read_csv(f"{work}/two/stations/base.csv")
t, z = b["t"], b["u_y"] - s["u_y"]
dt = t[1] - t[0]
w2 = k * (1 / M1 + 1 / M2)
W = np.arccos(1 - w2 * dt * dt / 2) / dt
zs = F / (M1 * w2)
check("gap against the discrete closed form, relative to F/(M1 w^2)", np.max(np.abs(z - zs * (1 - np.cos(W * t)))) / abs(zs), 1e-9)
cm = (M1 * b["u_y"] + M2 * s["u_y"]) / (M1 + M2)
check("centre of mass against F/(M1+M2) t^2/2, relative", np.max(np.abs(cm - F / (M1 + M2) * t**2 / 2)) / np.max(np.abs(cm)), 1e-9)
check("horizontal motion relative to the gap", max(np.max(np.abs(b["u_x"])), np.max(np.abs(s["u_x"]))) / abs(zs), 1e-9)
check("energy balance error", balance(f"{work}/two.log"), 1e-10)
for name in ("block", "base"):
    one, two = read_csv(f"{work}/two/stations/{name}.csv"), read_csv(f"{work}/two_np2/stations/{name}.csv")
    check(f"1 vs 2 ranks, station {name}", np.max(np.abs(one["u_y"] - two["u_y"])) / np.max(np.abs(one["u_y"])), 1e-9)
# 2. free block under a moment and a force
rho, hx, hy, nx, ny = 2000.0, 0.5, 0.5, 4, 2
x, y = np.meshgrid(np.arange(nx + 1) * hx, np.arange(ny + 1) * hy, indexing="ij")
wx = np.where((np.arange(nx + 1) == 0) | (np.arange(nx + 1) == nx), 0.5, 1.0)
wy = np.where((np.arange(ny + 1) == 0) | (np.arange(ny + 1) == ny), 0.5, 1.0)
m = rho * hx * hy * np.outer(wx, wy)
mass = m.sum()
xc, yc = (m * x).sum() / mass, (m * y).sum() / mass
J = (m * ((x - xc) ** 2 + (y - yc) ** 2)).sum()
c = read_csv(f"{work}/one/stations/corner.csv")
theta, U = 1e5 / J * c["t"] ** 2 / 2, 3e5 / mass * c["t"] ** 2 / 2
rx, ry = 2 - xc, 1 - yc
scale = np.max(np.abs(theta)) * np.hypot(rx, ry)
check("free block: u_x = U - theta r_y, relative", np.max(np.abs(c["u_x"] - (U - theta * ry))) / np.max(np.abs(U)), 1e-9)
check("free block: u_y = theta r_x, relative", np.max(np.abs(c["u_y"] - theta * rx)) / scale, 1e-9)
check("free block energy balance error", balance(f"{work}/one.log"), 1e-10)
r = read_csv(f"{work}/one/rigid_block.csv")
theta_r, U_r = 1e5 / J * r["t"] ** 2 / 2, 3e5 / mass * r["t"] ** 2 / 2
check("rigid_block.csv: theta_z = M/J t^2/2, relative", np.max(np.abs(r["theta_z"] - theta_r)) / np.max(np.abs(theta_r)), 1e-9)
check("rigid_block.csv: u_x of the mass centre = F/m t^2/2, relative", np.max(np.abs(r["u_x"] - U_r)) / np.max(np.abs(U_r)), 1e-9)
check("rigid_block.csv: u_y of the mass centre = 0, relative to u_x", np.max(np.abs(r["u_y"])) / np.max(np.abs(U_r)), 1e-9)
sys.exit(0 if ok else 1)
PY

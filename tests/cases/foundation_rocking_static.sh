# Static rocking stiffness of a rigid strip footing on an elastic half-space (issue 12): a
# moment M = 1e5 N m/m on a 4 m wide, 1 m high footing (B = 2 m half-width; 25 x the soil's
# shear modulus, so rigid to well under 1 %) welded to the surface of soil with G = 2e7 Pa,
# nu = 1/3 (vp = 2 vs). Closed form (the tilted rigid punch, Muskhelishvili; Gazetas 1991,
# table for strip foundations): K_r = pi G B^2 / (2 (1 - nu)) = 1.885e8 N m/rad per m.
# The moment is spread over the footing's nodes by -structure_load_moment (a linear
# distribution about their centroid), applied by a cosine ramp over 2 s (-structure_load_stf
# record) and held; the sides and base are fixed 8 B from the footing. Undamped, the model
# then oscillates about the static state; the mean over 2.2 .. 3 s is the static rotation
# theta = (u_y(right) - u_y(left)) / (2 B) of the footing's base corners (the oscillation is
# below 1e-3 of it). The finite element solution is stiffer than the exact one and the
# punch's r^(-1/2) edge stresses make its stiffness converge as O(h) (energy error
# O(h^(1/2)), squared), so two meshes, h = B/4 and B/8, must both be stiffer, the finer one
# less, and the Richardson extrapolation 2 K(h/2) - K(h) must be within 10 % of K_r (issue
# 12's bound; the fixed boundary at 8 B adds about 2 %: 1.5 % less at 15 B). Measured at
# commit time: 1.167 and 1.114 K_r, extrapolated 1.061 K_r. The coarse run on 2 ranks matches
# 1 rank to 1e-10 (each footing node carries its share once, whatever the partition); the
# accelerations to 1e-6 of their peak: in this quasi-static run M a is the small residual of
# much larger nodal forces (K u), whose round-off it inherits (2e-8 measured).
set -eu
. tests/tools/lib.sh
$PY - "$WORK/ramp.csv" <<'PY'
import sys
import numpy as np
t = np.linspace(0, 2, 401)
np.savetxt(sys.argv[1], np.c_[t, 0.5 * (1 - np.cos(np.pi * t / 2))], delimiter=",", header="time,factor", comments="")
PY
rocking="-mesh_box_upper 32,17 -regions soil,air,footing -region_soil_box 0,32,0,16 -region_air_box 0,32,16,17 -region_footing_box 14,18,16,17 -void_regions air
 -material_soil_rho 2000 -material_soil_vp 200 -material_soil_vs 100 -material_footing_rho 2000 -material_footing_vp 1000 -material_footing_vs 500
 -bc_left_type fixed -bc_right_type fixed -bc_bottom_type fixed -structure_load_region footing -structure_load_moment 1e5 -structure_load_stf record
 -structure_load_record $WORK/ramp.csv -ts_max_time 3 -output_fields 0 -progress_interval 1000000 -station_coordinates 14,16,18,16 -station_names L,R"
$SW $rocking -mesh_box_faces 64,34 -output_dir "$WORK/h" | grep "load: structure load on 'footing' (27 nodes, centroid (16, 16.5)): force (0, 0), moment (100000)"
$SW $rocking -mesh_box_faces 128,68 -output_dir "$WORK/h2" > /dev/null
$MPIEXEC -n 2 $SW $rocking -mesh_box_faces 64,34 -output_dir "$WORK/h_np2" > /dev/null
$CHECK stations-equal "$WORK/h" "$WORK/h_np2" --names L,R --tol 1e-10 --tol-a 1e-6
$PY - "$WORK" <<'PY'
import sys
import numpy as np
work = sys.argv[1]
G, nu, B, M = 2000 * 100.0**2, 1 / 3, 2.0, 1e5
K_r = np.pi * G * B * B / (2 * (1 - nu))
K = []
for run in ("h", "h2"):
    L = np.genfromtxt(f"{work}/{run}/stations/L.csv", delimiter=",", names=True)
    R = np.genfromtxt(f"{work}/{run}/stations/R.csv", delimiter=",", names=True)
    theta = (R["u_y"] - L["u_y"]) / (2 * B)
    w = L["t"] >= 2.2
    spread = theta[w].std() / theta[w].mean()
    K.append(M / theta[w].mean())
    print(f"rocking, mesh {run}: K = {K[-1]:.4e} N m/rad/m = {K[-1] / K_r:.4f} K_r (oscillation {spread:.1e} of theta)")
    if spread > 1e-3:
        sys.exit(1)
extrapolated = 2 * K[1] - K[0]
rel = extrapolated / K_r - 1
print(f"rocking: K_r = pi G B^2/(2(1-nu)) = {K_r:.4e}; extrapolated 2 K(h/2) - K(h) = {extrapolated:.4e} ({rel:+.3f}, bound 0.10)")
sys.exit(0 if K[0] > K[1] > K_r and abs(rel) <= 0.10 else 1)
PY

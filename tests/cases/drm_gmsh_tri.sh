# Domain Reduction Method on an unstructured Gmsh mesh (issue 12 item 1: the layer given as a
# region): tests/data/meshes/drm_halfspace_tri.geo, linear triangles of target size 1.25 m in a
# 200 m x 100 m half-space (rho 2000, vp 400, vs 200); the interior is the physical surface
# "inner" (-drm_regions inner), the layer the "outer" triangles along it. Plane SV at 20 deg,
# Ricker f0 = 3 Hz. The free-field site comes from the line x = -100 + h/100 crossing the
# triangles (exact crossings: an overlap or a gap would stop the run).
# Expected, as in tests/cases/drm_halfspace.sh: inside, the analytical free field (incident +
# reflected, Aki & Richards coefficients) within 2 % relative L2 (issue); outside the layer
# below 1 % of the incident peak (issue). The reference point is the one the run reports (the
# upstream, deepest e nodes, which the unstructured mesh places where it likes). 2 ranks give
# the 1-rank records inside to round-off (1e-9 of each quantity's peak, the bound of
# tests/cases/gmsh_meshes.sh for triangles on 2 ranks; measured 1.7e-10).
set -eu
. tests/tools/lib.sh
command -v gmsh >/dev/null || { echo "FAIL: gmsh is not installed"; exit 1; }
gmsh -2 tests/data/meshes/drm_halfspace_tri.geo -format msh41 -o "$WORK/tri.msh" > "$WORK/gmsh.log" 2>&1 || { cat "$WORK/gmsh.log"; exit 1; }
model="-mesh_file $WORK/tri.msh -regions inner,outer -material_inner_rho 2000 -material_inner_vp 400 -material_inner_vs 200 -material_outer_rho 2000
 -material_outer_vp 400 -material_outer_vs 200 -bc_left_type absorbing -bc_right_type absorbing -bc_bottom_type absorbing -input_method drm
 -drm_regions inner -drm_wave sv -drm_incidence_angle 20 -drm_stf ricker -drm_f0 3 -drm_t0 0.4 -drm_amplitude 0.1 -ts_max_time 1.3 -output_fields 0
 -progress_interval 100000 -station_coordinates -60,0,0,0,60,0,0,-50,-99.7,-50,99.7,-30,0,-99.7 -station_names s1,s2,s3,mid,left_out,right_out,base_out"
$SW $model -output_dir "$WORK/one" | tee "$WORK/one.log"
$MPIEXEC -n 2 $SW $model -output_dir "$WORK/two" > "$WORK/two.log"
$CHECK stations-equal "$WORK/one" "$WORK/two" --names s1,s2,s3,mid --tol 1e-9
$PY - "$WORK" <<'PY'
import re
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
from plane_wave_halfspace import HalfspacePlaneWave, ricker_velocity
w = sys.argv[1]
zr, xr = map(float, re.search(r"reference point: depth ([-0-9.e+]+) m, x = ([-0-9.e+]+) m", open(f"{w}/one.log").read()).groups())
f = HalfspacePlaneWave(2000, 400, 200, "sv", 20)
v = lambda t: ricker_velocity(t, 0.1, 3.0, 0.4)
ok = True
for n, (x, y) in dict(s1=(-60, 0), s2=(0, 0), s3=(60, 0), mid=(0, -50)).items():
    d = np.genfromtxt(f"{w}/one/stations/{n}.csv", delimiter=",", names=True)
    ref = f.velocity(v, d["t"], x, y, xr, zr)
    err = np.sqrt(np.sum((d["v_x"] - ref[0]) ** 2 + (d["v_y"] - ref[1]) ** 2) / np.sum(ref**2))
    print(f"triangles, sv 20 deg: {n} ({x}, {y}): relative L2 error {err:.2e} (bound 2e-2)")
    ok &= err <= 2e-2
for n in ("left_out", "right_out", "base_out"):
    d = np.genfromtxt(f"{w}/one/stations/{n}.csv", delimiter=",", names=True)
    peak = max(np.abs(d["v_x"]).max(), np.abs(d["v_y"]).max()) / 0.1
    print(f"triangles: {n}: peak {peak:.2e} of the incident peak (bound 1e-2)")
    ok &= peak <= 1e-2
sys.exit(0 if ok else 1)
PY

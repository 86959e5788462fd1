# Domain Reduction Method in 3D (issue 12 item 1): a plane SH wave at 20 deg from the vertical,
# travelling at azimuth 30 deg, in a homogeneous half-space (rho 2000, vp 400, vs 200),
# 100 m x 100 m x 50 m of hexahedra (h = 2 m, 18 points per S wavelength at the Ricker's top
# frequency 5.5 Hz), absorbing sides and base, the DRM layer 2 cells in.
# Closed form: SH reflects from a free surface with coefficient +1 and no conversion (zero
# traction mu du/dz at z = 0), so the transverse velocity (-sin 30, cos 30, 0) is
#   v(t - p (xi - xi_r) + q (z - z_r)) + v(t - p (xi - xi_r) - q z - q z_r),
# p = sin 20 / vs, q = cos 20 / vs, xi = x cos 30 + y sin 30, the reference point at the
# upstream e node (-48, -48: Omega starts 2 cells in at -46, the layer is one cell thick;
# xi_r = -48 (cos 30 + sin 30)) and the deepest e nodes, z_r = 48 m.
# Bounds (issue): 2 % relative L2 inside Omega; outside the layer below 1 % of the incident peak.
set -eu
. tests/tools/lib.sh
$SW -mesh_dim 3 -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -mesh_box_faces 50,50,25 -mesh_box_lower -50,-50,-50 \
  -mesh_box_upper 50,50,0 -bc_left_type absorbing -bc_right_type absorbing -bc_front_type absorbing -bc_back_type absorbing -bc_bottom_type absorbing \
  -input_method drm -drm_wave sh -drm_incidence_angle 20 -drm_azimuth 30 -drm_stf ricker -drm_f0 2 -drm_t0 0.6 -drm_amplitude 0.1 -ts_max_time 1.2 \
  -output_fields 0 -progress_interval 100000 -station_coordinates 0,0,0,10,-20,-25,30,30,0,-40,40,-40,-49.5,0,-25,0,0,-49.5,49.5,49.5,-10 \
  -station_names s0,s1,s2,s3,out1,out2,out3 -output_dir "$WORK/sh"
$PY - "$WORK" <<'PY'
import sys
import numpy as np
w = sys.argv[1]
az, p, q = np.radians(30), np.sin(np.radians(20)) / 200, np.cos(np.radians(20)) / 200
xr, zr = -48 * (np.cos(az) + np.sin(az)), 48.0
v = lambda t: 0.1 * (1 - 2 * (np.pi * 2 * (t - 0.6)) ** 2) * np.exp(-((np.pi * 2 * (t - 0.6)) ** 2))
ok = True
for n, (x, y, zc) in dict(s0=(0, 0, 0), s1=(10, -20, -25), s2=(30, 30, 0), s3=(-40, 40, -40)).items():
    d = np.genfromtxt(f"{w}/sh/stations/{n}.csv", delimiter=",", names=True)
    t, xi, z = d["t"], x * np.cos(az) + y * np.sin(az), -zc
    ut = v(t - p * (xi - xr) + q * (z - zr)) + v(t - p * (xi - xr) - q * z - q * zr)
    ref = np.array([-np.sin(az) * ut, np.cos(az) * ut, 0 * ut])
    got = np.array([d["v_x"], d["v_y"], d["v_z"]])
    err = np.sqrt(np.sum((got - ref) ** 2) / np.sum(ref**2))
    print(f"SH 20 deg, azimuth 30: {n} ({x}, {y}, {zc}): relative L2 error {err:.2e} (bound 2e-2)")
    ok &= err <= 2e-2
for n in ("out1", "out2", "out3"):
    d = np.genfromtxt(f"{w}/sh/stations/{n}.csv", delimiter=",", names=True)
    peak = max(np.abs(d[c]).max() for c in ("v_x", "v_y", "v_z")) / 0.1
    print(f"SH: {n}: peak {peak:.2e} of the incident peak (bound 1e-2)")
    ok &= peak <= 1e-2
sys.exit(0 if ok else 1)
PY

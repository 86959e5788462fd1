# Free-field site response at element degree 4 (issue 14): free_field_transfer.sh (the same
# site, input, closed form (Kramer 1996, eq. 7.32) and bounds) on one element across (4 m) and
# 20 of 2 m up (4x and 2x fewer than its 1 m cells; 2 m so the soil/rock contact is an element
# edge): the free-field sides are then the whole model's lateral support. Measured: f1 to
# 2.1e-7, |H| at the peak to 4.2e-6, the band to 4.2e-6 of 1/alpha (degree 1 with 1 m cells:
# 1.0e-4, 3.4e-4, 4.9e-4; the O((k h)^2) dispersion is gone at p = 4).
set -eu
. tests/tools/lib.sh
$SW -regions rock,soil -region_soil_box 0,4,0,30 -mesh_box_faces 1,20 -element_degree 4 -mesh_box_lower 0,-10 -mesh_box_upper 4,30 \
  -material_soil_rho 1900 -material_soil_vp 500 -material_soil_vs 200 -material_rock_rho 2400 -material_rock_vp 1600 -material_rock_vs 800 \
  -bc_bottom_type absorbing -bc_left_type freefield -bc_right_type freefield -input_wave sv -input_boundary bottom \
  -input_stf ricker -input_f0 2 -input_t0 0.6 -input_amplitude 0.1 -ts_max_time 10 -output_fields 0 -progress_interval 100000 \
  -station_coordinates 2,30,0,30 -station_names surface,edge -output_dir "$WORK"
$PY - "$WORK" <<'PY'
import sys
import numpy as np
d = np.genfromtxt(f"{sys.argv[1]}/stations/surface.csv", delimiter=",", names=True)
t, v = d["t"], d["v_x"]
f0, t0, A = 2.0, 0.6, 0.1
tau = np.pi * f0 * (t - t0)
vin = A * (1 - 2 * tau**2) * np.exp(-tau**2)
late = np.abs(v[t > 9.5]).max() / np.abs(v).max()
f = np.arange(1.40, 1.95, 1e-4)
def dtft(x):
    out = np.empty(len(f), complex)
    for i in range(0, len(f), 200):
        out[i:i + 200] = np.exp(-2j * np.pi * np.outer(f[i:i + 200], t)) @ x
    return out
ratio = np.abs(dtft(v)) / np.abs(2 * dtft(vin))
k = int(np.argmax(ratio))
# parabola through the three grid points around the maximum
y0, y1, y2 = ratio[k - 1], ratio[k], ratio[k + 1]
dk = 0.5 * (y0 - y2) / (y0 - 2 * y1 + y2)
fp, hp = f[k] + dk * 1e-4, y1 - 0.25 * (y0 - y2) * dk
alpha = 1900 * 200 / (2400 * 800)
f1, h1 = 200 / (4 * 30), 1 / alpha
ef, eh = abs(fp / f1 - 1), abs(hp / h1 - 1)
kk = 2 * np.pi * f / 200
exact = 1 / np.abs(np.cos(kk * 30) + 1j * alpha * np.sin(kk * 30))
band = np.abs(f - f1) < 0.1
shape = np.max(np.abs(ratio[band] - exact[band])) / h1
print(f"transfer: peak at {fp:.5f} Hz (vs/4H = {f1:.5f} Hz), error {ef:.2e} (bound 5e-3); |H| at the peak {hp:.4f} (1/alpha = {h1:.4f}), error {eh:.2e} (bound 1e-2)")
print(f"transfer: within f1 +- 0.1 Hz the computed ratio differs from |H(f)| by at most {shape:.2e} of 1/alpha (bound 5e-3); motion in the last 0.5 s {late:.1e} of the peak (bound 1e-4)")
sys.exit(0 if ef <= 5e-3 and eh <= 1e-2 and shape <= 5e-3 and late <= 1e-4 else 1)
PY

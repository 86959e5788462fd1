# Free-field lateral boundaries (issue 5 item 2): site response of a layer on elastic bedrock
# in a model only 4 m wide. 30 m of soil (rho 1900, vs 200, vp 500) on rock (rho 2400, vs 800,
# vp 1600; 10 m of it above the absorbing base), no damping, SV Ricker (f0 = 2 Hz) through the
# base, free-field sides, 1 m cells (120 points per S wavelength at 1.67 Hz).
# Expected (closed form, Kramer 1996, eq. 7.32): surface / (2 x incident) =
#   |H(f)| = 1 / |cos(k H) + i alpha sin(k H)|,  k = 2 pi f / vs_soil,
#   alpha = rho_s vs_s / (rho_r vs_r) = 0.19792;
# its first peak is at f1 = vs/4H = 1.66667 Hz with |H| = 1/alpha = 5.0526.
# Bounds: f1 within 0.5 % (issue); the peak amplitude within 1 %: the discrete errors are
# O((k h)^2) with k h = 0.052 at f1 (lumped-mass dispersion (k h)^2/24 = 1.1e-4, the same
# order for the discrete impedance jump and dashpot), and the peak of |H| is flat to second
# order in a frequency error, so 1 % leaves a margin of more than 10.
# The record: the layer loses (1 - R^2) of its energy per round trip 2H/vs = 0.3 s through the
# base (R = (1 - alpha)/(1 + alpha) = 0.67), so after 10 s the motion is below 1e-5 of its
# peak; the Fourier transform of the complete transient is then evaluated directly on a
# 1e-4 Hz grid (exact zero padding: the resolution is not limited by the record length).
# SEM_DEGREE / FREE_FIELD_FACES: the same site at another element degree and mesh
# (tests/cases/sem_free_field_transfer.sh).
set -eu
. tests/tools/lib.sh
$SW -regions rock,soil -region_soil_box 0,4,0,30 -mesh_box_faces "${FREE_FIELD_FACES:-4,40}" -element_degree "$DEGREE" -mesh_box_lower 0,-10 -mesh_box_upper 4,30 \
  -material_soil_rho 1900 -material_soil_vp 500 -material_soil_vs 200 -material_rock_rho 2400 -material_rock_vp 1600 -material_rock_vs 800 \
  -bc_bottom_type absorbing -bc_left_type freefield -bc_right_type freefield -input_wave sv -input_boundary bottom \
  -input_stf ricker -input_f0 2 -input_t0 0.6 -input_amplitude 0.1 -ts_max_time 10 -output_fields 0 -progress_interval 100000 \
  -station_coordinates 2,30,0,30 -station_names surface,edge -output_dir "$WORK"
$PY - "$WORK" <<'PY'
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
from spectra import dtft
d = np.genfromtxt(f"{sys.argv[1]}/stations/surface.csv", delimiter=",", names=True)
t, v = d["t"], d["v_x"]
f0, t0, A = 2.0, 0.6, 0.1
tau = np.pi * f0 * (t - t0)
vin = A * (1 - 2 * tau**2) * np.exp(-tau**2)
late = np.abs(v[t > 9.5]).max() / np.abs(v).max()
f = np.arange(1.40, 1.95, 1e-4)
ratio = np.abs(dtft(f, t, v)) / np.abs(2 * dtft(f, t, vin))
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

# Constant-Q damping (issue 8): site response of a damped layer on elastic bedrock, 1D column.
# 30 m of soil (rho 1900, vs 200, vp 500, damping ratio xi = 0.05: Q0 = 10, default band
# 0.5-20 Hz and 3 mechanisms, speeds given at f_r = f1 = vs/4H = 1.6667 Hz) on rock (rho 2400,
# vs 800, vp 1600, elastic; 10 m of it above the absorbing base), SV Ricker f0 = 4 Hz through
# the base, 0.5 m cells (40 points per wavelength at 10 Hz), vertical motion held (exact 1D).
# Closed form (Kramer 1996, eq. 7.32, with complex wavenumber and impedance): surface / (2 x incident)
#   H(f) = 1 / |cos(k* H) + i alpha* sin(k* H)|,  k* = w / v*,  alpha* = rho_s v* / (rho_r vs_r),
# 1. with v* = sqrt(G*(w)/rho), G* the fitted body's exact complex modulus (speed vs at f_r):
#    the first three resonance peaks within 0.5 % in frequency and 3 % in amplitude (issue 8).
#    Discrete errors are O((k h)^2) = 7e-4 at 8.7 Hz; the memory update is exact for u linear
#    over a step.
# 2. with v* = vs sqrt(1 + 2 i xi), the frequency-independent complex modulus G(1 + 2 i xi),
#    which is not causal: a causal constant-Q body is dispersive (Kramers-Kronig), its phase
#    speed c(f) = vs (1 + ln(f/f_r)/(pi Q)) to first order, while G(1 + 2 i xi) has phase speed
#    vs / Re[(1 + 2 i xi)^{-1/2}] = vs (1 + 1.5 xi^2). So its resonances are expected shifted by
#    ln(f_n/f_r)/(pi Q) - 1.5 xi^2 (-0.4 %, +3.1 %, +4.7 % here): the measured shift must
#    match that within the issue's 0.5 %, and the amplitudes within its 3 % (the fitted Q is
#    within 3.2 % of Q0 over the band, and the peak amplitude ~ 1/(alpha + (2n-1) pi xi/2)).
# The record: after 8 s the motion is below 1e-5 of its peak; the Fourier transforms of the
# complete transients are evaluated directly on a 1e-3 Hz grid.
set -eu
. tests/tools/lib.sh
$SW -regions rock,soil -region_soil_box 0,1,0,30 -mesh_box_faces 1,80 -mesh_box_lower 0,-10 -mesh_box_upper 1,30 \
  -material_soil_rho 1900 -material_soil_vp 500 -material_soil_vs 200 -material_soil_damping_ratio 0.05 -attenuation_reference_frequency 1.6666666667 \
  -material_rock_rho 2400 -material_rock_vp 1600 -material_rock_vs 800 -bc_bottom_type absorbing -input_wave sv -input_boundary bottom -constrain_components y \
  -input_stf ricker -input_f0 4 -input_t0 0.4 -input_amplitude 0.1 -ts_max_time 8 -output_fields 0 -progress_interval 100000 \
  -station_coordinates 0.5,30 -station_names surface -output_dir "$WORK" > "$WORK/log"
$PY - "$WORK" <<'PY'
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
from constant_q import model_from_report, complex_speed
from spectra import dtft
out = sys.argv[1]
fl, Y, fr = model_from_report(open(f"{out}/log").read(), "soil")
d = np.genfromtxt(f"{out}/stations/surface.csv", delimiter=",", names=True)
t, v = d["t"], d["v_x"]
f0, t0, A, H, xi, vs = 4.0, 0.4, 0.1, 30.0, 0.05, 200.0
tau = np.pi * f0 * (t - t0)
vin = A * (1 - 2 * tau**2) * np.exp(-tau**2)
late = np.abs(v[t > 7.5]).max() / np.abs(v).max()
f = np.arange(1.0, 10.0, 1e-3)
ratio = np.abs(dtft(f, t, v)) / np.abs(2 * dtft(f, t, vin))
def closed_form(vstar):
    k = 2 * np.pi * f / vstar
    alpha = 1900 * vstar / (2400 * 800)
    return 1 / np.abs(np.cos(k * H) + 1j * alpha * np.sin(k * H))
def peaks(y):
    """Frequency and height of the maximum near each of the first three resonances (parabola
    through the three grid points around it)."""
    res = []
    for n in (1, 2, 3):
        fn = (2 * n - 1) * vs / (4 * H)
        idx = np.where(np.abs(f - fn) < 0.15 * fn)[0]
        k = idx[np.argmax(y[idx])]
        y0, y1, y2 = y[k - 1], y[k], y[k + 1]
        dk = 0.5 * (y0 - y2) / (y0 - 2 * y1 + y2)
        res.append((f[k] + dk * 1e-3, y1 - 0.25 * (y0 - y2) * dk))
    return np.array(res)
sim = peaks(ratio)
fitted = peaks(closed_form(complex_speed(f, fl, Y, fr, vs)))
kramer = peaks(closed_form(vs * np.sqrt(1 + 2j * xi)))
ok = late <= 1e-5
for n in range(3):
    ef, ea = sim[n, 0] / fitted[n, 0] - 1, sim[n, 1] / fitted[n, 1] - 1
    shift = np.log(kramer[n, 0] / fr) / (np.pi * 0.5 / xi) - 1.5 * xi**2
    kf, ka = sim[n, 0] / kramer[n, 0] - 1, sim[n, 1] / kramer[n, 1] - 1
    print(f"resonance {n + 1}: {sim[n, 0]:.4f} Hz, |H| {sim[n, 1]:.4f}; fitted G*(w): {fitted[n, 0]:.4f} Hz, {fitted[n, 1]:.4f} (errors {ef:+.2e}, {ea:+.2e}; bounds 5e-3, 3e-2); "
          f"G(1+2i xi): {kramer[n, 0]:.4f} Hz, {kramer[n, 1]:.4f} (shift {kf:+.3e}, dispersion predicts {shift:+.3e}, bound 5e-3 apart; amplitude {ka:+.2e}, bound 3e-2)")
    ok = ok and abs(ef) <= 5e-3 and abs(ea) <= 3e-2 and abs(kf - shift) <= 5e-3 and abs(ka) <= 3e-2
print(f"transfer: motion in the last 0.5 s {late:.1e} of the peak (bound 1e-5)")
sys.exit(0 if ok else 1)
PY

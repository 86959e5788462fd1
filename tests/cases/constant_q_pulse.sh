# Constant-Q damping (issue 8): Ricker pulses travel about 10 wavelengths up 1D SV columns
# (rho 2000, vs 200, damping ratio 0.02: Q0 = 25, 3 mechanisms). Stations: a, 20 m above the
# absorbing base, and b at the free surface, L higher. The free surface doubles the incident
# wave exactly (also in the lumped-mass chain), so the spectral ratio is
#   |B(f)| / (2 |A(f)|) = exp(Im(k) L),   k = w sqrt(rho / M(w))   (exp(i(w t - k x))).
# Measured: Im k from the ratio, Re k from the fitted model's phase speed, and
#   Q = Re M / Im M = (Re k^2 - Im k^2) / (2 Re k Im k)   (M = rho w^2 / k^2).
# Bounds: Q within 5 % of Q0 over the fitted band (issue 8), and within 1 % of the fitted body's
# exact Q(f): the discrete errors are O((k h)^2) ((k h)^2/24 <= 1e-3 in every run below) and the
# memory update is exact for u linear over a step.
# Runs (windows: a is cut before the surface reflection returns, b ends before the down-going
# wave's leftovers from the base could return, and late enough for the dispersed pulse's slow
# low-frequency tail: b cut at 10 s instead of 16 s in run "low" put Q off by 11 %):
#  1. band 1-10 Hz: f0 = 4 Hz, L = 420 m (10.5 wavelengths at f0), 0.5 m cells; Q over 1-10 Hz.
#  2. the default band 0.5-20 Hz in two pulses: f0 = 1.5 Hz, L = 1380 m (10.4 wavelengths),
#     1 m cells, Q over 0.5-4 Hz; f0 = 8 Hz, L = 420 m (16.8 wavelengths), 0.25 m cells, Q over
#     4-20 Hz.
set -eu
. tests/tools/lib.sh
column() { # name band f0 t0 height cells t_end
  local band=""
  [ "$2" != default ] && band="-attenuation_band $2"
  $SW -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -material_soil_damping_ratio 0.02 $band \
    -bc_bottom_type absorbing -input_boundary bottom -input_wave sv -input_stf ricker -input_f0 "$3" -input_t0 "$4" -input_amplitude 0.1 \
    -ts_max_time "$7" -output_fields 0 -progress_interval 100 -mesh_box_faces 1,"$6" -mesh_box_upper 1,"$5" -constrain_components y \
    -station_coordinates 0.5,20,0.5,"$5" -station_names a,b -output_dir "$WORK/$1" > "$WORK/$1.log"
}
column narrow 1,10 4 0.3 440 880 4
column low default 1.5 1.0 1400 1400 16
column high default 8 0.15 440 1760 5
$PY - "$WORK" <<'PY'
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
from constant_q import model_from_report, modulus_ratio, complex_speed
work = sys.argv[1]
def measure(name, L, a_end, f):
    out = f"{work}/{name}"
    fl, Y, fr = model_from_report(open(f"{out}.log").read(), "soil")
    def station(s):
        d = np.genfromtxt(f"{out}/stations/{s}.csv", delimiter=",", names=True)
        return d["t"], d["v_x"]
    ta, va = station("a")
    tb, vb = station("b")
    va = np.where(ta < a_end, va, 0.0)
    dtft = lambda t, x: np.exp(-2j * np.pi * np.outer(f, t)) @ x
    ratio = np.abs(dtft(tb, vb)) / (2 * np.abs(dtft(ta, va)))
    k_im = -np.log(ratio) / L
    k_re = (2 * np.pi * f / complex_speed(f, fl, Y, fr, 200.0)).real
    q = (k_re**2 - k_im**2) / (2 * k_re * k_im)
    m = modulus_ratio(f, fl, Y)
    return q, m.real / m.imag, ratio
q0, ok = 25.0, True
for name, L, a_end, f in (("narrow", 420.0, 2.0, np.linspace(1, 10, 91)), ("low", 1380.0, 4.0, np.linspace(0.5, 4, 71)),
                          ("high", 420.0, 1.0, np.linspace(4, 20, 81))):
    q, q_fit, ratio = measure(name, L, a_end, f)
    e_fit, e_target = np.max(np.abs(q / q_fit - 1)), np.max(np.abs(q / q0 - 1))
    print(f"constant-Q pulse {name}: measured Q {q.min():.3f} to {q.max():.3f} over {f[0]:g}-{f[-1]:g} Hz (target {q0}); largest difference "
          f"{e_target:.2e} from the target (bound 5e-2), {e_fit:.2e} from the fitted body's Q(f) (bound 1e-2); amplitude ratio {ratio[0]:.3f} to {ratio[-1]:.2e}")
    ok = ok and e_target <= 0.05 and e_fit <= 0.01
sys.exit(0 if ok else 1)
PY

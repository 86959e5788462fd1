# The default scene (issue 8): a block on a soft layer over bedrock, free-field sides,
# geostatic stage, then the El Centro 1940 N-S record as an outcrop motion scaled to 0.3 g,
# on 2 ranks. It must run to the end (15 s at the step of the report: over 100000 energy
# rows), the energy budget must close to 1 % (issue bound; the discrete identity makes it
# round-off), the report must state the record's PGA, scale factor and interpretation and
# warn about no side (free-field sides hold back nothing), the output must parse, and the
# block must do what the scene's header promises: slide (slip path > 5 cm, net offset
# > 1 cm) and lift its heel (peak opening > 2 cm; rocking angle > 1e-3 rad).
# The free-field sides must let the site move as a layered site: the free-field station's
# peak velocity within 5 % of the 1D closed form for a 30 m layer (vs 200, rho 1900) on
# elastic rock (vs 800, rho 2400), undamped: surface = outcrop / (cos kH + i alpha sin kH),
# alpha = 1900*200/(2400*800), outcrop = the scaled, baseline-corrected record (measured:
# 1 %; the 5 % leaves room for the block's scattered field 37 m away and the mesh, whose
# free-field PSA moves by 1-2 % from h to h/2). Rollers give 0.13 m/s instead of 0.81.
# (With soil damping in the scene the closed form needs the damped wavenumber.)
set -eu
. tests/tools/lib.sh
$MPIEXEC -n 2 $SW -options_file config/scenes/default.yaml -output_dir "$WORK" | grep -vE "^step" | tee "$WORK/report.txt"
grep -q "record config/records/el_centro_1940_ns.csv (CSV in g, 2688 samples.*PGA 0.3 g (scale factor 0.8612 on the record's 0.3483 g).*outcrop motion" "$WORK/report.txt"
if grep -q "warning: boundary" "$WORK/report.txt"; then echo "FAIL: a side holds back the incident wave"; exit 1; fi
$CHECK energy "$WORK/energy.csv" --max-error 1e-2 --min-rows 100000
$PY scripts/check_output.py "$WORK"
$PY scripts/check_output.py "$WORK" --grid interface_base
$PY scripts/scene_metrics.py "$WORK" --json "$WORK/metrics.json"
$PY - "$WORK/metrics.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
checks = [("accumulated_slip", m["accumulated_slip"] > 0.05), ("|net_slip|", abs(m["net_slip"]) > 0.01),
          ("peak_uplift", m["peak_uplift"] > 0.02), ("peak_rocking_angle", m["peak_rocking_angle"] > 1e-3)]
for name, ok in checks:
    print(("ok " if ok else "FAIL ") + name)
sys.exit(0 if all(ok for _, ok in checks) else 1)
PY
$PY - "$WORK/stations/free_field.csv" <<'PY'
import sys
import numpy as np
g, pga, dt = 9.80665, 0.3, 0.02
d = np.loadtxt("config/records/el_centro_1940_ns.csv", delimiter=",", skiprows=1)
t, a = d[:, 0], d[:, 1] * g
def trapezoid(y):
    return np.concatenate([[0.0], np.cumsum(0.5 * (y[1:] + y[:-1]) * dt)])
ramp = t - t[0]
def final(y):
    v = trapezoid(y)
    return v[-1], trapezoid(v)[-1]
(v0, d0), (v1, d1), (v, dd) = final(np.ones_like(t)), final(ramp), final(a)
det = v0 * d1 - v1 * d0
a = a - (v * d1 - v1 * dd) / det - (v0 * dd - v * d0) / det * ramp
outcrop = trapezoid(a * pga * g / np.max(np.abs(a)))
n = 2 ** 16
w = 2 * np.pi * np.fft.rfftfreq(n, dt)
H, vs, alpha = 30.0, 200.0, 1900 * 200 / (2400 * 800)
surface = np.fft.irfft(np.fft.rfft(outcrop, n) / (np.cos(w * H / vs) + 1j * alpha * np.sin(w * H / vs)), n)[: int(round(15 / dt)) + 1]
sim = np.genfromtxt(sys.argv[1], delimiter=",", names=True)
expected, got = np.max(np.abs(surface)), np.max(np.abs(np.interp(np.arange(len(surface)) * dt, sim["t"], sim["v_x"])))
err = abs(got / expected - 1)
print(f"{'ok' if err <= 0.05 else 'FAIL'} free-field surface PGV {got:.4f} m/s vs 1D layer on rock {expected:.4f} m/s ({err:.1%}, allowed 5 %)")
sys.exit(0 if err <= 0.05 else 1)
PY

# scripts/response_spectrum.py (the exact piecewise-linear oscillator step of Nigam &
# Jennings 1969) against closed forms for u'' + 2 zeta w u' + w^2 u = -a(t) from rest:
#  1. a constant step a0 (exactly piecewise linear): u(t) = -(a0/w^2)[1 - e^(-zeta w t)
#     (cos wd t + zeta/sqrt(1-zeta^2) sin wd t)] at every sample to 1e-10 (round-off), and
#     PSA = a0 (1 + exp(-pi zeta/sqrt(1-zeta^2))) = 1.8545 a0 for zeta = 5 % (the first
#     peak, at t = pi/wd, is a sample here) to 1e-10;
#  2. harmonic resonance a = A0 sin(w t), 60 cycles (transient e^(-2 pi 0.05 60) = 6e-9):
#     the steady-state amplitude |u| = A0/(2 zeta w^2), PSA = A0/(2 zeta) = 10 A0; sampled
#     at T/200, the linear interpolation and the sampled peak lose (w dt)^2/8 ~ 1e-4: 0.1 %;
#  3. short periods: for a Ricker acceleration (f0 = 2 Hz) the oscillator of T = 0.01 s
#     follows the ground, u = -a/w^2 (1 + O(2 zeta f/fn, (f/fn)^2) ~ 0.3 %): PSA = PGA within 1 %;
#  4. an undamped oscillator after a rectangular pulse a0 of length td = T/4 < T/2 swings
#     with the residual amplitude 2 (a0/w^2) sin(pi td/T) (shock spectrum of a rectangular
#     pulse; e.g. Chopra, Dynamics of Structures, sec. 4.7): PSA = sqrt(2) a0; the pulse
#     ends over one sample (dt = T/2000), an error O(dt/T): 0.2 %.
# The all-periods routine must agree with the one-period response to round-off.
set -eu
. tests/tools/lib.sh
$PY - <<'PY'
import sys
import numpy as np
sys.path.insert(0, "scripts")
from response_spectrum import oscillator_response, pseudo_acceleration_spectrum, default_periods

fail = False
def check(name, value, expected, rel):
    global fail
    err = abs(value / expected - 1)
    ok = err <= rel
    fail |= not ok
    print(f"{'ok' if ok else 'FAIL'} {name}: {value:.8g} vs {expected:.8g} (relative error {err:.2e}, allowed {rel:g})")

zeta, T = 0.05, 0.5
w = 2 * np.pi / T
wd = w * np.sqrt(1 - zeta ** 2)
# 1. step: peak at pi/wd; dt chosen so that pi/wd is sample 250
dt = np.pi / wd / 250
t = dt * np.arange(2000)
a0 = 3.0
u = oscillator_response(np.full(len(t), a0), dt, T, zeta)
exact = -(a0 / w ** 2) * (1 - np.exp(-zeta * w * t) * (np.cos(wd * t) + zeta / np.sqrt(1 - zeta ** 2) * np.sin(wd * t)))
err = np.max(np.abs(u - exact)) / np.max(np.abs(exact))
print(f"{'ok' if err < 1e-10 else 'FAIL'} step response at every sample: {err:.2e} (allowed 1e-10)")
fail |= err >= 1e-10
psa = pseudo_acceleration_spectrum(np.full(len(t), a0), dt, [T], zeta)[0]
check("step PSA = a0 (1 + exp(-pi zeta/sqrt(1-zeta^2)))", psa, a0 * (1 + np.exp(-np.pi * zeta / np.sqrt(1 - zeta ** 2))), 1e-10)

# 2. resonance
A0, dt = 0.7, T / 200
t = dt * np.arange(60 * 200 + 1)
psa = pseudo_acceleration_spectrum(A0 * np.sin(w * t), dt, [T], zeta)[0]
check("resonance PSA = A0/(2 zeta)", psa, A0 / (2 * zeta), 1e-3)

# 3. short period: Ricker acceleration, f0 = 2 Hz
dt, f0, t0 = 0.0005, 2.0, 1.0
t = dt * np.arange(6000)
x = (np.pi * f0 * (t - t0)) ** 2
acc = (1 - 2 * x) * np.exp(-x)
psa = pseudo_acceleration_spectrum(acc, dt, [0.01], zeta)[0]
check("PSA(T = 0.01 s) = PGA", psa, np.max(np.abs(acc)), 1e-2)

# 4. rectangular pulse, undamped
T4, n = 1.0, 2000
dt = T4 / n
t = dt * np.arange(4 * n)
acc = np.where(t < T4 / 4 - dt / 2, a0, 0.0)
psa = pseudo_acceleration_spectrum(acc, dt, [T4], 0.0)[0]
check("rectangular pulse td = T/4: PSA = 2 a0 sin(pi/4)", psa, 2 * a0 * np.sin(np.pi / 4), 2e-3)

# all periods at once = one at a time
rng = np.random.default_rng(3)
acc = rng.normal(size=500)
periods = default_periods(12)
together = pseudo_acceleration_spectrum(acc, 0.01, periods)
alone = np.array([(2 * np.pi / p) ** 2 * np.max(np.abs(oscillator_response(acc, 0.01, p))) for p in periods])
err = np.max(np.abs(together / alone - 1))
print(f"{'ok' if err < 1e-12 else 'FAIL'} all periods at once vs one by one: {err:.1e} (allowed 1e-12)")
fail |= err >= 1e-12
sys.exit(1 if fail else 0)
PY

# scripts/foundation_impedance.py on a response with a closed-form impedance: a single
# degree of freedom m x'' + c x' + k x = P(t) (m = 1, f_n = 2 Hz, 20 % damping), P a Ricker
# (f0 2 Hz, t0 0.6 s), integrated here in time by scipy's solve_ivp (rtol 1e-10), written as
# slipwave stations. The script's K(w) = P(w)/X(w) must be k - m w^2 + i w c (the SDOF's
# dynamic stiffness) within 1e-4 of |K| at every kept frequency (the time integration's tolerance is 1e-10;
# the load is rebuilt on the same samples), for the vertical mode (u_y of
# one station) and for rocking (theta = (u_y(R) - u_y(L)) / (x_R - x_L), stations at x = -/+1
# moving -/+ theta). It must also write the plot.
set -eu
. tests/tools/lib.sh
$PY - "$WORK" <<'PY'
import os, sys
import numpy as np
from scipy.integrate import solve_ivp
work = sys.argv[1]
m, k = 1.0, (2 * np.pi * 2) ** 2
c = 2 * 0.2 * np.sqrt(k * m)
t = np.arange(0, 20, 1e-3)
P = lambda s: 1e3 * (1 - 2 * (np.pi * 2 * (s - 0.6)) ** 2) * np.exp(-(np.pi * 2 * (s - 0.6)) ** 2)
sol = solve_ivp(lambda s, y: [y[1], (P(s) - c * y[1] - k * y[0]) / m], (0, t[-1]), [0, 0], t_eval=t, rtol=1e-10, atol=1e-14, max_step=1e-3)
x = sol.y[0]
os.makedirs(work + "/run/stations", exist_ok=True)
z = np.zeros_like(t)
for name, uy in (("C", x), ("L", -x), ("R", x)):
    np.savetxt(f"{work}/run/stations/{name}.csv", np.column_stack([t, z, uy, z, z, z, z]), delimiter=",", header="t,u_x,u_y,v_x,v_y,a_x,a_y", comments="")
np.save(work + "/sdof.npy", [m, k, c])
PY
$PY scripts/foundation_impedance.py "$WORK/run" --mode vertical --station C --amplitude 1e3 --stf ricker --f0 2 --t0 0.6 --out "$WORK/vertical"
$PY scripts/foundation_impedance.py "$WORK/run" --mode rocking --stations L,R --x-left -1 --x-right 1 --amplitude 1e3 --stf ricker --f0 2 --t0 0.6 --out "$WORK/rocking"
$PY - "$WORK" <<'PY'
import sys
import numpy as np
work = sys.argv[1]
m, k, c = np.load(work + "/sdof.npy")
ok = True
for mode in ("vertical", "rocking"):
    d = np.genfromtxt(f"{work}/{mode}/impedance.csv", delimiter=",", names=True)
    w = 2 * np.pi * d["f"]
    exact = k - m * w * w + 1j * w * c
    err = np.max(np.abs(d["K1"] + 1j * d["wC"] - exact) / np.abs(exact))
    print(f"{mode}: {len(w)} frequencies {d['f'][0]:.2f}-{d['f'][-1]:.2f} Hz, max |K - (k - m w^2 + i w c)| / |K| = {err:.2e} (bound 1e-4)")
    ok &= err <= 1e-4 and len(w) > 10
sys.exit(0 if ok else 1)
PY
test -s "$WORK/vertical/impedance.png" && test -s "$WORK/rocking/impedance.png"

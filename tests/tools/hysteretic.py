"""Checks of hysteretic (Masing) soil runs against closed forms written here from the physics
(docs/hysteretic-soil.md), not from the C++ kernel.

loop: one cell in strain-controlled cyclic simple shear (all nodes prescribed: bottom fixed,
top moving with the harmonic velocity v = A sin(2 pi f t), vertical motion held), so the
strain is uniform, gamma(t) = A (1 - cos(2 pi f t)) / (2 pi f H): a first loading to
gamma_m = A / (pi f H) at T/2, an unloading to 0 at T, a reloading to gamma_m at 3T/2. The
shear stress comes from the program's energy ledger: the supports' work per step is
h v_n R_n (problem/energy_ledger.cpp), so tau_n = (dW_n / (h v_n) - m_top a_n) / area, with
m_top a_n the inertia of the top nodes (half the cell's mass, lumped). Masing's rules on the
hyperbola F(g) = Gmax g / (1 + g / g_r) give the loop:
  loading    tau = F(gamma)
  unloading  tau = F(gamma_m) - 2 F((gamma_m - gamma) / 2)
  reloading  tau = tau_0 + 2 F(gamma / 2),  tau_0 = F(gamma_m) - 2 F(gamma_m / 2)
and the energies: work to gamma_m = V int_0^gamma_m F = V Gmax g_r^2 (X - ln(1 + X)),
X = gamma_m / g_r; the closed loop's area, that of a symmetric loop of amplitude
a = gamma_m / 2 (Masing loops depend on the strain range only), 8 int_0^a F - 4 a F(a).
"""
import argparse
import math
import sys

import numpy as np

sys.path.insert(0, "python")
from slipwave.run_folder import read_csv  # noqa: E402


def hyperbola(gmax, g_r):
    return lambda g: gmax * g / (1 + np.abs(g) / g_r)


def loop(args):
    d = read_csv(args.csv)
    gmax, g_r, A, f, H = args.gmax, args.reference_strain, args.amplitude, args.f0, args.height
    V, area = args.volume, args.area
    F = hyperbola(gmax, g_r)
    t = d["time"]
    h = np.diff(t)
    # Supports' work per step, less the inertia of the top nodes (the kinetic column is the
    # whole cell's: all of it moves with the top's velocity times y/H).
    dW = np.diff(d["external_work"])
    tn = t[1:]
    v = A * np.sin(2 * np.pi * f * tn)
    acc = 2 * np.pi * f * A * np.cos(2 * np.pi * f * tn)
    m_top = args.rho * V / 2
    gamma = A * (1 - np.cos(2 * np.pi * f * tn)) / (2 * np.pi * f * H)
    gm = A / (np.pi * f * H)
    T = 1 / f
    tau_m = F(gm)
    tau0 = tau_m - 2 * F(gm / 2)
    expect = np.where(tn <= T / 2, F(gamma), np.where(tn <= T, tau_m - 2 * F((gm - gamma) / 2), tau0 + 2 * F(gamma / 2)))
    # Near a reversal v_n -> 0 and the quotient carries no information.
    live = np.abs(v) > 0.05 * A
    tau = (dW / (h * v) - m_top * acc) / area
    err = np.max(np.abs(tau[live] - expect[live])) / tau_m
    # N surfaces: the model's backbone F_N is within e = (ln r)^2 / 16 of F (r the knot ratio,
    # knots from ~1e-6 to 0.1; docs/hysteretic-soil.md, table "Error of N surfaces"), its Masing
    # branches within 2 e tau_m. The time step's error (second order) comes on top of it: the
    # bound is the N-surface one, which it must leave room for.
    r = (0.1 / 1e-6) ** (1 / (args.surfaces - 1))
    e = math.log(r) ** 2 / 16
    print(f"loop: {live.sum()} steps, largest |tau - Masing closed form| {err:.3e} of tau_m = {tau_m:.6g} Pa (bound 2 e = {2 * e:.2e}, N-surface)")
    ok = err <= 2 * e
    # Energies at the reversals (v = 0): T/2 (gamma_m), 3T/2 (gamma_m again).
    k1 = int(np.argmin(np.abs(t - T / 2)))
    k3 = int(np.argmin(np.abs(t - 1.5 * T)))
    X = gm / g_r
    work = V * gmax * g_r ** 2 * (X - math.log1p(X))
    a = gm / 2
    x = a / g_r
    loop_area = V * (8 * gmax * g_r ** 2 * (x - math.log1p(x)) - 4 * a * F(a))
    got_work = d["strain"][k1] + d["hysteretic_dissipated"][k1]
    got_area = d["hysteretic_dissipated"][k3] - d["hysteretic_dissipated"][k1]
    e_work = abs(got_work - work) / work
    e_area = abs(got_area - loop_area) / loop_area
    # |F - F_N| <= e F: the work within e, the area 8 int F - 4 a F(a) within e (8 int F + 4 a F(a)).
    bound_area = e * (8 * gmax * g_r ** 2 * (x - math.log1p(x)) + 4 * a * F(a)) * V / loop_area
    print(f"loop: stored + dissipated at gamma_m {got_work:.6g} J, V int F {work:.6g} J: {e_work:.2e} (bound e = {e:.2e}); "
          f"loop area {got_area:.6g} J, closed form {loop_area:.6g} J: {e_area:.2e} (bound {bound_area:.2e})")
    closed = abs(d["strain"][k3] - d["strain"][k1]) / d["strain"][k1]
    print(f"loop: stored energy back at gamma_m differs by {closed:.2e} (the loop closes; bound 1e-9)")
    ok = ok and e_work <= e and e_area <= bound_area and closed <= 1e-9
    return 0 if ok else 1


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="cmd", required=True)
    q = sub.add_parser("loop")
    q.add_argument("csv")
    for name in ("gmax", "reference-strain", "amplitude", "f0", "height", "volume", "area", "rho"):
        q.add_argument("--" + name, type=float, required=True)
    q.add_argument("--surfaces", type=int, required=True)
    a = p.parse_args()
    return {"loop": loop}[a.cmd](a)


if __name__ == "__main__":
    sys.exit(main())

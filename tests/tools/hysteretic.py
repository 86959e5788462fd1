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


def masing_loop(args):
    """The strain-controlled loop of `loop` in closed form: (gamma(t), Masing tau(t), largest
    gamma up to t, gamma_m, tau_m, e the N-surface error) for scalar or array t."""
    gmax, g_r, A, f, H = args.gmax, args.reference_strain, args.amplitude, args.f0, args.height
    F = hyperbola(gmax, g_r)
    gm, T = A / (np.pi * f * H), 1 / f
    tau_m, tau0 = F(gm), F(gm) - 2 * F(gm / 2)
    e = math.log((0.1 / 1e-6) ** (1 / (args.surfaces - 1))) ** 2 / 16
    gamma = lambda t: A * (1 - np.cos(2 * np.pi * f * t)) / (2 * np.pi * f * H)  # noqa: E731
    tau = lambda t: np.where(t <= T / 2, F(gamma(t)), np.where(t <= T, tau_m - 2 * F((gm - gamma(t)) / 2), tau0 + 2 * F(gamma(t) / 2)))  # noqa: E731
    largest = lambda t: np.where(t <= T / 2, gamma(t), gm)  # noqa: E731
    return gamma, tau, largest, gm, tau_m, e


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


def frames(args):
    """The volume output of the same loop run: the cell's shear stress (xy) at each frame
    against the Masing closed forms of `loop` at the frame's strain, the largest shear strain
    reached against max gamma(t) up to the frame, and the secant G/Gmax there against
    1 / (1 + gamma / g_r), the hyperbola's."""
    sys.path.insert(0, "tests/tools")
    from frames import Frames
    f = Frames(args.dir)
    _, tau, largest, gm, tau_m, e = masing_loop(args)
    g_r = args.reference_strain
    worst_tau = worst_g = worst_ratio = 0.0
    for k, t in enumerate(f.times):
        g_max = largest(t)
        worst_tau = max(worst_tau, abs(f.field("stress", k)[0][1] - tau(t)) / tau_m)
        worst_g = max(worst_g, abs(f.field("max_shear_strain", k)[0][0] - g_max) / gm)
        ratio = 1 / (1 + g_max / g_r)
        worst_ratio = max(worst_ratio, abs(f.field("secant_modulus_ratio", k)[0][0] - ratio))
    # The displacement is central difference's integral of the prescribed acceleration: the
    # strain within 1e-5 of gm of the closed form at 1000 steps per cycle (second order).
    print(f"frames: {len(f.times)} frames; stress xy within {worst_tau:.2e} of tau_m of the Masing closed forms (bound 2 e = {2 * e:.2e}); "
          f"max_shear_strain within {worst_g:.2e} of gamma_m (bound 1e-5); secant G/Gmax within {worst_ratio:.2e} (bound e = {e:.2e})")
    return 0 if worst_tau <= 2 * e and worst_g <= 1e-5 and worst_ratio <= e + 1e-5 and len(f.times) >= 7 else 1


def station(args):
    """A station in the same loop run's cell (-station_stress): every step, its engineering
    shear strain 2 e_xy against gamma(t) (bound 1e-5 of gamma_m, the time step's, as in
    `frames`) and its s_xy against the Masing closed forms (bound 2 e, as `loop`); the other
    strains zero (the top moves in x only: 1e-12 of gamma_m); and at each volume frame its
    stress equal to the frame's cell stress (the same path, io/volume_output.cpp: 1e-12)."""
    sys.path.insert(0, "tests/tools")
    from frames import Frames
    from slipwave import RunFolder
    d = RunFolder(args.dir).station(args.name)
    gamma, tau, _, gm, tau_m, e = masing_loop(args)
    t = d["t"]
    err_g = np.max(np.abs(2 * d["e_xy"] - gamma(t))) / gm
    err_tau = np.max(np.abs(d["s_xy"] - tau(t))) / tau_m
    others = max(np.max(np.abs(d[c])) for c in d.names if c.startswith("e_") and c != "e_xy") / gm
    f = Frames(args.dir)
    components = [c for c in d.names if c.startswith("s_")]
    order = {"s_xx": 0, "s_yy": 4, "s_zz": 8, "s_xy": 1, "s_yz": 5, "s_xz": 2}  # row-major 3 x 3 of the frames
    err_frame = 0.0
    for k, tf in enumerate(f.times):
        row = int(np.argmin(np.abs(t - tf)))
        for c in components:
            err_frame = max(err_frame, abs(d[c][row] - f.field("stress", k)[0][order[c]]) / tau_m)
    print(f"station: {len(t)} rows; 2 e_xy within {err_g:.2e} of gamma_m of gamma(t) (bound 1e-5); s_xy within {err_tau:.2e} of tau_m of the "
          f"Masing closed forms (bound 2 e = {2 * e:.2e}); other strains {others:.1e} of gamma_m (bound 1e-12); stress at {len(f.times)} frames "
          f"within {err_frame:.1e} of tau_m of the volume output's (bound 1e-12)")
    return 0 if err_g <= 1e-5 and err_tau <= 2 * e and others <= 1e-12 and err_frame <= 1e-12 and len(f.times) >= 7 else 1


def ricker(t, amplitude, f0, t0):
    a = (np.pi * f0 * (t - t0)) ** 2
    return amplitude * (1 - 2 * a) * np.exp(-a)


class MasingSprings:
    """Masing's rules on the hyperbola F(g) = Gmax g / (1 + g/g_r) in simple shear, as Iwan
    (1967) showed they arise: M elastic-perfectly-plastic springs in parallel, spring j of
    stiffness k_j yielding at strain y_j, so that the first-loading curve sum_j k_j min(g, y_j)
    interpolates F at the yield strains (chosen here log-spaced from 1e-8 to 1, far finer than
    any run's surfaces). Under reversal each spring stays elastic over 2 y_j: the unloading
    branch is tau_a - 2 F((g_a - g)/2), the loop closes, and a branch that passes the last
    reversal rejoins the earlier curve (Masing's extended rules). One state per cell: the
    springs' plastic strains."""

    def __init__(self, gmax, g_r, cells, springs=400):
        y = np.geomspace(1e-8, 1.0, springs)
        F = gmax * y / (1 + y / g_r)
        slope = np.diff(np.concatenate(([0.0], F))) / np.diff(np.concatenate(([0.0], y)))
        self.k = slope - np.concatenate((slope[1:], [0.0]))  # the drop of slope at each kink
        self.y = y
        self.p = np.zeros((cells, springs))

    def stress(self, g):
        d = g[:, None] - self.p
        over = np.abs(d) > self.y
        self.p = np.where(over, g[:, None] - np.sign(d) * self.y, self.p)
        return np.sum(self.k * (g[:, None] - self.p), axis=1)


def column_1d(H, layer_bottom, rho, vs, g_r, amplitude, f0, t0, t_end, dz):
    """Surface velocity of a 1D shear column by velocity-stress finite differences (staggered
    in space and time): nodes every dz from the base (0) to the free top (H), one strain per
    cell, rho dz node masses (half at the ends). The base is the elastic half-space of the
    same material, a Lysmer dashpot with the incident wave: force rho vs (2 v_in - v_0), taken
    at mid-step (second order). Cells above layer_bottom are Masing soil (g_r), the others
    linear (g_r = None: all linear). Returns (t, v_top)."""
    n = int(round(H / dz))
    gmax, c = rho * vs * vs, rho * vs
    dt = 0.5 * dz / vs
    steps = int(np.ceil(t_end / dt))
    centre = (np.arange(n) + 0.5) * dz
    soil = centre > layer_bottom if g_r else np.zeros(n, dtype=bool)
    springs = MasingSprings(gmax, g_r, int(soil.sum())) if g_r else None
    m = np.full(n + 1, rho * dz)
    m[0] = m[-1] = rho * dz / 2
    u = np.zeros(n + 1)
    v_half = np.zeros(n + 1)  # v at t - dt/2
    t_out, v_out = [0.0], [0.0]
    for k in range(steps):
        t = k * dt
        g = np.diff(u) / dz
        tau = gmax * g
        if springs is not None:
            tau[soil] = springs.stress(g[soil])
        f = np.zeros(n + 1)
        f[:-1] += tau
        f[1:] -= tau
        v_new = v_half + dt * f / m
        # Base: m0 (v+ - v-)/dt = f0 + c (2 v_in - (v+ + v-)/2).
        v_new[0] = (m[0] * v_half[0] / dt + f[0] + c * (2 * ricker(t, amplitude, f0, t0) - 0.5 * v_half[0])) / (m[0] / dt + 0.5 * c)
        if k > 0:
            t_out.append(t)
            v_out.append(0.5 * (v_half[-1] + v_new[-1]))
        v_half = v_new
        u = u + dt * v_half
    return np.array(t_out), np.array(v_out)


def column(args):
    """The surface velocity of slipwave's 1D column against column_1d's, relative L2 over
    the record (the FD solution interpolated to the station's times)."""
    d = read_csv(args.station)
    t, v = d["t"], d["v_x"]
    ts, vs_fd = column_1d(args.height, args.layer_bottom, args.rho, args.speed, args.reference_strain, args.amplitude, args.f0, args.t0, t[-1], args.dz)
    ref = np.interp(t, ts, vs_fd)
    l2 = math.sqrt(np.sum((v - ref) ** 2) / np.sum(ref ** 2))
    tl, vl = column_1d(args.height, args.layer_bottom, args.rho, args.speed, None, args.amplitude, args.f0, args.t0, t[-1], args.dz)
    lin = np.interp(t, tl, vl)
    nonlinear = math.sqrt(np.sum((lin - ref) ** 2) / np.sum(ref ** 2))
    # The finite differences against the closed form of the linear column, 2 v_in(t - H/c).
    exact = 2 * ricker(t - args.height / args.speed, args.amplitude, args.f0, args.t0)
    fd_err = math.sqrt(np.sum((lin - exact) ** 2) / np.sum(exact ** 2))
    print(f"column: surface velocity against the 1D Masing finite differences: L2 {l2:.3e} (bound {args.l2_max:.1e}); "
          f"the nonlinear answer differs from the linear one by {nonlinear:.3e}; peaks {np.max(np.abs(v)):.4f} (slipwave), "
          f"{np.max(np.abs(ref)):.4f} (FD), {np.max(np.abs(lin)):.4f} m/s (linear); FD linear against 2 v_in(t - H/c): {fd_err:.2e}")
    return 0 if l2 <= args.l2_max and nonlinear > 10 * args.l2_max else 1


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="cmd", required=True)
    q = sub.add_parser("loop")
    q.add_argument("csv")
    for name in ("gmax", "reference-strain", "amplitude", "f0", "height", "volume", "area", "rho"):
        q.add_argument("--" + name, type=float, required=True)
    q.add_argument("--surfaces", type=int, required=True)
    q = sub.add_parser("frames")
    q.add_argument("dir")
    for name in ("gmax", "reference-strain", "amplitude", "f0", "height"):
        q.add_argument("--" + name, type=float, required=True)
    q.add_argument("--surfaces", type=int, required=True)
    q = sub.add_parser("station")
    q.add_argument("dir")
    q.add_argument("name")
    for name in ("gmax", "reference-strain", "amplitude", "f0", "height"):
        q.add_argument("--" + name, type=float, required=True)
    q.add_argument("--surfaces", type=int, required=True)
    q = sub.add_parser("column")
    q.add_argument("station")
    for name in ("height", "layer-bottom", "rho", "speed", "reference-strain", "amplitude", "f0", "t0", "dz", "l2-max"):
        q.add_argument("--" + name, type=float, required=True)
    a = p.parse_args()
    return {"loop": loop, "frames": frames, "station": station, "column": column}[a.cmd](a)


if __name__ == "__main__":
    sys.exit(main())

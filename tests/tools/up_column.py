#!/usr/bin/python3
"""Semi-analytic solution of the 1D Biot u-p column (no fluid acceleration), for checking
slipwave's saturated regions in the dynamic regime between drained and undrained.

Depth z from the top (0) to the base (H); u the displacement along +z (down), p the pore
pressure (compression positive), sigma = E u' - alpha p (tension positive), E = K + 4G/3:
    rho u_tt = E u'' - alpha p',     p_t / M + alpha u'_t = kappa p''.
In the Laplace domain every solution is a sum of exp(+-lambda_i z), where mu = lambda^2 solves
    E kappa mu^2 - (rho s^2 kappa + s (E/M + alpha^2)) mu + rho s^3 / M = 0
(derived in docs/saturated-soil.md style from the two equations with u, p ~ exp(m z):
p = alpha s m u / (kappa m^2 - s/M)). Boundary conditions: top z = 0 drained (p = 0) with a
total traction T(s) (sigma_zz = T); base z = H impervious (p' = 0) with a prescribed
displacement U_b(s), or (--base absorbing) slipwave's absorbing base with an incident wave:
the Lysmer dashpot of impedance Z = rho c_u (c_u the undrained P speed, as a saturated
region's absorbing boundary has it) and the incident wave's force 2 Z v_in, so
sigma(H) + Z s u(H) = -2 Z V(s) (V the incident particle velocity, up positive). The four coefficients come from a 4x4 solve per s, written with
exp(-lambda z) and exp(-lambda (H - z)), Re lambda > 0, so nothing overflows.
Time domain: the Fourier-series (Durbin 1974) inversion
    f(t) = e^{ct}/Tp [ F(c)/2 + sum_k Re(F(c + i k pi/Tp) e^{i k pi t/Tp}) ],
valid for 0 <= t < 2 Tp with aliasing error ~ e^{-2 c Tp}.

`python3 up_column.py selfcheck` compares the quasi-static limit (rho -> 0) under a step load
with Terzaghi's series (Terzaghi 1923; Wang 2000 sec. 6.2), which validates the solution and
the inversion together; `compare` checks a slipwave base-shaking run.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from slipwave import RunFolder  # noqa: E402


def laplace_column(s, z, H, E, alpha, M, kappa, rho, T, Ub, Z=0.0):
    """u(z, s), p(z, s) for the arrays z, at one complex s. Z = 0: the base displacement is Ub;
    Z > 0: the base is absorbing, sigma(H) + Z s u(H) = Ub."""
    a = E * kappa
    b = -(rho * s * s * kappa + s * (E / M + alpha * alpha))
    c = rho * s ** 3 / M
    disc = np.sqrt(b * b - 4 * a * c)
    mus = [(-b + disc) / (2 * a), (-b - disc) / (2 * a)]
    lam = [np.sqrt(m) for m in mus]
    lam = [l if l.real > 0 else -l for l in lam]
    g = [alpha * s * l / (kappa * l * l - s / M) for l in lam]
    eH = [np.exp(-l * H) for l in lam]
    # Unknowns A1, A2 (exp(-lam z)), B1, B2 (exp(-lam (H - z))).
    A = np.zeros((4, 4), dtype=complex)
    rhs = np.zeros(4, dtype=complex)
    for i in range(2):
        # top traction: E u' - alpha p at z = 0
        A[0, i] = E * (-lam[i]) - alpha * (-g[i])
        A[0, 2 + i] = (E * lam[i] - alpha * g[i]) * eH[i]
        # top drained: p(0) = 0
        A[1, i] = -g[i]
        A[1, 2 + i] = g[i] * eH[i]
        if Z > 0:
            # absorbing base: sigma(H) + Z s u(H)
            A[2, i] = (E * (-lam[i]) - alpha * (-g[i]) + Z * s) * eH[i]
            A[2, 2 + i] = E * lam[i] - alpha * g[i] + Z * s
        else:
            # base displacement u(H)
            A[2, i] = eH[i]
            A[2, 2 + i] = 1
        # base impervious: p'(H) = 0
        A[3, i] = g[i] * lam[i] * eH[i]
        A[3, 2 + i] = g[i] * lam[i]
    rhs[0], rhs[2] = T, Ub
    x = np.linalg.solve(A, rhs)
    u = np.zeros(len(z), dtype=complex)
    p = np.zeros(len(z), dtype=complex)
    for i in range(2):
        e1, e2 = np.exp(-lam[i] * z), np.exp(-lam[i] * (H - z))
        u += x[i] * e1 + x[2 + i] * e2
        p += -g[i] * x[i] * e1 + g[i] * x[2 + i] * e2
    return u, p


def invert(times, z, H, E, alpha, M, kappa, rho, T_of_s, Ub_of_s, Tp, c, kmax, Z=0.0):
    """u(z, t), p(z, t): arrays len(times) x len(z)."""
    times = np.asarray(times)
    u = np.zeros((len(times), len(z)))
    p = np.zeros((len(times), len(z)))
    for k in range(kmax + 1):
        s = c + 1j * k * math.pi / Tp
        uk, pk = laplace_column(s, np.asarray(z, dtype=float), H, E, alpha, M, kappa, rho, T_of_s(s), Ub_of_s(s), Z)
        w = 0.5 if k == 0 else 1.0
        phase = np.exp(1j * k * math.pi * times / Tp)[:, None]
        u += w * np.real(uk[None, :] * phase)
        p += w * np.real(pk[None, :] * phase)
    scale = (np.exp(c * times) / Tp)[:, None]
    return u * scale, p * scale


def ricker_laplace(f0, t0, amplitude, t_end):
    """Laplace transform of the Ricker velocity, by quadrature of the sampled wavelet (it is
    below 1e-12 of its peak outside [0, t_end])."""
    t = np.linspace(0, t_end, 20001)
    a = (math.pi * f0 * (t - t0)) ** 2
    v = amplitude * (1 - 2 * a) * np.exp(-a)
    dt = t[1] - t[0]
    return lambda s: np.sum(v * np.exp(-s * t)) * dt


def selfcheck(a):
    # Terzaghi: E = 3.2e8, M = 5.5e9, alpha = 1, kappa = 3.87e-8, H = 10 (as saturated_terzaghi.sh).
    E, M, alpha, kappa, H, load = 3.2e8, 5.5e9, 1.0, 3.8e-4 / (1000 * 9.80665), 10.0, 1e5
    cv = kappa / (1 / M + alpha ** 2 / E)
    gamma = alpha * M / (E + alpha ** 2 * M)
    worst = 0.0
    for Tv in (0.1, 0.3, 0.6):
        t = Tv * H ** 2 / cv
        Tp = 4 * t
        _, p = invert([t], [2.5, 7.5], H, E, alpha, M, kappa, a.rho, lambda s: -load / s, lambda s: 0.0, Tp, 6 / Tp, 16000)
        for j, depth in enumerate((2.5, 7.5)):
            m = 2 * np.arange(400) + 1
            want = gamma * load * np.sum(4 / (m * math.pi) * np.sin(m * math.pi * depth / (2 * H)) * np.exp(-(m * math.pi) ** 2 * Tv / 4))
            err = abs(p[0, j] - want) / load
            worst = max(worst, err)
            print(f"selfcheck: T_v {Tv}, depth {depth} m: Laplace {p[0, j]:.6g} Pa, Terzaghi {want:.6g} Pa, difference {err:.2e} of the load")
    print(f"selfcheck: largest difference {worst:.2e} of the load (bound {a.tol:.0e})")
    return 0 if worst <= a.tol else 1


def compare(a):
    """slipwave's column shaken at its base (velocity a Ricker, y up; --base absorbing: the
    incident wave's velocity) against the solution: relative L2 over [0, t_end] of the top
    displacement and of p at each station."""
    E = a.rho * a.vp ** 2
    M = a.fluid_bulk_modulus / a.porosity
    kappa = a.hydraulic_conductivity / (1000 * 9.80665)
    V = ricker_laplace(a.f0, a.t0, a.amplitude, 2 * a.t0 + 1.0)
    Tp = 4 * a.t_end
    ok = True
    names = a.stations.split(",")
    depths = [float(x) for x in a.depths.split(",")]
    data = [RunFolder(a.dir).station(n) for n in names]
    t = data[0]["t"]
    keep = t <= a.t_end
    t = t[keep]
    kmax = int(2 * math.pi * 8 * a.f0 * Tp / math.pi)
    if a.base == "absorbing":
        Z = a.rho * math.sqrt((E + M) / a.rho)  # rho c_u, alpha = 1
        u, p = invert(t, depths, a.height, E, 1.0, M, kappa, a.rho, lambda s: 0.0, lambda s: -2 * Z * V(s), Tp, 5 / Tp, kmax, Z)
    else:
        # Base displacement along +z (down) is minus the upward one: U_b = -V/s.
        u, p = invert(t, depths, a.height, E, 1.0, M, kappa, a.rho, lambda s: 0.0, lambda s: -V(s) / s, Tp, 5 / Tp, kmax)
    for j, (name, d) in enumerate(zip(names, depths)):
        if d > 0:  # the drained top has p = 0
            got_p = data[j]["p"][keep]
            err = math.sqrt(np.sum((got_p - p[:, j]) ** 2) / np.sum(p[:, j] ** 2))
            ok = ok and err <= a.tol
            print(f"up-column: {name} (depth {d} m): p relative L2 {err:.3e} (bound {a.tol:.0e}), peak {np.max(np.abs(p[:, j])):.4g} Pa")
        else:
            got_u = -data[j]["u_y"][keep]
            err = math.sqrt(np.sum((got_u - u[:, j]) ** 2) / np.sum(u[:, j] ** 2))
            ok = ok and err <= a.tol
            print(f"up-column: {name}: top displacement relative L2 {err:.3e} (bound {a.tol:.0e}), peak {np.max(np.abs(u[:, j])):.4g} m")
    return 0 if ok else 1


def convergence(a):
    """The observed spatial order of three runs of the same column (a.dirs: element sizes h,
    h/2, h/4, coarse to fine) taken with one time step: per station (name:u for the top
    displacement, name:p for the pore pressure), the relative L2 distances d1 = |x_h - x_h/2| /
    |x_h/2| and d2 = |x_h/2 - x_h/4| / |x_h/4| over [0, t_end] and the rate log2(d1 / d2), which
    must be at least --min-rate. With the one step the runs share their time error, so the
    distances are the spatial ones (the semi-analytic solution could not show them below
    ~1e-4, its own accuracy and the split's time error)."""
    runs = [RunFolder(d) for d in a.dirs.split(",")]
    ok = True
    for item in a.stations.split(","):
        name, kind = item.split(":")
        series = [r.station(name) for r in runs]
        if any(len(x["t"]) != len(series[0]["t"]) or np.max(np.abs(x["t"] - series[0]["t"])) > 1e-12 for x in series):
            print(f"up-column convergence: {name}: the runs are not sampled at the same times (one -ts_dt for all)")
            return 1
        keep = series[0]["t"] <= a.t_end
        x = [(-d["u_y"] if kind == "u" else d["p"])[keep] for d in series]
        d1 = math.sqrt(np.sum((x[0] - x[1]) ** 2) / np.sum(x[1] ** 2))
        d2 = math.sqrt(np.sum((x[1] - x[2]) ** 2) / np.sum(x[2] ** 2))
        rate = math.log2(d1 / d2)
        ok = ok and rate >= a.min_rate
        print(f"up-column convergence: {name} ({'top displacement' if kind == 'u' else 'pore pressure'}): relative L2 distances h -> h/2 {d1:.3e}, "
              f"h/2 -> h/4 {d2:.3e}, observed order {rate:.2f} (at least {a.min_rate})")
    return 0 if ok else 1


def main():
    p = argparse.ArgumentParser(description=__doc__)
    sub = p.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("selfcheck")
    s.add_argument("--tol", type=float, default=1e-3)
    s.add_argument("--rho", type=float, default=2.0, help="a density small enough that inertia is negligible [kg/m^3]")
    c = sub.add_parser("compare")
    c.add_argument("dir")
    c.add_argument("--stations", required=True, help="names, the top one (depth 0) first")
    c.add_argument("--depths", required=True)
    c.add_argument("--height", type=float, required=True)
    c.add_argument("--rho", type=float, required=True)
    c.add_argument("--vp", type=float, required=True)
    c.add_argument("--porosity", type=float, required=True)
    c.add_argument("--fluid-bulk-modulus", type=float, default=2.2e9)
    c.add_argument("--hydraulic-conductivity", type=float, required=True)
    c.add_argument("--f0", type=float, required=True)
    c.add_argument("--t0", type=float, required=True)
    c.add_argument("--amplitude", type=float, required=True)
    c.add_argument("--t-end", type=float, required=True)
    c.add_argument("--base", choices=("velocity", "absorbing"), default="velocity", help="prescribed base velocity, or an absorbing base with the incident wave")
    c.add_argument("--tol", type=float, default=0.03)
    v = sub.add_parser("convergence")
    v.add_argument("dirs", help="three output dirs, element size h, h/2, h/4")
    v.add_argument("--stations", required=True, help="name:u (top displacement) or name:p (pore pressure), ...")
    v.add_argument("--t-end", type=float, required=True)
    v.add_argument("--min-rate", type=float, required=True)
    a = p.parse_args()
    return {"selfcheck": selfcheck, "compare": compare, "convergence": convergence}[a.cmd](a)


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Checks of slipwave's saturated (Biot u-p) regions against closed-form poroelasticity.

Material numbers are recomputed here from the scene's inputs (not read from slipwave), with
the formulas of Wang (2000), "Theory of Linear Poroelasticity", ch. 2-3 and 6:
  alpha = 1 (incompressible grains), M = K_f / n, E = rho vp^2 (drained P modulus),
  kappa = k_h / (rho_f g), c_v = kappa / (1/M + alpha^2 / E), gamma = alpha M / (E + alpha^2 M).
Each subcommand prints what it measured and exits 1 when a bound is violated.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from slipwave import RunFolder, read_csv  # noqa: E402

G_STANDARD = 9.80665


def material(a):
    E = a.rho * a.vp ** 2
    M = a.fluid_bulk_modulus / a.porosity
    alpha = 1.0
    kappa = a.hydraulic_conductivity / (1000.0 * G_STANDARD)
    return dict(E=E, M=M, alpha=alpha, kappa=kappa, cv=kappa / (1 / M + alpha ** 2 / E), gamma=alpha * M / (E + alpha ** 2 * M),
                vu=math.sqrt((E + alpha ** 2 * M) / a.rho))


def terzaghi_pressure(depth, H, Tv, p0, terms=400):
    """Terzaghi (1923) series for a layer drained at depth 0, impervious at depth H, under a
    load applied at t = 0: p = p0 sum_m 4/(m pi) sin(m pi z / 2H) exp(-m^2 pi^2 Tv / 4), m odd.
    With compressible constituents the same series holds with p0 = gamma sigma and c_v above
    (Wang 2000, sec. 6.2)."""
    m = 2 * np.arange(terms) + 1
    return p0 * np.sum(4 / (m * math.pi) * np.sin(m * math.pi * depth / (2 * H)) * np.exp(-(m * math.pi) ** 2 * Tv / 4))


def terzaghi_mean(Tv, terms=400):
    """Mean of p/p0 over the layer: sum_m 8/(m pi)^2 exp(-m^2 pi^2 Tv / 4), m odd (Terzaghi)."""
    m = 2 * np.arange(terms) + 1
    return np.sum(8 / (m * math.pi) ** 2 * np.exp(-(m * math.pi) ** 2 * Tv / 4))


TERZAGHI_TIMES = (0.1, 0.3, 0.6)  # the T_v at which the Terzaghi checks sample a run


def terzaghi_samples(a, folder):
    """A Terzaghi run's p at each station and its settlement at each T_v of TERZAGHI_TIMES:
    [(T_v, t, [(depth, p), ...], settlement)]."""
    mat = material(a)
    stations = [(name, float(depth)) for name, depth in (s.split(":") for s in a.stations.split(","))]
    run = RunFolder(folder)
    top = run.station(a.top)
    out = []
    for Tv in TERZAGHI_TIMES:
        t = Tv * a.height ** 2 / mat["cv"]
        ps = [(depth, np.interp(t, run.station(name)["t"], run.station(name)["p"])) for name, depth in stations]
        out.append((Tv, t, ps, -np.interp(t, top["t"], top["u_y"])))
    return out


def terzaghi(a):
    mat = material(a)
    H, load = a.height, a.load
    p0 = mat["gamma"] * load
    ok = True
    print(f"terzaghi: c_v {mat['cv']:.5g} m^2/s, loading efficiency {mat['gamma']:.5f}, p0 {p0:.6g} Pa, H {H} m")
    for Tv, t, ps, got_s in terzaghi_samples(a, a.dir):
        for depth, got in ps:
            want = terzaghi_pressure(depth, H, Tv, p0)
            err = abs(got - want) / load
            ok = ok and err <= a.p_tol
            print(f"terzaghi: T_v {Tv}: t {t:.5g} s, depth {depth} m: p {got:.6g} Pa, Terzaghi {want:.6g} Pa, error {err:.2e} of the load (bound {a.p_tol:.0e})")
        # Settlement = integral of the strain, eps = (-load + alpha p)/E (uniaxial strain).
        want_s = (load * H - mat["alpha"] * p0 * H * terzaghi_mean(Tv)) / mat["E"]
        err = abs(got_s - want_s) / want_s
        ok = ok and err <= a.s_tol
        print(f"terzaghi: T_v {Tv}: settlement {got_s:.6g} m, Terzaghi {want_s:.6g} m, relative error {err:.2e} (bound {a.s_tol:.0e})")
    return 0 if ok else 1


def terzaghi_discretisation(a):
    """The discretisation error of a Terzaghi run: its distance from a finer run of the same
    scene (a.reference), at the samples of `terzaghi`: the largest p difference over the load
    and the largest relative settlement difference. Below ~1e-3 the closed form cannot measure
    it: the mass-proportional damping that stills the undrained ringing drags the consolidation
    by that much on every mesh (halving the damping halves it). Each run's two numbers must be
    within the bounds; with --coarser, every run listed there (fewer or more unknowns, another
    degree) must be farther from the reference on both."""
    ref = terzaghi_samples(a, a.reference)

    def distance(folder):
        dp = ds = 0.0
        for (_, _, ps, s), (_, _, qs, r) in zip(terzaghi_samples(a, folder), ref):
            dp = max([dp] + [abs(p - q) / a.load for (_, p), (_, q) in zip(ps, qs)])
            ds = max(ds, abs(s - r) / abs(r))
        return dp, ds

    dp, ds = distance(a.dir)
    ok = dp <= a.p_tol and ds <= a.s_tol
    print(f"terzaghi discretisation: {a.dir}: p {dp:.2e} of the load (bound {a.p_tol:.0e}), settlement {ds:.2e} (bound {a.s_tol:.0e}) from {a.reference}")
    for other in a.coarser or []:
        op, os_ = distance(other)
        farther = op > dp and os_ > ds
        ok = ok and farther
        print(f"terzaghi discretisation: {other}: p {op:.2e}, settlement {os_:.2e}: {'farther, as it must be' if farther else 'NOT farther'}")
    return 0 if ok else 1


def delay(t, x, y):
    """Time by which y lags x: peak of the cross-correlation, refined by a parabola."""
    dt = t[1] - t[0]
    c = np.correlate(y, x, mode="full")
    k = int(np.argmax(c))
    frac = 0.5 * (c[k - 1] - c[k + 1]) / (c[k - 1] - 2 * c[k] + c[k + 1])
    return (k - (len(x) - 1) + frac) * dt


def pulse(a):
    """A P pulse travelling up a column between stations a.lower and a.upper (a.distance
    apart): its speed from the cross-correlation delay, and at the upper station the ratio
    p / (rho c v_y), which is the loading efficiency for the undrained plane wave
    (sigma_yy = -rho c v_y for an upgoing wave, p = gamma (-sigma_yy))."""
    mat = material(a)
    lo = RunFolder(a.dir).station(a.lower)
    up = RunFolder(a.dir).station(a.upper)
    speed_want = mat["vu"] if a.limit == "undrained" else a.vp
    vname = "v_" + a.component
    c = a.distance / delay(lo["t"], lo[vname], up[vname])
    err = abs(c - speed_want) / speed_want
    ok = err <= a.speed_tol
    print(f"pulse: speed {c:.6g} m/s, {a.limit} speed {speed_want:.6g} m/s (undrained {mat['vu']:.6g}, drained {a.vp:.6g}), relative error {err:.2e} (bound {a.speed_tol:.0e})")
    if a.limit == "undrained":
        v, p = up[vname], up["p"]
        big = np.abs(v) > 0.2 * np.max(np.abs(v))
        ratio = np.sum(p[big] * v[big]) / np.sum(v[big] ** 2) / (a.rho * mat["vu"])
        err = abs(ratio - mat["gamma"]) / mat["gamma"]
        ok = ok and err <= a.gamma_tol
        print(f"pulse: p / (rho c v) {ratio:.6f}, loading efficiency {mat['gamma']:.6f}, relative error {err:.2e} (bound {a.gamma_tol:.0e})")
    if a.late_after is not None:
        # After the pulse has left through the top, anything at the upper station came back.
        late = np.max(np.abs(up[vname][up["t"] > a.late_after])) / np.max(np.abs(up[vname]))
        ok = ok and late <= a.late_max
        print(f"pulse: motion after t = {a.late_after} s {late:.2e} of the peak (bound {a.late_max:.0e})")
    return 0 if ok else 1


def energy(a):
    """The budget with the fluid (docs/saturated-soil.md): stored (kinetic + strain + fluid
    storage) change = work in - absorbed - damped - Darcy dissipation + inflow work, to
    round-off. The Darcy column must matter: without it the error would be darcy/scale."""
    d = read_csv(a.csv)
    err = np.max(np.abs(d["relative_balance_error"]))
    darcy, inflow = d["darcy_dissipated"][-1], d["fluid_inflow_work"][-1]
    work_in = d["input_work"][-1]
    scale = np.max(np.abs(d["balance_error"])) / max(err, 1e-300)
    ok = err <= a.max_error and darcy >= a.min_darcy_fraction * work_in and np.all(np.diff(d["darcy_dissipated"]) >= -1e-12 * scale)
    print(f"energy: max relative balance error {err:.3e} (bound {a.max_error:.0e}); Darcy dissipation {darcy:.6g} J = {darcy / work_in:.3f} of the input "
          f"{work_in:.6g} J (at least {a.min_darcy_fraction}), never decreasing; inflow work {inflow:.4g} J")
    return 0 if ok else 1


def checkerboard(a):
    """The node-alternating part of the pore pressure on the grid of node lines (uniform at
    degree 1; at degree p > 1 the lines through the GLL nodes, unevenly spaced): per sub-cell
    c = (p00 - p10 - p01 + p11)/4, which is +-A for a checkerboard of amplitude A and
    dx dy p_xy / 4 for a smooth field (below 1 % of max |p| for the wavelengths a mesh of 10
    points per wavelength carries: (h k)^2 / 4 <= (2 pi / 10)^2 / 4 = 0.1, times the share of
    the mixed derivative). Sub-cells within `margin` node lines of the box's edges are left out
    (corners of absorbing boundaries); every field frame after the first is checked."""
    f = RunFolder(a.dir).volume()
    g = f.geometry
    lines = [np.unique(np.round(g[:, d], 9)) for d in (0, 1)]
    I, J = (np.searchsorted(lines[d], np.round(g[:, d], 9)) for d in (0, 1))
    x0, x1, y0, y1 = (float(v) for v in a.box.split(","))
    i0, i1 = np.searchsorted(lines[0], x0 - 1e-9) + a.margin, np.searchsorted(lines[0], x1 + 1e-9) - 1 - a.margin
    j0, j1 = np.searchsorted(lines[1], y0 - 1e-9) + a.margin, np.searchsorted(lines[1], y1 + 1e-9) - 1 - a.margin
    worst = 0.0
    frames = f.series("pore_pressure")[1:]
    for p in frames:
        P = np.zeros((I.max() + 1, J.max() + 1))
        P[I, J] = p[:, 0]
        W = P[i0:i1 + 1, j0:j1 + 1]
        c = (W[:-1, :-1] - W[1:, :-1] - W[:-1, 1:] + W[1:, 1:]) / 4
        worst = max(worst, np.max(np.abs(c)) / np.max(np.abs(W)))
    print(f"checkerboard: largest node-alternating part {worst:.3e} of max |p| over {len(frames)} frames (bound {a.max_ratio:.0e}; a checkerboard gives ~1)")
    return 0 if worst <= a.max_ratio else 1


def geostatic(a):
    """After the geostatic stage of a column under gravity with a water table: the effective
    vertical stress (the volume output's stress of frame 0) is the total overburden minus
    alpha p_h, sigma'_yy(y) = -g int_y^H rho dy + alpha rho_f g (z_w - y)+ (Terzaghi's
    effective stress with hydrostatic pore water), within round-off of the static solve; the
    stations' total p is rho_f g (z_w - y)+, and over the dynamic stage nothing moves and the
    excess pore pressure stays zero."""
    g = 9.81
    f = RunFolder(a.dir).volume()
    xyz, cells = f.geometry, f.topology
    yc = xyz[cells][:, :, 1].mean(axis=1)
    syy = f.field("stress", 0)[:, 4]
    # Layers: (top elevation, bottom elevation, density) from the top down.
    layers = [tuple(float(v) for v in l.split(":")) for l in a.layers.split(",")]

    def overburden(y):
        total = 0.0
        for top, bottom, rho in layers:
            total += rho * g * max(0.0, top - max(bottom, y)) if y < top else 0.0
        return total
    want = np.array([-overburden(y) + a.rho_f * g * max(0.0, a.water_table - y) for y in yc])
    err = np.max(np.abs(syy - want)) / np.max(np.abs(want))
    ok = err <= a.stress_tol
    print(f"geostatic: effective vertical stress against overburden - p_h: largest error {err:.2e} of the largest (bound {a.stress_tol:.0e}) over {len(yc)} cells")
    for name, y in (s.split(":") for s in a.stations.split(",")):
        d = RunFolder(a.dir).station(name)
        want_p = a.rho_f * g * max(0.0, a.water_table - float(y))
        err_p = np.max(np.abs(d["p"] - want_p)) / (a.rho_f * g * a.water_table)
        exc = np.max(np.abs(d["p_excess"])) / (a.rho_f * g * a.water_table)
        vmax = max(np.max(np.abs(d[c])) for c in d.names if c.startswith("v_"))
        ok = ok and err_p <= a.stress_tol and exc <= a.stress_tol and vmax <= a.v_max
        print(f"geostatic: station {name} (y = {y} m): p {d['p'][-1]:.6g} Pa against rho_f g (z_w - y) = {want_p:.6g} Pa (error {err_p:.1e}), "
              f"excess {exc:.1e}, max |v| {vmax:.1e} m/s (bounds {a.stress_tol:.0e} of rho_f g z_w, {a.v_max:.0e} m/s)")
    return 0 if ok else 1


def mandel_roots(k, count=300):
    """The positive roots of tan(x) = k x (k > 1), one per interval (m pi, (m+1) pi) after the
    first in (0, pi/2), by bisection on sin x - k x cos x."""
    f = lambda x: math.sin(x) - k * x * math.cos(x)
    roots = []
    for m in range(count):
        lo, hi = m * math.pi + 1e-9, (m + 1) * math.pi - 1e-9
        xs = np.linspace(lo, hi, 64)
        ys = [f(x) for x in xs]
        for i in range(len(xs) - 1):
            if ys[i] * ys[i + 1] < 0:
                a, b = xs[i], xs[i + 1]
                for _ in range(80):
                    mid = 0.5 * (a + b)
                    (a, b) = (mid, b) if f(a) * f(mid) > 0 else (a, mid)
                roots.append(0.5 * (a + b))
    return np.array(roots)


def mandel(a):
    """Mandel's problem (plane strain; Cheng & Detournay 1988, Abousleiman et al. 1996): a
    specimen of half-width a between rigid frictionless plates under the force 2F (stress
    sigma = F/a), lateral sides drained. With nu, nu_u the drained and undrained Poisson
    ratios, B Skempton's coefficient and c = 2 kappa B^2 G (1-nu)(1+nu_u)^2 / (9 (1-nu_u)(nu_u-nu)):
      p(x, t) = 2 p0 sum_n sin(a_n) / (a_n - sin a_n cos a_n) (cos(a_n x/a) - cos a_n) exp(-a_n^2 c t/a^2),
      p0 = sigma B (1 + nu_u) / 3,  tan a_n = (1 - nu)/(nu_u - nu) a_n.
    The centre pressure first rises above p0 (the Mandel-Cryer effect) and returns to it later.
    Checked: the peak of p(0, t), the time it returns to p0 (a well-conditioned marker of the
    rise; the peak itself is too flat to time), and both stations' p over [t1, t_end]."""
    rho, G = a.rho, a.rho * a.vs ** 2
    lam = a.rho * a.vp ** 2 - 2 * G
    K = lam + 2 * G / 3
    M = a.fluid_bulk_modulus / a.porosity
    Ku = K + M
    B = M / Ku
    nu, nuu = (3 * K - 2 * G) / (2 * (3 * K + G)), (3 * Ku - 2 * G) / (2 * (3 * Ku + G))
    kappa = a.hydraulic_conductivity / (1000 * G_STANDARD)
    c = 2 * kappa * B ** 2 * G * (1 - nu) * (1 + nuu) ** 2 / (9 * (1 - nuu) * (nuu - nu))
    p0 = a.load * B * (1 + nuu) / 3
    roots = mandel_roots((1 - nu) / (nuu - nu))
    coef = 2 * np.sin(roots) / (roots - np.sin(roots) * np.cos(roots))

    def p(x, t):
        return p0 * np.sum(coef * (np.cos(roots * x / a.half_width) - np.cos(roots)) * np.exp(-roots ** 2 * c * t / a.half_width ** 2))
    print(f"mandel: nu {nu:.4f}, nu_u {nuu:.4f}, B {B:.4f}, c {c:.4f} m^2/s, p0 {p0:.6g} Pa; the series at t = 0+ gives {p(0.0, 0.0) / p0:.4f} p0")
    ok = True
    ts = np.linspace(a.t1, a.t_end, 4000)
    for name, x in ((n.split(":")[0], float(n.split(":")[1])) for n in a.stations.split(",")):
        d = RunFolder(a.dir).station(name)
        got = np.interp(ts, d["t"], d["p"])
        want = np.array([p(x, t) for t in ts])
        err = np.max(np.abs(got - want)) / p0
        ok = ok and err <= a.tol
        print(f"mandel: {name} (x = {x} m): p over [{a.t1}, {a.t_end}] s within {err:.2e} p0 of the series (bound {a.tol:.0e})")
        if x == 0:
            peak_w, peak_g = np.max(want), np.max(got)
            t_w, t_g = ts[np.argmax((want < p0) & (ts > ts[np.argmax(want)]))], ts[np.argmax((got < p0) & (ts > ts[np.argmax(got)]))]
            e_peak, e_time = abs(peak_g - peak_w) / peak_w, abs(t_g - t_w) / t_w
            ok = ok and e_peak <= a.tol and e_time <= a.tol and peak_w > 1.03 * p0
            print(f"mandel: centre peak {peak_g:.6g} Pa against {peak_w:.6g} Pa = {peak_w / p0:.4f} p0 (error {e_peak:.2e}); back to p0 at {t_g:.5f} s "
                  f"against {t_w:.5f} s (error {e_time:.2e}); bound {a.tol:.0e}")
    return 0 if ok else 1


def site(a):
    """The saturated site scene shaken by SV and by P (config/scenes/saturated_site.yaml):
    - both budgets close to round-off (relative balance error <= --energy-tol);
    - SV: a vertically incident shear wave in a laterally uniform column changes no volume,
      so the excess pore pressure stays at the geostatic relaxation's residue, below
      --sv-ratio of what P gives at the same stations;
    - P: the layer (30 m) is thin against the wavelength (866 m at 2 Hz) and undrained away
      from the surface (diffusion length sqrt(c_v / w) = 0.6 m), so at depth z the vertical
      total stress is the inertia of the soil above, sigma_yy = -rho z a_mean (a_mean the
      trapezoid mean of a_y between the surface and the station; the profile's curvature
      error is ~ (k z)^2 / 12 < 1 %), and the excess pore pressure is gamma rho z a_mean
      (gamma the loading efficiency): relative L2 below --p-tol."""
    ok = True
    for run in (a.sv, a.p):
        e = RunFolder(run).energy()
        err = np.max(np.abs(e["relative_balance_error"]))
        ok = ok and err <= a.energy_tol
        print(f"site: {run}: energy balance {err:.2e} (bound {a.energy_tol:.0e})")
    E, M = a.rho * a.vp ** 2, a.fluid_bulk_modulus / a.porosity
    gamma = M / (E + M)
    surface = RunFolder(a.p).station(a.surface)
    for name, depth in ((n.split(":")[0], float(n.split(":")[1])) for n in a.stations.split(",")):
        dp = RunFolder(a.p).station(name)
        ds = RunFolder(a.sv).station(name)
        pred = gamma * a.rho * depth * 0.5 * (surface["a_y"] + dp["a_y"])
        l2 = math.sqrt(np.sum((dp["p_excess"] - pred) ** 2) / np.sum(pred ** 2))
        ratio = np.max(np.abs(ds["p_excess"])) / np.max(np.abs(dp["p_excess"]))
        ok = ok and l2 <= a.p_tol and ratio <= a.sv_ratio
        print(f"site: {name} (depth {depth} m): P: excess p against gamma rho z a_mean, relative L2 {l2:.2e} (bound {a.p_tol:.0e}); "
              f"SV: max |excess p| {ratio:.1e} of P's (bound {a.sv_ratio:.0e})")
    return 0 if ok else 1


def main():
    p = argparse.ArgumentParser(description=__doc__)
    sub = p.add_subparsers(dest="cmd", required=True)
    parsers = []
    t = sub.add_parser("terzaghi")
    t.add_argument("dir")
    t.add_argument("--height", type=float, required=True)
    t.add_argument("--load", type=float, required=True, help="compressive load on the top [Pa]")
    t.add_argument("--stations", required=True, help="name:depth,... (depth below the drained top [m])")
    t.add_argument("--top", required=True, help="station at the loaded top")
    t.add_argument("--p-tol", type=float, default=0.01)
    t.add_argument("--s-tol", type=float, default=0.01)
    parsers.append(t)
    td = sub.add_parser("terzaghi-discretisation")
    td.add_argument("dir")
    td.add_argument("--reference", required=True, help="output dir of a finer run of the same scene")
    td.add_argument("--coarser", action="append", help="output dir of a run that must be farther from the reference (repeatable)")
    td.add_argument("--height", type=float, required=True)
    td.add_argument("--load", type=float, required=True, help="compressive load on the top [Pa]")
    td.add_argument("--stations", required=True, help="name:depth,... (depth below the drained top [m])")
    td.add_argument("--top", required=True, help="station at the loaded top")
    td.add_argument("--p-tol", type=float, required=True)
    td.add_argument("--s-tol", type=float, required=True)
    parsers.append(td)
    u = sub.add_parser("pulse")
    u.add_argument("dir")
    u.add_argument("--lower", required=True)
    u.add_argument("--upper", required=True)
    u.add_argument("--distance", type=float, required=True)
    u.add_argument("--limit", choices=("undrained", "drained"), required=True)
    u.add_argument("--component", default="y", help="the vertical axis: y in 2D, z in 3D")
    u.add_argument("--speed-tol", type=float, default=0.01)
    u.add_argument("--gamma-tol", type=float, default=0.02)
    u.add_argument("--late-after", type=float, help="time after which the pulse has left the column [s]")
    u.add_argument("--late-max", type=float, default=0.01)
    parsers.append(u)
    for q in parsers:
        q.add_argument("--rho", type=float, required=True)
        q.add_argument("--vp", type=float, required=True)
        q.add_argument("--porosity", type=float, required=True)
        q.add_argument("--fluid-bulk-modulus", type=float, default=2.2e9)
        q.add_argument("--hydraulic-conductivity", type=float, required=True)
    c = sub.add_parser("checkerboard")
    c.add_argument("dir")
    c.add_argument("--box", required=True, help="x0,x1,y0,y1 of the saturated region [m]")
    c.add_argument("--margin", type=int, default=2)
    c.add_argument("--max-ratio", type=float, required=True)
    gs = sub.add_parser("geostatic")
    gs.add_argument("dir")
    gs.add_argument("--layers", required=True, help="top:bottom:rho,... from the top down [m, m, kg/m^3]")
    gs.add_argument("--water-table", type=float, required=True)
    gs.add_argument("--rho-f", type=float, default=1000.0)
    gs.add_argument("--stations", required=True, help="name:y,...")
    gs.add_argument("--stress-tol", type=float, required=True)
    gs.add_argument("--v-max", type=float, required=True)
    md = sub.add_parser("mandel")
    md.add_argument("dir")
    md.add_argument("--half-width", type=float, required=True)
    md.add_argument("--load", type=float, required=True, help="the plates' compressive stress F/a [Pa]")
    md.add_argument("--stations", required=True, help="name:x,... (x from the centre [m])")
    md.add_argument("--t1", type=float, required=True)
    md.add_argument("--t-end", type=float, required=True)
    md.add_argument("--tol", type=float, default=0.02)
    md.add_argument("--rho", type=float, required=True)
    md.add_argument("--vp", type=float, required=True)
    md.add_argument("--vs", type=float, required=True)
    md.add_argument("--porosity", type=float, required=True)
    md.add_argument("--fluid-bulk-modulus", type=float, default=2.2e9)
    md.add_argument("--hydraulic-conductivity", type=float, required=True)
    st = sub.add_parser("site")
    st.add_argument("--sv", required=True, help="output dir of the SV run")
    st.add_argument("--p", required=True, help="output dir of the P run")
    st.add_argument("--surface", required=True)
    st.add_argument("--stations", required=True, help="name:depth,...")
    st.add_argument("--rho", type=float, required=True)
    st.add_argument("--vp", type=float, required=True)
    st.add_argument("--porosity", type=float, required=True)
    st.add_argument("--fluid-bulk-modulus", type=float, default=2.2e9)
    st.add_argument("--energy-tol", type=float, required=True)
    st.add_argument("--p-tol", type=float, required=True)
    st.add_argument("--sv-ratio", type=float, required=True)
    e = sub.add_parser("energy")
    e.add_argument("csv")
    e.add_argument("--max-error", type=float, required=True)
    e.add_argument("--min-darcy-fraction", type=float, required=True)
    a = p.parse_args()
    return {"terzaghi": terzaghi, "terzaghi-discretisation": terzaghi_discretisation, "pulse": pulse, "energy": energy, "checkerboard": checkerboard, "geostatic": geostatic, "mandel": mandel, "site": site}[a.cmd](a)


if __name__ == "__main__":
    sys.exit(main())

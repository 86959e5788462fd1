#!/usr/bin/python3
"""Plots what a hysteretic (Masing) soil region did and what its model implies, as PNG figures.

usage: /usr/bin/python3 scripts/soil_loops.py OUT [--out DIR] [--region NAME] [--station NAME ...]

OUT is the -output_dir of a run with a hysteretic region (-material_<r>_model hysteretic) and
stations that record stress and strain (-station_stress true) in it. Figures go to OUT/plots/
(or DIR):
  soil_loops_<station>.png    the station's shear stress tau_xy = s_xy against its engineering
                              shear strain gamma_xy = 2 e_xy (the loops), over the region's
                              backbone tau = Gmax gamma G/Gmax(gamma) and its mirror
  soil_curves_<region>.png    G/Gmax and damping ratio against shear strain: the curves the
                              region's backbone implies (G/Gmax of the backbone as run, with
                              its strength cap if any; the Masing damping of that backbone,
                              the hysteretic damping of the model, zero at small strain) against
                              the published curve it came from (Darendeli 2001: his G/Gmax and
                              his damping D = b (G/Gmax)^0.1 D_Masing + D_min; MKZ and GQ/H:
                              their closed forms, uncapped); the stations' closed cycles (secant
                              G/Gmax and loop damping between reversals) as points

The region's parameters come from OUT/run_info.json ("hysteretic_regions", written by the
program); every curve is computed here from the published formulas, not by the program:
  MKZ (Matasovic and Vucetic 1993): G/Gmax = 1 / (1 + beta (gamma/gamma_r)^s)
  table: the user's rows (run_info.json carries them and their "# source:"), linear in
    (ln gamma, ln G/Gmax) between rows, as the program reads them
  GQ/H (Groholski et al. 2016): tau/tau_max = [1 + x - sqrt((1+x)^2 - 4 theta x)] / (2 theta),
    x = gamma/gamma_r, gamma_r = tau_max/Gmax, theta = theta1 + theta2 theta4 x^theta5 /
    (theta3^theta5 + theta4 x^theta5) (rationalised: 2x / (1 + x + sqrt(...)), exact at theta 0)
  Darendeli (2001), the general model fitted to all soils (his phi1..phi12):
    gamma_r = (phi1 + phi2 PI OCR^phi3) (sigma'_0/p_a)^phi4 [%], a = phi5,
    G/Gmax = 1 / (1 + (gamma/gamma_r)^a),
    D_min = (phi6 + phi7 PI OCR^phi8) (sigma'_0/p_a)^phi9 (1 + phi10 ln f) [%],
    D_Masing,a=1 = (100/pi) [4 (gamma - gamma_r ln((gamma + gamma_r)/gamma_r)) / (gamma^2/(gamma + gamma_r)) - 2] [%],
    D_Masing = c1 D_Masing,a=1 + c2 D_Masing,a=1^2 + c3 D_Masing,a=1^3,
    c1 = -1.1143 a^2 + 1.8618 a + 0.2523, c2 = 0.0805 a^2 - 0.0710 a - 0.0095,
    c3 = -0.0005 a^2 + 0.0002 a + 0.0003, b = phi11 + phi12 ln N, D = b (G/Gmax)^0.1 D_Masing + D_min
  Masing damping of a backbone F at amplitude gamma_a (the loop of Masing's rules over 4 pi
  times the secant energy): xi = (2/pi) (2 int_0^gamma_a F / (gamma_a F(gamma_a)) - 1).
The program's N surfaces follow the backbone within the error docs/hysteretic-soil.md states
(1.3 % at N = 24); the small-strain damping of a damped region is its constant-Q on top.
Prints the files written; exits 1 when the run has no hysteretic region or no station with
stress columns.
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from slipwave import RunFolder  # noqa: E402

# Darendeli (2001), Table 8.12 (all soils): phi1 .. phi12 (index 0 unused).
DARENDELI_PHI = (None, 0.0352, 0.0010, 0.3246, 0.3483, 0.9190, 0.8005, 0.0129, -0.1069, -0.2889, 0.2919, 0.6329, -0.0057)
ATMOSPHERE = 101325.0  # p_a [Pa]


def darendeli_reference_strain(pi, ocr, sigma):
    """gamma_r as a ratio (his formula gives percent)."""
    p = DARENDELI_PHI
    return (p[1] + p[2] * pi * ocr ** p[3]) * (sigma / ATMOSPHERE) ** p[4] / 100


def darendeli_modulus_ratio(gamma, pi, ocr, sigma):
    return 1 / (1 + (np.asarray(gamma) / darendeli_reference_strain(pi, ocr, sigma)) ** DARENDELI_PHI[5])


def darendeli_minimum_damping(pi, ocr, sigma, frequency):
    """D_min as a ratio (his formula gives percent)."""
    p = DARENDELI_PHI
    return (p[6] + p[7] * pi * ocr ** p[8]) * (sigma / ATMOSPHERE) ** p[9] * (1 + p[10] * math.log(frequency)) / 100


def darendeli_masing_damping(gamma, reference_strain, curvature):
    """His Masing damping of his curve: the a = 1 closed form corrected to a by c1, c2, c3 (a
    ratio; his formulas give percent)."""
    g, g_r, a = np.asarray(gamma, dtype=float), reference_strain, curvature
    d1 = 100 / math.pi * (4 * (g - g_r * np.log((g + g_r) / g_r)) / (g ** 2 / (g + g_r)) - 2)
    c1 = -1.1143 * a ** 2 + 1.8618 * a + 0.2523
    c2 = 0.0805 * a ** 2 - 0.0710 * a - 0.0095
    c3 = -0.0005 * a ** 2 + 0.0002 * a + 0.0003
    return (c1 * d1 + c2 * d1 ** 2 + c3 * d1 ** 3) / 100


def darendeli_damping(gamma, pi, ocr, sigma, frequency, cycles):
    """His damping ratio D = b (G/Gmax)^0.1 D_Masing + D_min (a ratio)."""
    p = DARENDELI_PHI
    masing = darendeli_masing_damping(gamma, darendeli_reference_strain(pi, ocr, sigma), p[5])
    b = p[11] + p[12] * math.log(cycles)
    return b * darendeli_modulus_ratio(gamma, pi, ocr, sigma) ** 0.1 * masing + darendeli_minimum_damping(pi, ocr, sigma, frequency)


def mkz_modulus_ratio(gamma, reference_strain, curvature, beta):
    return 1 / (1 + beta * (np.asarray(gamma) / reference_strain) ** curvature)


def gqh_modulus_ratio(gamma, gmax, strength, theta):
    g = np.asarray(gamma, dtype=float)
    x = g / (strength / gmax)
    t1, t2, t3, t4, t5 = theta
    th = t1 + t2 * t4 * x ** t5 / (t3 ** t5 + t4 * x ** t5)
    tau = strength * 2 * x / (1 + x + np.sqrt((1 + x) ** 2 - 4 * th * x))
    return tau / (gmax * g)


def published_modulus_ratio(region, gamma):
    """G/Gmax of the published curve the region's backbone came from (uncapped)."""
    kind = region["backbone"]
    if kind == "mkz":
        return mkz_modulus_ratio(gamma, region["reference_strain"], region["curvature"], region["beta"])
    if kind == "darendeli":
        return darendeli_modulus_ratio(gamma, region["plasticity_index"], region["ocr"], region["mean_effective_stress_pa"])
    if kind == "gqh":
        return gqh_modulus_ratio(gamma, region["gmax_pa"], region["strength_pa"], region["theta"])
    if kind == "table":
        return table_modulus_ratio(gamma, np.asarray(region["table"], dtype=float))
    raise ValueError(f"backbone {kind!r}; allowed: mkz, darendeli, gqh, table")


def table_modulus_ratio(gamma, rows):
    """A user's table (strain, G/Gmax), read as the program reads it: linear in (ln gamma,
    ln G/Gmax) between rows, the first row's ratio below it, the last row's stress beyond."""
    g = np.asarray(gamma, dtype=float)
    ratio = np.exp(np.interp(np.log(g), np.log(rows[:, 0]), np.log(rows[:, 1])))
    beyond = g > rows[-1, 0]
    return np.where(beyond, rows[-1, 1] * rows[-1, 0] / g, ratio)


def model_modulus_ratio(region, gamma):
    """G/Gmax of the backbone as run: the published one, capped at tau_max (strength_pa > 0) for
    MKZ and Darendeli (GQ/H's strength is its own tau_max)."""
    ratio = published_modulus_ratio(region, gamma)
    cap = region["strength_pa"] / region["gmax_pa"]
    if region["backbone"] != "gqh" and cap > 0:
        ratio = np.minimum(ratio, cap / np.asarray(gamma))
    return ratio


def masing_damping(ratio_of, gamma_a, panels=4000):
    """(2/pi) (2 int_0^gamma_a F / (gamma_a F(gamma_a)) - 1) with F(g) = g ratio_of(g) (Gmax 1):
    Simpson's rule in ln g from 1e-12 gamma_a (below it F = g to that precision)."""
    out = []
    for ga in np.atleast_1d(gamma_a):
        s = np.linspace(math.log(ga * 1e-12), math.log(ga), 2 * panels + 1)
        g = np.exp(s)
        f = g * ratio_of(g) * g  # F dg = F g ds
        h = s[1] - s[0]
        integral = (ga * 1e-12) ** 2 / 2 + h / 3 * (f[0] + f[-1] + 4 * f[1:-1:2].sum() + 2 * f[2:-1:2].sum())
        out.append(2 / math.pi * (2 * integral / (ga * ga * ratio_of(np.array([ga]))[0]) - 1))
    return np.array(out)


def station_cycles(gamma, tau, gmax, smallest=1e-6, closure=0.1):
    """Secant G/Gmax and damping of the station's closed cycles: from each strain reversal to
    the second next (a full cycle), amplitude gamma_a = half the strain range, tau_a half the
    stress range, damping = loop area / (2 pi tau_a gamma_a). Left out: cycles below
    `smallest` (the model's elastic limit: no loop) and those that do not close (end point
    further than `closure` of the ranges from the start), whose area is no loop's."""
    d = np.diff(gamma)
    turns = [k for k in range(1, len(d)) if d[k - 1] * d[k] < 0]
    out = []
    for i0, i2 in zip(turns, turns[2:]):
        g, t = gamma[i0:i2 + 1], tau[i0:i2 + 1]
        ga, ta = (g.max() - g.min()) / 2, (t.max() - t.min()) / 2
        if ga < smallest or ta <= 0 or abs(g[-1] - g[0]) > closure * 2 * ga or abs(t[-1] - t[0]) > closure * 2 * ta:
            continue
        area = abs(np.sum(0.5 * (t[1:] + t[:-1]) * np.diff(g)))
        out.append((ga, ta / (gmax * ga), area / (2 * math.pi * ta * ga)))
    return np.array(out).reshape(-1, 3)


def plot_loops(path, name, gamma, tau, region):
    fig, ax = plt.subplots(figsize=(6, 5))
    ax.plot(gamma * 100, tau / 1e3, lw=0.8, label=f"station {name}")
    top = max(np.max(np.abs(gamma)), 1e-9)
    g = np.linspace(1e-9, top, 400)
    F = region["gmax_pa"] * g * model_modulus_ratio(region, g)
    ax.plot(g * 100, F / 1e3, "k--", lw=0.8, label="backbone")
    ax.plot(-g * 100, -F / 1e3, "k--", lw=0.8)
    ax.set_xlabel("shear strain gamma_xy = 2 e_xy [%]")
    ax.set_ylabel("shear stress tau_xy [kPa]")
    ax.set_title(f"{name}: region {region['region']} ({region['backbone']})")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def plot_curves(path, region, cycles):
    g = np.logspace(-6, -1, 200)
    kind = region["backbone"]
    ratio_model = model_modulus_ratio(region, g)
    damp_model = masing_damping(lambda x: model_modulus_ratio(region, x), g)
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.5))
    a1.semilogx(g * 100, ratio_model, label="backbone as run (Masing model)")
    a2.semilogx(g * 100, damp_model * 100, label="Masing damping of the backbone as run")
    if kind == "darendeli":
        args = (region["plasticity_index"], region["ocr"], region["mean_effective_stress_pa"])
        a1.semilogx(g * 100, darendeli_modulus_ratio(g, *args), "k--", label="Darendeli (2001)")
        a2.semilogx(g * 100, darendeli_damping(g, *args, region["frequency_hz"], region["cycles"]) * 100, "k--", label="Darendeli (2001): D")
    else:
        label = {"mkz": "MKZ (Matasovic and Vucetic 1993)", "gqh": "GQ/H (Groholski et al. 2016)"}.get(kind, "user table")
        a1.semilogx(g * 100, published_modulus_ratio(region, g), "k--", label=label)
        a2.semilogx(g * 100, masing_damping(lambda x: published_modulus_ratio(region, x), g) * 100, "k--", label=label + ", Masing")
    for name, c in cycles.items():
        if len(c):
            a1.semilogx(c[:, 0] * 100, c[:, 1], "o", ms=3, label=f"station {name} cycles")
            a2.semilogx(c[:, 0] * 100, c[:, 2] * 100, "o", ms=3, label=f"station {name} cycles")
    a1.set_ylabel("G/Gmax [-]")
    a2.set_ylabel("damping ratio [%]")
    for a in (a1, a2):
        a.set_xlabel("shear strain amplitude [%]")
        a.grid(alpha=0.3, which="both")
        a.legend(fontsize=8)
    fig.suptitle(f"region {region['region']}: {kind}, Gmax {region['gmax_pa']:.4g} Pa, {region['surfaces']} surfaces")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("out", help="the run's -output_dir")
    p.add_argument("--out", dest="plots", help="folder for the PNGs (default OUT/plots)")
    p.add_argument("--region", help="the hysteretic region (default: the only one)")
    p.add_argument("--station", action="append", help="a station to plot (default: every station with stress columns)")
    a = p.parse_args()
    run = RunFolder(a.out)
    regions = run.run_info().get("hysteretic_regions", [])
    if not regions:
        print(f"{a.out}: no hysteretic region in run_info.json; allowed: a run with -material_<r>_model hysteretic")
        return 1
    if a.region is None and len(regions) > 1:
        print(f"--region is needed: the run has {len(regions)} hysteretic regions; allowed: {', '.join(r['region'] for r in regions)}")
        return 1
    chosen = [r for r in regions if a.region in (None, r["region"])]
    if not chosen:
        print(f"--region {a.region}: not a hysteretic region of the run; allowed: {', '.join(r['region'] for r in regions)}")
        return 1
    region = chosen[0]
    names = a.station or [n for n in run.station_names() if "s_xy" in run.station(n)]
    if not names:
        print(f"{a.out}: no station with stress columns; allowed: a run with -station_stress true")
        return 1
    plots = a.plots or os.path.join(a.out, "plots")
    os.makedirs(plots, exist_ok=True)
    written, cycles = [], {}
    for name in names:
        d = run.station(name)
        gamma, tau = 2 * d["e_xy"], d["s_xy"]
        path = os.path.join(plots, f"soil_loops_{name}.png")
        plot_loops(path, name, gamma, tau, region)
        written.append(path)
        cycles[name] = station_cycles(gamma, tau, region["gmax_pa"])
    path = os.path.join(plots, f"soil_curves_{region['region']}.png")
    plot_curves(path, region, cycles)
    written.append(path)
    print("\n".join(written))
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Foundation impedance from a forced-vibration run: K(w) = K1(w) + i w C(w) = P(w) / R(w).

P(t) is the load slipwave applied (-structure_load_force or _moment times its factor
history, rebuilt here from the same parameters: Ricker, harmonic or a CSV time,factor), R(t)
the foundation's response from its stations:
    vertical    u_y of --station        (P: the vertical force)
    horizontal  u_x of --station        (P: the horizontal force)
    rocking     (u_y(right) - u_y(left)) / (x_right - x_left) of --stations left,right
                (P: the moment)
Both are Fourier-transformed on the run's samples (zero-padded to --pad times the length);
the ratio is kept where the load's spectrum exceeds --min-spectrum of its peak. With
--k-ref K_ref (a static stiffness) and --half-width B and --vs vs the script also gives the
dimensionless coefficients of K = K_ref (k(a0) + i a0 c(a0)), a0 = w B / vs (Gazetas 1991).
With --inertia (the foundation's mass, or its moment of inertia for rocking) its own
inertia is taken out, K = P/R + inertia w^2: the soil's impedance under a massless footing.
Writes <out>/impedance.csv (f, a0, K1, wC, C[, k, c]) and <out>/impedance.png (matplotlib,
Agg).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from slipwave import RunFolder  # noqa: E402


def ricker(t, f0, t0):
    a = (np.pi * f0 * (t - t0)) ** 2
    return (1 - 2 * a) * np.exp(-a)


def load_history(t, args):
    if args.stf == "ricker":
        s = ricker(t, args.f0, args.t0 if args.t0 is not None else 1.2 / args.f0)
    elif args.stf == "harmonic":
        t0 = args.t0 or 0.0
        s = np.where(t < t0, 0.0, np.sin(2 * np.pi * args.f0 * (t - t0)))
    else:
        d = np.genfromtxt(args.stf_csv, delimiter=",", skip_header=1)
        s = np.interp(t, d[:, 0], d[:, 1], left=0.0, right=d[-1, 1])
    return args.amplitude * s


def response(args):
    """Times, the response R(t) and the coordinates used."""
    if args.mode == "rocking":
        left, right = args.stations.split(",")
        run = RunFolder(args.run)
        a, b = run.station(left), run.station(right)
        if args.x_left is None or args.x_right is None:
            sys.exit("foundation_impedance: rocking needs --x-left and --x-right (the stations' x)")
        return a["t"], (b["u_y"] - a["u_y"]) / (args.x_right - args.x_left)
    d = RunFolder(args.run).station(args.station)
    return d["t"], d["u_y" if args.mode == "vertical" else "u_x"]


def impedance(t, p, r, pad, min_spectrum):
    """Frequencies [Hz] and K = P/R where |P| >= min_spectrum max|P| (uniform t)."""
    dt = t[1] - t[0]
    n = pad * len(t)
    P, R = np.fft.rfft(p, n), np.fft.rfft(r, n)
    f = np.fft.rfftfreq(n, dt)
    keep = (np.abs(P) >= min_spectrum * np.abs(P).max()) & (f > 0)
    return f[keep], P[keep] / R[keep]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run", help="slipwave output directory (with stations/)")
    ap.add_argument("--mode", choices=["vertical", "horizontal", "rocking"], required=True)
    ap.add_argument("--station", help="station on the foundation (vertical, horizontal)")
    ap.add_argument("--stations", help="left,right stations on the foundation's base (rocking)")
    ap.add_argument("--x-left", type=float, help="x of the left station [m] (rocking)")
    ap.add_argument("--x-right", type=float, help="x of the right station [m] (rocking)")
    ap.add_argument("--amplitude", type=float, required=True, help="force [N, N/m in 2D] or moment [N m, N m/m] of the load")
    ap.add_argument("--stf", choices=["ricker", "harmonic", "csv"], default="ricker", help="the load's factor history, as -structure_load_stf")
    ap.add_argument("--stf-csv", help="time,factor CSV (--stf csv)")
    ap.add_argument("--f0", type=float, default=2.0, help="-structure_load_f0 [Hz]")
    ap.add_argument("--t0", type=float, help="-structure_load_t0 [s] (default: 1.2/f0 for ricker, 0 for harmonic)")
    ap.add_argument("--inertia", type=float, default=0.0, help="foundation mass [kg, kg/m] or moment of inertia [kg m^2, kg m^2/m] to take out")
    ap.add_argument("--pad", type=int, default=4, help="zero padding factor of the FFT")
    ap.add_argument("--min-spectrum", type=float, default=0.05, help="keep frequencies where |P| >= this fraction of its peak")
    ap.add_argument("--half-width", type=float, help="B [m], for a0 = w B / vs")
    ap.add_argument("--vs", type=float, help="soil S-wave speed [m/s], for a0")
    ap.add_argument("--k-ref", type=float, help="static stiffness for k(a0), c(a0)")
    ap.add_argument("--out", help="output directory (default: the run directory)")
    args = ap.parse_args(argv)
    t, r = response(args)
    p = load_history(t, args)
    f, K = impedance(t, p, r, args.pad, args.min_spectrum)
    w = 2 * np.pi * f
    K = K + args.inertia * w * w
    cols = [f, np.full_like(f, np.nan), K.real, K.imag, K.imag / w]
    names = ["f", "a0", "K1", "wC", "C"]
    if args.half_width and args.vs:
        cols[1] = w * args.half_width / args.vs
    if args.k_ref:
        cols += [K.real / args.k_ref, K.imag / (cols[1] * args.k_ref)]
        names += ["k", "c"]
    out = args.out or args.run
    os.makedirs(out, exist_ok=True)
    np.savetxt(os.path.join(out, "impedance.csv"), np.column_stack(cols), delimiter=",", header=",".join(names), comments="")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    x, xlabel = (cols[1], "a0 = w B / vs") if args.half_width and args.vs else (f, "f [Hz]")
    fig, ax = plt.subplots(2, 1, sharex=True, figsize=(6, 6))
    if args.k_ref:
        ax[0].plot(x, cols[5]), ax[0].set_ylabel("k = K1 / K_ref")
        ax[1].plot(x, cols[6]), ax[1].set_ylabel("c = wC / (a0 K_ref)")
    else:
        ax[0].plot(x, K.real), ax[0].set_ylabel("K1")
        ax[1].plot(x, K.imag / w), ax[1].set_ylabel("C")
    ax[1].set_xlabel(xlabel)
    ax[0].set_title(f"{args.mode} impedance")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "impedance.png"), dpi=100)
    print(f"foundation_impedance: {args.mode}, {len(f)} frequencies {f[0]:.3g}-{f[-1]:.3g} Hz -> {out}/impedance.csv, impedance.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())

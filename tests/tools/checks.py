#!/usr/bin/python3
"""Checks of slipwave output against closed-form physics, used by tests/cases/*.sh.

Each subcommand prints what it measured and exits 1 when a bound is violated.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from slipwave import RunFolder, read_csv  # noqa: E402


def ricker_velocity(t, amplitude, f0, t0):
    a = (math.pi * f0 * (t - t0)) ** 2
    return amplitude * (1 - 2 * a) * np.exp(-a)


def column(args):
    """Vertically incident plane wave in a 1D column on an absorbing base: the free surface
    doubles the incident velocity and delays it by the travel time, v_s(t) = 2 v_in(t - H/c)
    (reflection at a traction-free surface, e.g. Kramer, Geotechnical Earthquake Engineering,
    sec. 5.2). After the surface reflection leaves through the base nothing should return:
    any late motion at the surface is a spurious reflection of the absorbing boundary."""
    d = read_csv(args.station)
    t = d["t"]
    v = d["v_" + args.component]
    ref = 2 * ricker_velocity(t - args.height / args.speed, args.amplitude, args.f0, args.t0)
    window = t <= args.t_end if args.t_end is not None else np.ones_like(t, dtype=bool)
    l2 = math.sqrt(np.sum((v - ref)[window] ** 2) / np.sum(ref[window] ** 2))
    peak = np.max(np.abs(ref))
    # The surface reflection reaches the base at t0 + 2H/c; a reflection there would be back
    # at the surface from t0 + 3H/c on, minus the half-width of the wavelet (1.5/f0 holds
    # all but 1e-6 of a Ricker pulse's envelope exp(-(pi f0 t)^2)). What is measured there is
    # the departure from the closed form: where 2H/c < 3/f0 (the P column: 0.5 s < 0.6 s) the
    # window still holds the tail of the surface pulse itself (1e-3 of its peak at 0.2 s
    # from its centre), which is no reflection.
    late = t > args.t0 + 3 * args.height / args.speed - 1.5 / args.f0
    late_max = np.max(np.abs((v - ref)[late])) if np.any(late) else 0.0
    print(f"column: L2 error {l2:.4e} (bound {args.l2_max:.1e}); late motion {late_max / peak:.2e} of peak (bound {args.late_max:.1e}), "
          f"{np.count_nonzero(late)} late samples")
    ok = l2 <= args.l2_max and (args.late_max <= 0 or (np.any(late) and late_max <= args.late_max * peak))
    return 0 if ok else 1


def column_error(args):
    d = read_csv(args.station)
    t = d["t"]
    v = d["v_" + args.component]
    ref = 2 * ricker_velocity(t - args.height / args.speed, args.amplitude, args.f0, args.t0)
    print(f"{math.sqrt(np.sum((v - ref) ** 2) / np.sum(ref ** 2)):.10e}")
    return 0


def energy(args):
    d = read_csv(args.csv)
    err = np.max(np.abs(d["relative_balance_error"]))
    print(f"energy: max relative balance error {err:.3e} over {len(d)} rows (bound {args.max_error:.1e})")
    ok = err <= args.max_error and len(d) >= args.min_rows
    if args.input_work is not None:
        got = d["input_work"][-1]
        rel = abs(got - args.input_work) / abs(args.input_work)
        print(f"energy: input work {got:.6e} J, expected {args.input_work:.6e} J, relative difference {rel:.3e} (bound {args.input_tol:.1e})")
        ok = ok and rel <= args.input_tol
    if args.final_fraction is not None:
        stored = d["kinetic"][-1] + d["strain"][-1]
        frac = stored / max(np.max(d["kinetic"] + d["strain"]), 1e-300)
        print(f"energy: energy left at the end {frac:.3e} of the peak (bound {args.final_fraction:.1e})")
        ok = ok and frac <= args.final_fraction
    return 0 if ok else 1


def stations_equal(args):
    worst, worst_a = 0.0, 0.0
    tol_a = args.tol if args.tol_a is None else args.tol_a
    for name in args.names.split(","):
        a = RunFolder(args.dir_a).station(name)
        b = RunFolder(args.dir_b).station(name)
        if len(a) != len(b):
            print(f"stations: {name}: {len(a)} rows vs {len(b)}")
            return 1
        # Each quantity (u, v, a) is scaled by its peak over all components: a component that
        # is zero up to round-off (u_y of a vertically incident SV wave) has no scale of its own.
        # p: the pore pressure column of saturated scenes; s, e: the stress and strain of
        # -station_stress; absent elsewhere.
        for q in ("t", "u", "v", "a", "p", "s", "e"):
            cols = [c for c in a.names if c == q or c.startswith(q + "_")]
            if not cols:
                continue
            scale = max(max(np.max(np.abs(a[c])) for c in cols), 1e-300)
            for c in cols:
                diff = np.max(np.abs(a[c] - b[c])) / scale
                if q == "a":
                    worst_a = max(worst_a, diff)
                else:
                    worst = max(worst, diff)
    print(f"stations: largest difference {worst:.3e} of each quantity's peak for t, u, v, p, s, e (bound {args.tol:.1e}), {worst_a:.3e} for a (bound {tol_a:.1e})")
    return 0 if worst <= args.tol and worst_a <= tol_a else 1


def energy_equal(args):
    """Two runs' energy ledgers (energy.csv) row by row: every energy column scaled by the
    largest energy either run stored or booked (the balance-error columns, round-off by
    themselves, are left out). energy.csv holds 10 significant digits (src/app/energy_csv.cpp),
    so two values equal to round-off may print one unit of the 10th digit apart: up to 1e-9 of
    the value. That unit is allowed on top of the bound and the rest is reported."""
    a, b = read_csv(args.csv_a), read_csv(args.csv_b)
    if len(a) != len(b):
        print(f"energy: {len(a)} rows vs {len(b)}")
        return 1
    cols = [c for c in a.names if c not in ("step", "time", "balance_error", "relative_balance_error")]
    scale = max(max(np.max(np.abs(a[c])) for c in cols), 1e-300)
    worst = max(np.max(np.abs(a[c] - b[c]) - 1e-9 * np.maximum(np.abs(a[c]), np.abs(b[c]))) for c in cols) / scale
    raw = max(np.max(np.abs(a[c] - b[c])) for c in cols) / scale
    steps = np.max(np.abs(a["step"] - b["step"]))
    print(f"energy: largest difference {raw:.3e} of the largest energy {scale:.4e} J ({max(worst, 0):.3e} beyond the printed digits) "
          f"over {len(cols)} columns, {len(a)} rows (bound {args.tol:.1e})")
    return 0 if worst <= args.tol and steps == 0 else 1


def main():
    p = argparse.ArgumentParser(description=__doc__)
    sub = p.add_subparsers(dest="cmd", required=True)
    for name in ("column", "column-error"):
        c = sub.add_parser(name)
        c.add_argument("station")
        c.add_argument("--component", default="x")
        c.add_argument("--height", type=float, required=True)
        c.add_argument("--speed", type=float, required=True)
        c.add_argument("--amplitude", type=float, required=True)
        c.add_argument("--f0", type=float, required=True)
        c.add_argument("--t0", type=float, required=True)
        c.add_argument("--l2-max", type=float, default=0.015)
        c.add_argument("--late-max", type=float, default=1e-3)
        c.add_argument("--t-end", type=float, help="compare only up to this time [s]")
    e = sub.add_parser("energy")
    e.add_argument("csv")
    e.add_argument("--max-error", type=float, required=True)
    e.add_argument("--min-rows", type=int, default=2)
    e.add_argument("--input-work", type=float)
    e.add_argument("--input-tol", type=float, default=0.01)
    e.add_argument("--final-fraction", type=float)
    s = sub.add_parser("stations-equal")
    s.add_argument("dir_a")
    s.add_argument("dir_b")
    s.add_argument("--names", required=True)
    s.add_argument("--tol", type=float, required=True)
    s.add_argument("--tol-a", type=float, help="bound for the accelerations (default: --tol)")
    q = sub.add_parser("energy-equal")
    q.add_argument("csv_a")
    q.add_argument("csv_b")
    q.add_argument("--tol", type=float, required=True)
    args = p.parse_args()
    return {"column": column, "column-error": column_error, "energy": energy, "stations-equal": stations_equal, "energy-equal": energy_equal}[args.cmd](args)


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Closed-form checks of the Mohr-Coulomb interface in whole runs, used by
tests/cases/interface_newmark_block.sh, interface_incline_block.sh and interface_tied.sh.

Each subcommand prints what it measured and exits 1 when a bound is violated.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from slipwave import RunFolder, read_csv  # noqa: E402


def newmark(args):
    """Newmark (1965) rigid block on a base shaken by a rectangular acceleration pulse
    A g over t_p: the block slides with relative acceleration (A - N) g during the pulse and
    -N g after it, until the relative velocity is zero again; the permanent slip is
    V^2/(2 g N) (1 - N/A), V = A g t_p."""
    g, A, N, tp = args.g, args.A, args.N, args.tp
    V = A * g * tp
    expected = V * V / (2 * g * N) * (1 - N / A)
    ok = True
    slip = RunFolder(args.out_dir).interface(args.interface).field("accumulated_slip", -1).ravel()
    rel = np.abs(slip - expected) / expected
    print(f"newmark: expected permanent slip {expected:.6e} m; interface accumulated_slip {slip.min():.6e}..{slip.max():.6e} m, "
          f"largest relative error {rel.max():.3e} (bound {args.tol:.1e})")
    ok &= bool(rel.max() <= args.tol)
    b, m = read_csv(args.base), read_csv(args.block)
    late = b["t"] >= args.t_settled
    du = np.mean(b["u_x"][late] - m["u_x"][late])
    rel_st = abs(du - expected) / expected
    print(f"newmark: stations base - block displacement after t = {args.t_settled} s: {du:.6e} m, relative error {rel_st:.3e} (bound {args.tol:.1e})")
    ok &= rel_st <= args.tol
    # Sliding ends at t = V/(N g): afterwards the block moves with the base.
    dv = np.max(np.abs(b["v_x"][late] - m["v_x"][late]))
    print(f"newmark: largest base - block velocity after t = {args.t_settled} s: {dv:.3e} m/s ({dv / V:.2e} of V, bound {args.stuck_tol:.1e})")
    ok &= dv <= args.stuck_tol * V
    if args.energy:
        e = read_csv(args.energy)
        diss = e["interface_dissipated"][-1]
        want = N * args.sigma_n * args.area * float(np.mean(slip))
        rel_d = abs(diss - want) / want
        print(f"newmark: interface dissipated {diss:.6e} J, friction x slip N |sigma_N| A slip = {want:.6e} J, relative difference {rel_d:.2e} (bound 1e-3)")
        ok &= rel_d <= 1e-3
    return 0 if ok else 1


def incline(args):
    """Block sliding down an incline: a = g (sin b - tan phi cos b) - c A/m. The station
    velocity of the block is fitted by a straight line over [t1, t2] (least squares); the
    block's elastic ringing is averaged out by the fit."""
    b = math.radians(args.beta)
    expected = args.g * (math.sin(b) - math.tan(math.radians(args.phi)) * math.cos(b)) - args.c * args.area / args.mass
    d = read_csv(args.station)
    t, v = d["t"], d["v_" + args.component]
    w = (t >= args.t1) & (t <= args.t2)
    slope, _ = np.polyfit(t[w], v[w], 1)
    rel = abs(slope - expected) / abs(expected)
    print(f"incline: beta {args.beta} deg, phi {args.phi} deg, c {args.c} Pa: expected a = {expected:.6e} m/s^2, fitted {slope:.6e} m/s^2 "
          f"over [{args.t1}, {args.t2}] s ({np.count_nonzero(w)} samples), relative error {rel:.3e} (bound {args.tol:.1e})")
    return 0 if rel <= args.tol else 1


def tied(args):
    """A tied interface is a spring layer of stiffness K (Pa/m) between equal media of
    impedance Z = rho vs: for a plane wave of angular frequency w the transmission is
    T = 1 / (1 + i w Z / (2K)), so |1 - T| <= w Z / (2K). The station records with and without
    the interface may differ by at most that at the top frequency of the input spectrum,
    times the safety factor given."""
    worst_all = []
    ok = True
    for K, dir_if in zip(args.K, args.dirs_if):
        bound = args.safety * args.omega * args.Z / (2 * K)
        worst = 0.0
        for name in args.names.split(","):
            a = RunFolder(args.dir_ref).station(name)
            c = RunFolder(dir_if).station(name)
            if len(a) != len(c):
                print(f"tied: {name}: {len(a)} rows vs {len(c)}")
                return 1
            for q in args.quantities.split(","):
                worst = max(worst, np.max(np.abs(a[q] - c[q])) / np.max(np.abs(a[q])))
        print(f"tied: K = {K:.3e} Pa/m: largest station difference {worst:.3e} of the peak; "
              f"bound {args.safety} x w Z/(2K) = {bound:.3e}")
        ok &= worst <= bound
        worst_all.append(worst)
    if len(worst_all) == 2:
        ratio = worst_all[0] / worst_all[1]
        kr = args.K[1] / args.K[0]
        print(f"tied: error ratio {ratio:.3f} for a penalty ratio {kr:.3f} (first order in 1/K: expected {kr:.3f}, "
              f"allowed [{args.ratio_min * kr:.3f}, {args.ratio_max * kr:.3f}])")
        ok &= args.ratio_min * kr <= ratio <= args.ratio_max * kr
    return 0 if ok else 1


def main():
    p = argparse.ArgumentParser(description=__doc__)
    sub = p.add_subparsers(dest="cmd", required=True)
    n = sub.add_parser("newmark")
    n.add_argument("--out-dir", required=True, help="output folder holding interface_NAME.xmf")
    n.add_argument("--interface", required=True, help="interface NAME")
    n.add_argument("--base", required=True, help="station CSV on the base")
    n.add_argument("--block", required=True, help="station CSV in the block")
    n.add_argument("--energy")
    n.add_argument("--g", type=float, default=9.81)
    n.add_argument("--A", type=float, required=True, help="pulse amplitude in g")
    n.add_argument("--N", type=float, required=True, help="tan(phi)")
    n.add_argument("--tp", type=float, required=True)
    n.add_argument("--sigma-n", type=float, default=0.0, help="|sigma_N| [Pa] for the dissipation check")
    n.add_argument("--area", type=float, default=1.0)
    n.add_argument("--t-settled", type=float, required=True)
    n.add_argument("--tol", type=float, required=True)
    n.add_argument("--stuck-tol", type=float, default=1e-2)
    i = sub.add_parser("incline")
    i.add_argument("station")
    i.add_argument("--component", default="x")
    i.add_argument("--g", type=float, default=9.81)
    i.add_argument("--beta", type=float, required=True)
    i.add_argument("--phi", type=float, required=True)
    i.add_argument("--c", type=float, default=0.0)
    i.add_argument("--area", type=float, default=1.0)
    i.add_argument("--mass", type=float, default=1.0)
    i.add_argument("--t1", type=float, required=True)
    i.add_argument("--t2", type=float, required=True)
    i.add_argument("--tol", type=float, required=True)
    t = sub.add_parser("tied")
    t.add_argument("dir_ref")
    t.add_argument("--dirs-if", nargs="+", required=True)
    t.add_argument("--K", type=float, nargs="+", required=True)
    t.add_argument("--names", required=True)
    t.add_argument("--quantities", default="u_x,v_x")
    t.add_argument("--omega", type=float, required=True)
    t.add_argument("--Z", type=float, required=True)
    t.add_argument("--safety", type=float, default=1.0)
    t.add_argument("--ratio-min", type=float, default=0.8)
    t.add_argument("--ratio-max", type=float, default=1.25)
    args = p.parse_args()
    return {"newmark": newmark, "incline": incline, "tied": tied}[args.cmd](args)


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Checks of slipwave's contact-interface output, used by tests/cases/interface_{bar_impact,lift_drop,hard_cases,mpi}.sh.

Reads the interface frames of output_dir (through interface_NAME.xmf), energy.csv and the station
CSVs. Each subcommand prints what it measured and exits 1 when a bound is violated.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from slipwave import RunFolder  # noqa: E402


def interface_frames(out_dir, name, field):
    """Frame times and values [frame, pair id, component] of one interface field, in the
    order of the XDMF temporal collection."""
    frames = RunFolder(out_dir).interface(name)
    return np.array(frames.times), frames.stacked([field])[field]


def stored_total(d):
    """Mechanical energy held or spent by the model: kinetic + strain + interface stored +
    interface dissipated + contact dashpots + absorbed + damped + anelastic, minus what the
    loads put in (input and external work). For a closed model without loads this is the brief's
    kinetic + strain + interface terms; its growth above the energy at t = 0 is energy the scheme
    created."""
    return (d["kinetic"] + d["strain"] + d["interface_stored"] + d["interface_dissipated"] + d["contact_damped"] + d["absorbed"] + d["damped"]
            + d["anelastic"] - d["input_work"] - d["external_work"])


def energy_growth(args):
    d = RunFolder(args.dir).energy()
    tot = stored_total(d)
    ref = args.reference if args.reference is not None else tot[0]
    growth = np.max(tot) / ref - 1
    bal = np.max(np.abs(d["relative_balance_error"]))
    print(f"energy: largest growth of kinetic+strain+interface stored+dissipated (net of loads) {growth:+.3e} of {ref:.6e} J "
          f"(bound {args.max_growth:.1e}); balance error {bal:.2e} of the largest energy (bound {args.max_balance:.1e}); {len(d)} rows")
    peak_stored, dissipated = np.max(d["interface_stored"]), d["interface_dissipated"][-1]
    print(f"energy: interface held at most {peak_stored:.4e} J (need > {args.min_stored:g}), dissipated {dissipated:.4e} J (need >= {args.min_dissipated:g})")
    ok = growth <= args.max_growth and bal <= args.max_balance and len(d) >= 2
    return 0 if ok and peak_stored > args.min_stored and dissipated >= args.min_dissipated else 1


def bar_contact(args):
    """Contact phase of a bar impact. Duration from energy.csv (every step): in contact
    exactly when the interface stores energy (a frictionless pair in compression holds
    A sigma_N^2 / 2E; an open one holds 0); first to last step in contact, plus one step
    (the rows sample the step ends). The contact stress from the interface output: the mean
    sigma_N over the middle of the contact phase (the plateau of a 1D impact; central
    differences ring behind a step front, so the mean, not the peak, is compared)."""
    d = RunFolder(args.dir).energy()
    te, stored = d["time"], d["interface_stored"]
    contact = np.nonzero(stored > 0)[0]
    if len(contact) == 0:
        print("contact: the bars never touched")
        return 1
    dt = te[1] - te[0]
    first, last = contact[0], contact[-1]
    sep = first + np.argmax(stored[first:] <= 0)  # first row after the contact with the pair open again
    if stored[sep] > 0:
        print("contact: the bars never separated")
        return 1
    # Contact starts within the step before the first row in contact and ends within the step
    # before the first open row: the duration is sep - first steps.
    t_on, t_off = te[first] - dt, te[sep] - dt
    duration = t_off - t_on
    recontact = np.count_nonzero(np.diff((stored[sep:] > 0).astype(int)) == 1)
    # sigma_N of the interface output, checked against the ledger at every frame: the pairs
    # of a one-cell-high bar share the area equally (A / n each), so stored = sum A/n sigma^2 / 2E.
    t, s = interface_frames(args.dir, args.name, "sigma_N")
    s = s[:, :, 0]
    row = np.array([np.argmin(np.abs(te - x)) for x in t])  # energy.csv keeps 10 digits of the time
    ledger = stored[row]
    from_h5 = np.sum(s ** 2, axis=1) * args.area / s.shape[1] / (2 * args.E)
    mismatch = np.max(np.abs(from_h5 - ledger)) / np.max(ledger)
    # Every step: the compression |sigma_N| = sqrt(2 E stored / A); its mean over the middle
    # of the contact phase (central differences ring behind a step front at a frequency the
    # output frames alias, so the mean of every step is compared, not the peak).
    sig = np.sqrt(2 * args.E * stored / args.area)
    mid = (te >= t_on + args.plateau_skip * duration) & (te <= t_off - args.plateau_skip * duration)
    plateau = np.mean(sig[mid])
    ripple = np.max(np.abs(sig[mid] - plateau)) / plateau
    after = t > te[last] + dt
    tail = np.max(np.abs(s[after]), initial=0.0)
    dur_err = abs(duration - args.duration) / args.duration
    st_err = abs(plateau - args.stress) / args.stress
    print(f"contact: from t = {t_on:.6e} to {t_off:.6e} s (dt {dt:.3e} s), duration {duration:.6e} s, expected {args.duration:.6e} s, "
          f"relative difference {dur_err:.3e} (bound {args.duration_tol:.1e}); "
          f"then {recontact} brief re-contact(s) (ringing of the discrete unloading front), the last one ending at {te[last]:.6e} s")
    print(f"contact: plateau compression {plateau:.6e} Pa (mean of {np.count_nonzero(mid)} steps over the middle {1 - 2 * args.plateau_skip:.0%}), "
          f"expected {args.stress:.6e} Pa, relative difference {st_err:.3e} (bound {args.stress_tol:.1e}); ripple {ripple:.2e} of it; "
          f"largest |sigma_N| after separation {tail:.3e} Pa (must be 0); "
          f"sigma_N of the {len(t)} output frames against the ledger's stored energy: {mismatch:.2e} (bound 1e-9)")
    ok = dur_err <= args.duration_tol and st_err <= args.stress_tol and tail == 0.0 and mismatch <= 1e-9 and te[last] - t_off <= args.duration_tol * args.duration
    return 0 if ok else 1


def station_window(args):
    """Mean and spread of a station column over a time window, against an expected value."""
    d = RunFolder(args.dir).station(args.station)
    w = (d["t"] >= args.t0) & (d["t"] <= args.t1)
    x = d[args.column][w]
    mean = np.mean(x)
    err = abs(mean - args.expected)
    spread = np.max(np.abs(x - mean))
    print(f"station {args.station} {args.column} over [{args.t0:.4g}, {args.t1:.4g}] s ({np.count_nonzero(w)} samples): mean {mean:.6e}, "
          f"expected {args.expected:.6e}, difference {err:.3e} (bound {args.tol:.1e}); spread {spread:.3e}")
    return 0 if err <= args.tol and np.count_nonzero(w) > 0 else 1


def open_traction(args):
    """While a pair is open (status 2) its traction must be exactly zero."""
    _, st = interface_frames(args.dir, args.name, "status")
    _, sN = interface_frames(args.dir, args.name, "sigma_N")
    _, sT = interface_frames(args.dir, args.name, "sigma_T")
    is_open = st[:, :, 0] == 2
    n_open = np.count_nonzero(is_open)
    worst = max(np.max(np.abs(sN[:, :, 0][is_open]), initial=0.0), np.max(np.abs(sT[is_open]), initial=0.0))
    print(f"open pairs: {n_open} pair-frames open (need >= {args.min_open}); largest |traction| while open {worst:.3e} Pa (must be 0)")
    return 0 if n_open >= args.min_open and worst == 0.0 else 1


def lift_drop(args):
    """Block launched upward from its base: flight (interface open, nothing stored), landing
    after 2 v0/g, interpenetration below the penalty's dynamic estimate. Per step from
    energy.csv: interface_stored = 1/2 E A u^2 for a uniform penetration u over the contact
    area A (the normal spring's energy; 0 while open), so u = sqrt(2 stored / (E A))."""
    d = RunFolder(args.dir).energy()
    t, stored = d["time"], d["interface_stored"]
    dt = t[1] - t[0]
    touching = stored > 0
    first_open = np.argmax(~touching)
    if touching[first_open]:
        print("lift-drop: the interface never opened")
        return 1
    land = first_open + np.argmax(touching[first_open:])
    if not touching[land]:
        print("lift-drop: the block never landed")
        return 1
    flight = t[land]
    err = abs(flight - args.flight)
    # Work of the interface constant during the flight: no force while open.
    w = d["interface_work"][first_open:land]
    print(f"lift-drop: opens at step {first_open} (t = {t[first_open]:.4e} s), lands at t = {flight:.6e} s; ballistic 2 v0/g = {args.flight:.6e} s, "
          f"difference {err:.3e} s (bound {args.flight_tol:.3e} s); interface work varies by {np.ptp(w):.3e} J in flight (must be 0), stored max {np.max(stored[first_open:land]):.3e} J (must be 0)")
    pen = np.sqrt(2 * np.max(stored[land:]) / (args.E * args.area))
    print(f"lift-drop: largest interpenetration after landing {pen:.6e} m; penalty estimate v0 sqrt(m/k) + m g/k = {args.penetration_max:.6e} m "
          f"(ratio {pen / args.penetration_max:.3f}, must be <= 1)")
    ok = err <= args.flight_tol and np.ptp(w) == 0.0 and np.max(stored[first_open:land]) == 0.0 and pen <= args.penetration_max
    return 0 if ok else 1


def decay(args):
    """Free decay of a damped oscillation about zero at a station: the largest value of one
    column in each window of one expected period (the cycle's peak, whatever faster ringing
    rides on it), from the first window on. The damping ratio from the mean logarithmic
    decrement over the peaks, delta = ln(p_0 / p_N) / N, zeta = delta / sqrt(4 pi^2 + delta^2),
    and the damped period from the peak spacing; each against the expected value."""
    d = RunFolder(args.dir).station(args.station)
    t, x = d["t"], d[args.column]
    peaks = []
    for w in range(int(t[-1] / args.period)):
        idx = np.nonzero((t >= w * args.period) & (t < (w + 1) * args.period))[0]
        peaks.append(idx[np.argmax(x[idx])])
    k = np.array(peaks)
    if len(k) < 3 or np.any(x[k] <= 0):
        print(f"decay: {len(k)} cycles, peaks {x[k]} (need >= 3, all > 0)")
        return 1
    n = len(k) - 1
    delta = np.log(x[k[0]] / x[k[-1]]) / n
    zeta = delta / np.sqrt(4 * np.pi ** 2 + delta ** 2)
    period = (t[k[-1]] - t[k[0]]) / n
    z_err = abs(zeta - args.zeta)
    p_err = abs(period - args.period) / args.period
    print(f"decay: {len(k)} cycles of {args.column} at {args.station}, peaks {x[k[0]]:.4e} .. {x[k[-1]]:.4e}; damping ratio {zeta:.6f}, expected {args.zeta:.6f}, "
          f"difference {z_err:.2e} (bound {args.zeta_tol:.1e}); damped period {period:.6e} s, expected {args.period:.6e} s, relative difference {p_err:.2e} "
          f"(bound {args.period_tol:.1e})")
    return 0 if z_err <= args.zeta_tol and p_err <= args.period_tol else 1


def interface_equal(args):
    """Interface fields of two runs (1 and 2 ranks) compared per pair id at every frame,
    each field scaled by its peak over the run."""
    worst, ok = 0.0, True
    for field in args.fields.split(","):
        ta, a = interface_frames(args.dir_a, args.name, field)
        tb, b = interface_frames(args.dir_b, args.name, field)
        if a.shape != b.shape or np.max(np.abs(ta - tb)) > 1e-12 * max(np.max(np.abs(ta)), 1e-300):
            print(f"interface {field}: shapes {a.shape} vs {b.shape} or frame times differ")
            return 1
        peak = max(np.max(np.abs(a)), 1e-300)
        diff = np.max(np.abs(a - b)) / peak
        worst = max(worst, diff)
        print(f"interface {field}: {a.shape[0]} frames x {a.shape[1]} pairs, peak {peak:.4e}, largest difference {diff:.3e} of the peak (bound {args.tol:.1e})")
        if args.min_peak is not None and field in args.min_peak_fields.split(","):
            print(f"interface {field}: peak {peak:.4e} (need >= {args.min_peak:g})")
            ok = ok and peak >= args.min_peak
    return 0 if worst <= args.tol and ok else 1


def main():
    p = argparse.ArgumentParser(description=__doc__)
    sub = p.add_subparsers(dest="cmd", required=True)
    e = sub.add_parser("energy-growth")
    e.add_argument("dir")
    e.add_argument("--max-growth", type=float, required=True)
    e.add_argument("--max-balance", type=float, required=True)
    e.add_argument("--min-stored", type=float, default=-1.0, help="the interface must have held more than this [J] (contact happened)")
    e.add_argument("--min-dissipated", type=float, default=-1.0, help="the interface must have dissipated at least this [J] (slip happened)")
    e.add_argument("--reference", type=float, help="energy to compare with (default: the total at t = 0)")
    c = sub.add_parser("bar-contact")
    c.add_argument("dir")
    c.add_argument("--name", required=True)
    c.add_argument("--duration", type=float, required=True)
    c.add_argument("--duration-tol", type=float, required=True)
    c.add_argument("--stress", type=float, required=True)
    c.add_argument("--stress-tol", type=float, required=True)
    c.add_argument("--plateau-skip", type=float, default=0.25)
    c.add_argument("--E", type=float, required=True, help="normal penalty stiffness [Pa/m]")
    c.add_argument("--area", type=float, required=True, help="contact area [m^2] (one-cell-high bar)")
    s = sub.add_parser("station-window")
    s.add_argument("dir")
    s.add_argument("--station", required=True)
    s.add_argument("--column", required=True)
    s.add_argument("--t0", type=float, required=True)
    s.add_argument("--t1", type=float, required=True)
    s.add_argument("--expected", type=float, required=True)
    s.add_argument("--tol", type=float, required=True)
    o = sub.add_parser("open-traction")
    o.add_argument("dir")
    o.add_argument("--name", required=True)
    o.add_argument("--min-open", type=int, default=1)
    l = sub.add_parser("lift-drop")
    l.add_argument("dir")
    l.add_argument("--flight", type=float, required=True)
    l.add_argument("--flight-tol", type=float, required=True)
    l.add_argument("--E", type=float, required=True)
    l.add_argument("--area", type=float, required=True)
    l.add_argument("--penetration-max", type=float, required=True)
    q = sub.add_parser("interface-equal")
    q.add_argument("dir_a")
    q.add_argument("dir_b")
    q.add_argument("--name", required=True)
    q.add_argument("--fields", required=True)
    q.add_argument("--tol", type=float, required=True)
    q.add_argument("--min-peak", type=float)
    q.add_argument("--min-peak-fields", default="")
    y = sub.add_parser("decay")
    y.add_argument("dir")
    y.add_argument("--station", required=True)
    y.add_argument("--column", required=True)
    y.add_argument("--zeta", type=float, required=True)
    y.add_argument("--zeta-tol", type=float, required=True)
    y.add_argument("--period", type=float, required=True)
    y.add_argument("--period-tol", type=float, required=True)
    args = p.parse_args()
    return {"energy-growth": energy_growth, "bar-contact": bar_contact, "station-window": station_window, "open-traction": open_traction,
            "lift-drop": lift_drop, "interface-equal": interface_equal, "decay": decay}[args.cmd](args)


if __name__ == "__main__":
    sys.exit(main())

"""What the 2D and 3D series of the speed-against-error benchmark share (bench/sem_speed_error.py,
bench/sem_speed_error_3d.py): the run report's time loop, the pooled error of station traces,
the time at a target error, and the results section of the markdown page. numpy only."""
import datetime
import math
import os
import re
import subprocess
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "python"))
from slipwave import read_csv  # noqa: E402

# The issue 25 goals: time to 1 % and to 0.1 % error.
TARGETS = (0.01, 0.001)


def ricker_rate(t, f0, t0):
    """d/dt of the Ricker (1 - 2a) exp(-a), a = (pi f0 (t - t0))^2: a load's rate, whose response
    is the velocity."""
    a = (np.pi * f0 * (t - t0)) ** 2
    return -2 * (np.pi * f0) ** 2 * (t - t0) * (3 - 2 * a) * np.exp(-a)


def parse_log(path):
    """(steps, time loop [s], nodes or None, integrator order) from a run's report."""
    text = open(path).read()
    m = re.search(r"done: (\d+) steps in ([0-9.]+) s wall \(([0-9.eE+-]+) s per step\)", text)
    steps, wall, per = int(m.group(1)), float(m.group(2)), float(m.group(3))
    # The time loop (TSSolve: the steps and their monitor, no set-up, no final output);
    # "s per step" carries 3 significant digits where "s wall" has 2 decimals.
    loop = max(wall, steps * per) if wall < 10 else wall
    nodes = re.search(r"cells, (\d+) nodes", text)
    order = re.search(r"\(-ts_cd_order (\d)", text)
    return steps, loop, int(nodes.group(1)) if nodes else None, int(order.group(1)) if order else 2


def pooled_error(stations_dir, names, components, reference_at, t_end):
    """Relative L2 error of station records against a reference: sqrt(sum |v - v_ref|^2 /
    sum |v_ref|^2) over the samples at t <= t_end of the components of all stations pooled, and
    the same per station. reference_at(i, component, t): the reference of station names[i]."""
    num = den = 0.0
    per_station = []
    for i, name in enumerate(names):
        d = read_csv(os.path.join(stations_dir, f"{name}.csv"))
        inside = d["t"] <= t_end + 1e-9
        e2 = r2 = 0.0
        for component in components:
            r = reference_at(i, component, d["t"][inside])
            e2 += np.sum((d[component][inside] - r) ** 2)
            r2 += np.sum(r ** 2)
        per_station.append(math.sqrt(e2 / r2))
        num += e2
        den += r2
    return math.sqrt(num / den), per_station


def at_target(points, target):
    """Time at the target error by log-log interpolation between the bracketing runs, or
    extrapolation from the two nearest ones (flagged). points: (error, time), any order."""
    pts = sorted(points, key=lambda q: -q[0])
    if len(pts) < 2:
        return None, ""
    for (e1, t1), (e2, t2) in zip(pts, pts[1:]):
        if e1 >= target >= e2:
            s = math.log(target / e1) / math.log(e2 / e1)
            return math.exp(math.log(t1) + s * math.log(t2 / t1)), "interpolated"
    (e1, t1), (e2, t2) = (pts[-2], pts[-1]) if pts[-1][0] > target else (pts[0], pts[1])
    if e2 >= e1 or t2 <= t1:
        return None, ""
    s = math.log(target / e1) / math.log(e2 / e1)
    return math.exp(math.log(t1) + s * math.log(t2 / t1)), "extrapolated"


def times_at_targets(runs):
    """Per series (p, mode) of runs (dicts with p, mode, err, loop): {target: (time, how)}."""
    keys = sorted({(r["p"], r["mode"]) for r in runs})
    return {key: {target: at_target([(r["err"], r["loop"]) for r in runs if (r["p"], r["mode"]) == key], target) for target in TARGETS}
            for key in keys}


def observed_orders(runs, size_key):
    """Sets r["observed"]: the order of the error in h against the previous run of the same series
    (runs sorted by series, then by size_key, the elements per unit length)."""
    for r in runs:
        prev = [q for q in runs if q["p"] == r["p"] and q["mode"] == r["mode"] and q[size_key] < r[size_key]]
        r["observed"] = math.log(prev[-1]["err"] / r["err"]) / math.log(r[size_key] / prev[-1][size_key]) if prev else None


def fmt(value, spec, missing="n/a"):
    return missing if value is None else format(value, spec)


def machine_state():
    """When, which commit, and how loaded the machine was, for a results section."""
    try:
        commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True, text=True).stdout.strip()
    except OSError:
        commit = "?"
    load = os.getloadavg()
    return (f"{datetime.datetime.utcnow():%Y-%m-%d %H:%M} UTC, commit {commit}, {os.cpu_count()} cores, load average "
            f"{load[0]:.1f} / {load[1]:.1f} / {load[2]:.1f} (1 / 5 / 15 min) when the analysis ran.")


def replace_section(doc, begin, end, section):
    """Puts section (which starts with begin and ends with end and a newline) in place of the one
    between these markers in doc, or at its end."""
    text = open(doc).read() if os.path.exists(doc) else ""
    if begin in text and end in text:
        text = text[:text.index(begin)] + section + text[text.index(end) + len(end) + 1:]
    else:
        text = text + ("\n" if text and not text.endswith("\n\n") else "") + section
    with open(doc, "w") as out:
        out.write(text)


def main(usage, geometry, plan, analyse):
    """The command line of a series' module: geometry, plan or analyse MANIFEST (usage otherwise)."""
    command = sys.argv[1] if len(sys.argv) > 1 else ""
    if command == "geometry":
        geometry()
    elif command == "plan":
        plan()
    elif command == "analyse" and len(sys.argv) == 3:
        analyse(sys.argv[2])
    else:
        sys.exit(usage)

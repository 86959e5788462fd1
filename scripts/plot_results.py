#!/usr/bin/python3
"""Plots the results of a slipwave run as PNG figures (matplotlib, no display needed).

usage: /usr/bin/python3 scripts/plot_results.py OUT [--out DIR] [--reference STATION] [--layer H,VS]

OUT is the -output_dir of a run. Figures go to OUT/plots/ (or DIR). Accelerations are in g
(9.80665 m/s^2) everywhere; stations are shown from the highest to the lowest (by their
coordinates in stations.h5; at equal height the one nearest the highest station first), so a
structure comes first, then the free-field surface, then the bedrock:
  stations_acceleration.png     the input (outcrop) motion of input_motion.csv, then one row per
                                station: horizontal and vertical acceleration as computed
                                (unfiltered, the dynamic motion: no gravity in it), with each
                                trace's peak; the suptitle gives the highest frequency the mesh
                                resolves (OUT/run_info.json): content above it is numerical
  spectra.png, spectra.csv      5 %-damped pseudo-acceleration response spectra PSA(T) [g] of
                                the input motion and of every station's horizontal
                                acceleration, at N_PERIODS log-spaced periods from 0.02 to 5 s
                                (exact piecewise-linear oscillator step, response_spectrum.py);
                                the periods shorter than 1 / resolved frequency are shaded
  amplification.png             PSA(station) / PSA(input outcrop motion): the site's
                                amplification, the free-field surface (--reference) in bold,
                                the layer's fundamental period 4 H / vs marked (--layer)
  transfer_ratio.png            PSA(station) / PSA(reference station) of every other station:
                                the structure / free-field spectral ratio (--reference NAME,
                                default free_field; skipped without that station)
  interface_<name>_history.png  accumulated slip (the slip path) and opening (mean and max
                                over the pairs), the net tangential offset (mean slip), the
                                structure's rocking angle (rigid_<region>.csv, else the
                                stations block_base_left and block_base_right), and the
                                fraction of pairs in stick / slip / open vs time
  interface_<name>_profile.png  accumulated slip and opening of every pair at the last output
                                step, and the accumulated slip in space and time
  energy.png                    the energy budget (bulk terms), the interfaces' terms on their
                                own axis, and the relative balance error
  stations_pore_pressure.png    saturated scenes: the excess pore pressure (over the
                                hydrostatic one of -water_table) [kPa] at every station,
                                compression positive

Works for 2D and 3D output. What is absent (no stations, no interface, no energy.csv) is
skipped with a message. Prints the list of files written; exits 1 if nothing was plotted.
The output may be plotted while the run is going (the XDMF lists the finished steps).
The figure_* functions return matplotlib figures (tests check their axes).
"""
import argparse
import glob
import os
import sys
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "python"))
from response_spectrum import pseudo_acceleration_spectrum, resample_uniform  # noqa: E402
from slipwave import INTERFACE_STATUS, RunFolder, read_csv  # noqa: E402

try:
    import h5py
except ImportError:  # only the interface plots and stations.h5 need it
    h5py = None

STANDARD_GRAVITY = 9.80665  # m/s^2 per g
SPECTRUM_DAMPING = 0.05
N_PERIODS = 200  # log-spaced: about 80 per decade, smooth at the spectra's narrow peaks
PERIOD_RANGE = (0.02, 5.0)  # s
MAX_POINTS = 20000  # a time series longer than this is thinned for plotting (every k-th sample)
STATUS_NAMES = INTERFACE_STATUS
STATUS_COLORS = ("tab:green", "tab:orange", "tab:red")
INPUT_LABEL = "input (outcrop motion)"


def note(message):
    print(f"plot_results: {message}")


def thin(*arrays):
    """Every k-th sample, so that at most MAX_POINTS remain (the last sample is kept)."""
    n = len(arrays[0])
    if n <= MAX_POINTS:
        return arrays
    idx = np.unique(np.append(np.arange(0, n, int(np.ceil(n / MAX_POINTS))), n - 1))
    return tuple(a[idx] for a in arrays)


def save(fig, path, written):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    written.append(path)


def spectral_periods():
    return np.logspace(np.log10(PERIOD_RANGE[0]), np.log10(PERIOD_RANGE[1]), N_PERIODS)


# ---------------------------------------------------------------------------------------
# What the run says about itself


def run_info(run):
    try:
        return run.run_info()
    except (OSError, ValueError):
        return {}


def resolution_note(info):
    """The title's statement of what the mesh resolves, from run_info.json."""
    if "resolved_frequency_hz" not in info:
        return "resolved frequency unknown (no run_info.json)"
    # Spectral elements (degree p > 1) count GLL nodes per wavelength.
    points = f"GLL nodes at degree {info['element_degree']}" if "element_degree" in info else "points"
    return (f"mesh resolves up to {info['resolved_frequency_hz']:.3g} Hz "
            f"({info['points_per_wavelength']:g} {points} per S wavelength in '{info['slowest_region']}'); "
            "content above is numerical")


def read_input_motion(run):
    """The outcrop motion the run applied (input_motion.csv): (component, t [s], a [m/s^2]),
    or None without an incident wave."""
    path = os.path.join(run.path, "input_motion.csv")
    if not os.path.isfile(path):
        return None
    table = read_csv(path)
    column = next((n for n in table.names if n.startswith("a_outcrop_")), None)
    if column is None or len(table) < 2:
        return None
    return column[-1], table["t"], table[column]


# ---------------------------------------------------------------------------------------
# Stations


def read_stations(run):
    """{name: station Table} of the stations with rows (stations/*.csv, else stations.h5)."""
    try:
        stations = run.stations()
    except ImportError:  # stations.h5 alone, and no h5py
        return {}
    return {name: data for name, data in stations.items() if len(data) and "t" in data}


def station_coordinates(run):
    """{name: point [m]} from stations.h5's group attribute "coordinates" ({} without it)."""
    path = os.path.join(run.path, "stations.h5")
    if h5py is None or not os.path.isfile(path):
        return {}
    with h5py.File(path, "r") as f:
        return {name: np.array(f[name].attrs["coordinates"]) for name in f if "coordinates" in f[name].attrs}


def station_order(names, coordinates):
    """The stations from the highest to the lowest (the last coordinate is the vertical); at
    equal height the nearest (horizontally) to the highest station first, so that a structure's
    stations come before the free field's at the same level. Without coordinates: as given."""
    if not names or any(n not in coordinates for n in names):
        return list(names)
    top = max(names, key=lambda n: coordinates[n][-1])
    def key(n):
        x = coordinates[n]
        return (-round(float(x[-1]), 9), float(np.linalg.norm(x[:-1] - coordinates[top][:-1])), n)
    return sorted(names, key=key)


def figure_pore_pressure(stations, order):
    """Saturated scenes only: the stations' column p_excess; None without it."""
    names = [n for n in order if "p_excess" in stations[n]]
    if not names:
        return None
    fig, ax = plt.subplots(figsize=(11, 4), layout="constrained")
    for name in names:
        tt, p = thin(stations[name]["t"], stations[name]["p_excess"])
        ax.plot(tt, p / 1e3, lw=0.8, label=name)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("excess pore pressure [kPa]")
    ax.set_title("Excess pore pressure at the stations (over the hydrostatic; compression positive)")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper right", fontsize=8)
    return fig


def components(data):
    """(horizontal components, vertical component) of a station's record: the vertical axis is
    the last one (y in 2D, z in 3D)."""
    comps = [c for c in "xyz" if f"a_{c}" in data]
    return comps[:-1], comps[-1]


def figure_stations(stations, order, motion, info):
    """Rows: the input motion (if any), then each station in order; columns: horizontal and
    vertical acceleration [g]."""
    rows = ([("input", None)] if motion is not None else []) + [("station", n) for n in order]
    fig, axes = plt.subplots(len(rows), 2, figsize=(12, 1.9 * len(rows) + 1.2), sharex=True, squeeze=False,
                             layout="constrained")
    for row, (kind, name) in enumerate(rows):
        ax_h, ax_v = axes[row]
        if kind == "input":
            c, t, a = motion
            tt, y = thin(t, a / STANDARD_GRAVITY)
            vertical = "z" if any("a_z" in stations[n] for n in order) else "y"
            ax = ax_v if c == vertical else ax_h
            ax.plot(tt, y, lw=0.8, color="k", label=f"a_{c}")
            ax.set_title(f"{INPUT_LABEL}: peak {np.max(np.abs(a)) / STANDARD_GRAVITY:.3g} g", fontsize=9)
            other = ax_v if ax is ax_h else ax_h
            other.text(0.5, 0.5, "no input in this direction", ha="center", va="center", transform=other.transAxes,
                       fontsize=8, color="0.4")
            for x in (ax_h, ax_v):
                x.set_ylabel("acceleration [g]")
                x.grid(alpha=0.3)
            continue
        data = stations[name]
        horizontal, vertical = components(data)
        peaks = []
        for c in horizontal:
            tt, a = thin(data["t"], data[f"a_{c}"] / STANDARD_GRAVITY)
            ax_h.plot(tt, a, lw=0.8, label=f"a_{c}")
            peaks.append(f"a_{c} {np.max(np.abs(a)):.3g} g")
        tt, a = thin(data["t"], data[f"a_{vertical}"] / STANDARD_GRAVITY)
        ax_v.plot(tt, a, lw=0.8, color="tab:purple", label=f"a_{vertical}")
        ax_h.set_title(f"'{name}' horizontal: peak {', '.join(peaks)}", fontsize=9)
        ax_v.set_title(f"'{name}' vertical: peak a_{vertical} {np.max(np.abs(a)):.3g} g", fontsize=9)
        for ax in (ax_h, ax_v):
            ax.set_ylabel("acceleration [g]")
            ax.grid(alpha=0.3)
            if len(ax.lines) > 1:
                ax.legend(loc="upper right", fontsize=7)
    for ax in axes[-1]:
        ax.set_xlabel("time [s]")
    fig.suptitle("Accelerations as computed, unfiltered (dynamic motion, the static state under gravity is at rest), "
                 f"top to bottom\n{resolution_note(info)}", fontsize=10)
    return fig


def station_spectra(stations, order, motion):
    """The periods [s] and {label: PSA [g]}: the input motion's (INPUT_LABEL) first, then
    (station, component) of each station's horizontal components, in order."""
    periods = spectral_periods()
    spectra = {}
    if motion is not None:
        c, t, a = motion
        dt, acc = resample_uniform(t, a)
        spectra[INPUT_LABEL] = pseudo_acceleration_spectrum(acc, dt, periods, SPECTRUM_DAMPING) / STANDARD_GRAVITY
    for name in order:
        data = stations[name]
        if len(data["t"]) < 2:
            continue
        for c in components(data)[0]:
            dt, acc = resample_uniform(data["t"], data[f"a_{c}"])
            spectra[(name, c)] = pseudo_acceleration_spectrum(acc, dt, periods, SPECTRUM_DAMPING) / STANDARD_GRAVITY
    return periods, spectra


def label_of(key):
    return key if isinstance(key, str) else f"{key[0]} a_{key[1]}"


def shade_unresolved(ax, info):
    """Shades the periods shorter than 1 / resolved frequency (the mesh does not carry them)."""
    f = info.get("resolved_frequency_hz")
    if f and 1.0 / f > PERIOD_RANGE[0]:
        ax.axvspan(PERIOD_RANGE[0], 1.0 / f, color="0.85", zorder=0,
                   label=f"T < {1.0 / f:.3g} s: above the {f:.3g} Hz the mesh resolves")
        ax.set_xlim(PERIOD_RANGE)


def mark_layer_period(ax, layer):
    if layer:
        h, vs = layer
        ax.axvline(4 * h / vs, color="tab:red", ls="--", lw=1,
                   label=f"layer period 4H/vs = 4 x {h:g} m / {vs:g} m/s = {4 * h / vs:.3g} s")


def style_spectrum_axes(ax, ylabel):
    ax.set_xscale("log")
    ax.set_xlim(PERIOD_RANGE)
    ax.set_xlabel("period T [s]")
    ax.set_ylabel(ylabel)
    ax.grid(alpha=0.3, which="both")


def figure_spectra(periods, spectra, info, layer):
    fig, ax = plt.subplots(figsize=(10, 5.5), layout="constrained")
    for key, psa in spectra.items():
        if key == INPUT_LABEL:
            ax.plot(periods, psa, color="k", ls="--", lw=1.5, label=INPUT_LABEL)
        else:
            ax.plot(periods, psa, label=label_of(key))
    style_spectrum_axes(ax, "pseudo-acceleration PSA [g]")
    shade_unresolved(ax, info)
    mark_layer_period(ax, layer)
    ax.legend(fontsize=8)
    ax.set_title(f"{100 * SPECTRUM_DAMPING:g} %-damped pseudo-acceleration response spectra ({len(periods)} periods)")
    return fig


def figure_amplification(periods, spectra, info, layer, reference):
    """PSA(station) / PSA(input outcrop motion); None without the input motion."""
    if INPUT_LABEL not in spectra:
        return None
    outcrop = spectra[INPUT_LABEL]
    fig, ax = plt.subplots(figsize=(10, 5.5), layout="constrained")
    for key, psa in spectra.items():
        if key == INPUT_LABEL:
            continue
        bold = key[0] == reference
        ax.plot(periods, psa / outcrop, lw=2.2 if bold else 0.9, color="tab:blue" if bold else None,
                alpha=1 if bold else 0.7, label=label_of(key) + (" (free-field surface)" if bold else ""))
    ax.axhline(1, color="k", lw=0.6)
    style_spectrum_axes(ax, "PSA ratio to the outcrop motion [-]")
    shade_unresolved(ax, info)
    mark_layer_period(ax, layer)
    ax.legend(fontsize=8)
    ax.set_title(f"Amplification: {100 * SPECTRUM_DAMPING:g} %-damped PSA of each station over the input outcrop motion's")
    return fig


def figure_transfer(periods, spectra, info, reference):
    ref = {key[1]: s for key, s in spectra.items() if key != INPUT_LABEL and key[0] == reference}
    if not ref:
        note(f"no station '{reference}' (the free-field reference, --reference): transfer ratio skipped")
        return None
    others = [key for key in spectra if key != INPUT_LABEL and key[0] != reference and key[1] in ref]
    if not others:
        note(f"no station other than '{reference}': transfer ratio skipped")
        return None
    fig, ax = plt.subplots(figsize=(10, 5.5), layout="constrained")
    for name, c in others:
        ax.plot(periods, spectra[(name, c)] / ref[c], label=f"{name} / {reference} (a_{c})")
    ax.axhline(1, color="k", lw=0.6)
    style_spectrum_axes(ax, "PSA ratio [-]")
    shade_unresolved(ax, info)
    ax.legend(fontsize=8)
    ax.set_title(f"Transfer ratio: {100 * SPECTRUM_DAMPING:g} %-damped PSA of each station over the free field '{reference}'")
    return fig


def write_spectra_csv(path, periods, spectra):
    keys = list(spectra)
    names = ["input_outcrop_psa_g" if k == INPUT_LABEL else f"{k[0]}_a_{k[1]}_psa_g" for k in keys]
    np.savetxt(path, np.column_stack([periods] + [spectra[k] for k in keys]), delimiter=",",
               header="period_s," + ",".join(names), comments="", fmt="%.6g")


# ---------------------------------------------------------------------------------------
# Interfaces


def read_interface(run, name):
    """Interface `name`'s frames: dict with times [nsteps], geometry [npairs, 3], topology,
    topology_type and fields {name: array [nsteps, npairs, ncomp]} (the fields every frame
    has); None without frames."""
    frames = run.interface(name)
    if not len(frames):
        return None
    return {"times": np.array(frames.times), "geometry": frames.geometry, "topology": frames.topology,
            "topology_type": frames.topology_type, "fields": frames.stacked()}


def chain_order(topology, npairs):
    """Orders the pairs of a 2D interface (Polyline segments) along the line.

    Returns a list of chains (lists of pair indices, each in order along the line), or None if
    the segments do not form simple chains (a pair with more than two neighbours).
    """
    if topology is None or topology.ndim != 2 or topology.shape[1] != 2:
        return None
    neighbours = [[] for _ in range(npairs)]
    for a, b in topology:
        neighbours[a].append(b)
        neighbours[b].append(a)
    if any(len(n) > 2 for n in neighbours):
        return None
    seen = np.zeros(npairs, bool)
    chains = []
    # Open chains first (start at an end), then closed loops, then isolated pairs.
    starts = [i for i in range(npairs) if len(neighbours[i]) == 1] + list(range(npairs))
    for s in starts:
        if seen[s]:
            continue
        chain, prev, cur = [], -1, s
        while cur != -1 and not seen[cur]:
            seen[cur] = True
            chain.append(cur)
            nxt = [n for n in neighbours[cur] if n != prev and not seen[n]]
            prev, cur = cur, (nxt[0] if nxt else -1)
        chains.append(chain)
    return chains


def rocking_angles(run, stations, coordinates):
    """[(label, t [s], angle [rad])] of the structure's rotation: rigid_<region>.csv's theta_*
    columns (the rigid body's history) if there are any, else the stations block_base_left and
    block_base_right: (u_v(right) - u_v(left)) / their horizontal distance (counter-clockwise
    positive in 2D, as theta_z). [] without either."""
    angles = []
    for path in sorted(glob.glob(os.path.join(run.path, "rigid_*.csv"))):
        table = read_csv(path)
        region = os.path.basename(path)[len("rigid_"):-len(".csv")]
        for column in table.names:
            if column.startswith("theta_") and len(table) and np.any(table[column] != 0):
                angles.append((f"rigid body '{region}' {column}", table["t"], table[column]))
    if angles:
        return angles
    left, right = "block_base_left", "block_base_right"
    if left in stations and right in stations and left in coordinates and right in coordinates:
        vertical = components(stations[left])[1]
        span = float(np.linalg.norm(coordinates[right][:-1] - coordinates[left][:-1]))
        n = min(len(stations[left]), len(stations[right]))
        theta = (stations[right][f"u_{vertical}"][:n] - stations[left][f"u_{vertical}"][:n]) / span
        angles.append((f"(u_{vertical}({right}) - u_{vertical}({left})) / {span:g} m", stations[left]["t"][:n], theta))
    return angles


def plot_interfaces(run, plots, written, rocking):
    names = run.interface_names()
    if not names:
        note("no interface output (interface_*.xmf): interface plots skipped")
        return
    if h5py is None:
        note("h5py is not installed: interface plots skipped")
        return
    for name in names:
        xmf = os.path.join(run.path, f"interface_{name}.xmf")
        try:
            data = read_interface(run, name)
        except (OSError, KeyError, ET.ParseError, ValueError) as e:
            note(f"interface '{name}': cannot read {xmf} ({e}): skipped")
            continue
        if data is None or not data["fields"]:
            note(f"interface '{name}': no output steps in {xmf}: skipped")
            continue
        save(figure_interface_history(name, data, rocking), os.path.join(plots, f"interface_{name}_history.png"), written)
        fig = figure_interface_profile(name, data)
        if fig is not None:
            save(fig, os.path.join(plots, f"interface_{name}_profile.png"), written)


def scalar_field(data, name):
    """[nsteps, npairs] of a field; a vector field gives its magnitude; None if absent."""
    f = data["fields"].get(name)
    if f is None:
        return None
    return f[:, :, 0] if f.shape[2] == 1 else np.linalg.norm(f, axis=2)


def figure_interface_history(name, data, rocking):
    """Slip, opening, the rocking angle (rocking: rocking_angles(); its panel only if there is
    one) and the pairs' status vs time."""
    t = data["times"]
    npairs = data["geometry"].shape[0]
    fig, axes = plt.subplots(4 if rocking else 3, 1, figsize=(10, 12 if rocking else 9), sharex=True, layout="constrained")
    slip = scalar_field(data, "accumulated_slip")
    slip_label = "accumulated slip"
    if slip is None:
        slip, slip_label = scalar_field(data, "slip"), "|slip|"
    ax = axes[0]
    if slip is not None:
        ax.plot(t, slip.mean(axis=1), label=f"mean {slip_label}")
        ax.plot(t, slip.max(axis=1), label=f"max {slip_label}")
        current = scalar_field(data, "slip")
        if current is not None and slip_label != "|slip|":
            ax.plot(t, current.max(axis=1), ls="--", lw=0.9, label="max |slip| (current tangential gap)")
            # The net tangential offset: where the structure is relative to the soil (the
            # mean jump over the pairs), against the slip path above (every increment).
            mean_jump = data["fields"]["slip"].mean(axis=1)
            if data["topology_type"] == "Polyline":
                ax.plot(t, mean_jump[:, 0], color="k", lw=1.0, label="net tangential offset (mean slip, signed)")
            else:
                ax.plot(t, np.linalg.norm(mean_jump, axis=1), color="k", lw=1.0, label="net tangential offset (|mean slip|)")
        ax.legend(fontsize=8)
    else:
        ax.text(0.5, 0.5, "no slip field", ha="center", transform=ax.transAxes)
    ax.set_ylabel("slip [m]")
    ax.set_title(f"interface '{name}' ({npairs} pairs): slip over the pairs")
    ax = axes[1]
    opening = scalar_field(data, "opening")
    if opening is not None:
        ax.plot(t, opening.mean(axis=1), label="mean opening")
        ax.plot(t, opening.max(axis=1), label="max opening")
        ax.plot(t, opening.min(axis=1), lw=0.8, ls=":", label="min opening (< 0: penalty overlap)")
        plastic = scalar_field(data, "plastic_opening")
        if plastic is not None and np.any(plastic != 0):
            ax.plot(t, plastic.max(axis=1), ls="--", lw=0.9, label="max plastic opening")
        ax.axhline(0, color="k", lw=0.5)
        ax.legend(fontsize=8)
    else:
        ax.text(0.5, 0.5, "no opening field", ha="center", transform=ax.transAxes)
    ax.set_ylabel("opening [m]")
    ax.set_title(f"interface '{name}': normal opening over the pairs")
    if rocking:
        ax = axes[2]
        for label, tr, theta in rocking:
            tt, y = thin(tr, theta * 1e3)
            ax.plot(tt, y, lw=0.9, label=label)
        ax.axhline(0, color="k", lw=0.5)
        ax.set_ylabel("rocking angle [mrad]")
        ax.set_title(f"the structure's rotation (peak {max(np.max(np.abs(th)) for _, _, th in rocking) * 1e3:.3g} mrad; "
                     "counter-clockwise positive)")
        ax.legend(fontsize=8)
    ax = axes[-1]
    status = scalar_field(data, "status")
    if status is not None:
        s = np.rint(status).astype(int)
        fractions = [np.mean(s == k, axis=1) for k in range(3)]
        ax.stackplot(t, *fractions, labels=STATUS_NAMES, colors=STATUS_COLORS, alpha=0.8, step="post")
        ax.set_ylim(0, 1)
        ax.legend(loc="upper right", fontsize=8)
    else:
        ax.text(0.5, 0.5, "no status field", ha="center", transform=ax.transAxes)
    ax.set_ylabel("fraction of pairs [-]")
    ax.set_title(f"interface '{name}': pair status (stick / slip / open)")
    ax.set_xlabel("time [s]")
    for ax in axes:
        ax.grid(alpha=0.3)
    return fig


def figure_interface_profile(name, data):
    t = data["times"]
    xyz = data["geometry"]
    npairs = xyz.shape[0]
    slip = scalar_field(data, "accumulated_slip")
    if slip is None:
        slip = scalar_field(data, "slip")
    opening = scalar_field(data, "opening")
    if slip is None and opening is None:
        note(f"interface '{name}': no slip or opening field: profile skipped")
        return None
    chains = chain_order(data["topology"], npairs) if data["topology_type"] == "Polyline" else None
    if chains:
        # 2D: distance along the interface line, chain after chain.
        order, s, breaks, start = [], [], [], 0.0
        for chain in chains:
            seg = np.linalg.norm(np.diff(xyz[chain], axis=0), axis=1)
            s.extend(start + np.concatenate([[0.0], np.cumsum(seg)]))
            order.extend(chain)
            start = s[-1]
            breaks.append(start)
        order, s = np.array(order), np.array(s)
        xlabel = "distance along the interface [m]"
        first = xyz[order[0]]
        subtitle = f"from ({first[0]:g}, {first[1]:g})"
    else:
        # 3D (or an irregular line): pairs sorted by their coordinates, shown by index.
        order = np.lexsort(xyz.T[::-1])
        s = np.arange(npairs, dtype=float)
        xlabel = "pair (sorted by x, then y, then z) [-]"
        subtitle = ""
    three_d = data["topology_type"] != "Polyline"
    fig = plt.figure(figsize=(11, 8.5), layout="constrained")
    grid = fig.add_gridspec(2, 2, height_ratios=(1, 1.2))
    ax = fig.add_subplot(grid[0, :] if not three_d else grid[0, 0])
    status = scalar_field(data, "status")
    if slip is not None:
        ax.plot(s, slip[-1, order], "o-", ms=3, color="tab:blue", label="accumulated slip")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("slip [m]", color="tab:blue")
    ax.grid(alpha=0.3)
    if opening is not None:
        ax2 = ax.twinx()
        ax2.plot(s, opening[-1, order], "s--", ms=3, color="tab:red", label="opening")
        ax2.set_ylabel("opening [m]", color="tab:red")
        ax2.axhline(0, color="tab:red", lw=0.5)
    if status is not None:
        st = np.rint(status[-1, order]).astype(int)
        for k in range(3):
            sel = st == k
            if np.any(sel):
                ax.scatter(s[sel], np.zeros(sel.sum()), marker="|", s=200, color=STATUS_COLORS[k],
                           label=f"{STATUS_NAMES[k]} ({sel.sum()})", zorder=3)
    handles, labels = ax.get_legend_handles_labels()
    if opening is not None:
        h2, l2 = ax2.get_legend_handles_labels()
        handles, labels = handles[:1] + h2 + handles[1:], labels[:1] + l2 + labels[1:]
    ax.legend(handles, labels, loc="upper left", fontsize=8, title="markers at 0: status", title_fontsize=8)
    ax.set_title(f"interface '{name}' at the last output step t = {t[-1]:.4g} s {subtitle}")
    if three_d:
        ax3 = fig.add_subplot(grid[0, 1], projection="3d")
        values = slip[-1] if slip is not None else opening[-1]
        sc = ax3.scatter(xyz[:, 0], xyz[:, 1], xyz[:, 2], c=values, cmap="viridis", s=25)
        fig.colorbar(sc, ax=ax3, shrink=0.7, label=("accumulated slip" if slip is not None else "opening") + " [m]")
        ax3.set_xlabel("x [m]")
        ax3.set_ylabel("y [m]")
        ax3.set_zlabel("z [m]")
        ax3.set_title("pairs in space at the last step", fontsize=9)
    ax = fig.add_subplot(grid[1, :])
    field, label = (slip, "accumulated slip [m]") if slip is not None else (opening, "opening [m]")
    values = field[:, order]
    if len(t) > 1 and npairs > 1:
        edges_s = np.concatenate([[s[0] - 0.5 * (s[1] - s[0])], 0.5 * (s[1:] + s[:-1]), [s[-1] + 0.5 * (s[-1] - s[-2])]])
        edges_t = np.concatenate([[t[0]], 0.5 * (t[1:] + t[:-1]), [t[-1]]])
        mesh = ax.pcolormesh(edges_s, edges_t, values, cmap="viridis", shading="flat")
        fig.colorbar(mesh, ax=ax, label=label)
        if chains:
            for b in breaks[:-1]:
                ax.axvline(b, color="w", lw=0.8)
    else:
        ax.text(0.5, 0.5, "one output step or one pair: no space-time map", ha="center", transform=ax.transAxes)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("time [s]")
    ax.set_title(f"interface '{name}': {label.split(' [')[0]} in space and time")
    return fig


# ---------------------------------------------------------------------------------------
# Energy


# energy.csv's columns (src/app/energy_csv.cpp, problem/energy_ledger.hpp) as what they hold.
# external_work is the ledger's external + reactions: the work of f_external (gravity, surface
# tractions, point and body forces, and the free-field sides' C v_ff + A t_ff) and of the held
# dofs; absorbed takes the dashpots of the absorbing base and of the free-field sides (-C v).
BULK_TERMS = [
    ("kinetic", "kinetic energy (now)", "tab:blue", "-"),
    ("strain", "strain energy (now)", "tab:orange", "-"),
    ("input_work", "work of the incident wave at the base", "tab:green", "-"),
    ("external_work", "work of the external forces: free-field sides, gravity, loads, supports", "tab:olive", "-"),
    ("absorbed", "absorbed by the dashpots (absorbing base, free-field sides)", "tab:red", "-"),
    ("damped", "dissipated by Rayleigh damping", "tab:brown", "-"),
    ("anelastic", "work against the constant-Q damping (memory variables)", "tab:gray", "-"),
    ("hysteretic_dissipated", "dissipated by the hysteretic soil", "tab:cyan", "-"),
    ("darcy_dissipated", "dissipated by the pore-fluid flow (Darcy)", "tab:pink", "-"),
    ("cavitation_work", "work of the pore fluid on its cavities (cavitation)", "tab:pink", "--"),
]
INTERFACE_TERMS = [
    ("interface_work", "work of the interface forces on the bulk", "k", "-"),
    ("interface_stored", "stored in the interface springs (now)", "tab:pink", "--"),
    ("interface_dissipated", "dissipated by interface slip (Mohr-Coulomb)", "tab:purple", "-"),
    ("contact_damped", "absorbed by the contact dashpots", "tab:cyan", "-"),
]


def figure_energy(e):
    """Bulk terms (cumulative work, and the energies stored now), the interfaces' terms on an
    axis of their own (they are small beside the bulk's), and the relative balance error."""
    t = e["time"]
    has_interface = any(c in e and np.any(e[c] != 0) for c, *_ in INTERFACE_TERMS)
    rows = 2 + has_interface
    fig, axes = plt.subplots(rows, 1, figsize=(10, 3.6 * rows + 0.6), sharex=True, squeeze=False,
                             height_ratios=[2] + [1.4] * has_interface + [0.8], layout="constrained")
    axes = axes[:, 0]
    ax = axes[0]
    for column, label, color, ls in BULK_TERMS:
        if column in e and (column in ("kinetic", "strain") or np.any(e[column] != 0)):
            tt, y = thin(t, e[column])
            ax.plot(tt, y, color=color, ls=ls, label=label)
    ax.set_ylabel("energy [J/m in 2D, J in 3D]")
    ax.set_title("Energy budget of the bulk: work done since the start (cumulative) and energies stored now")
    ax.legend(loc="upper left", fontsize=8)
    if has_interface:
        ax = axes[1]
        for column, label, color, ls in INTERFACE_TERMS:
            if column in e:
                tt, y = thin(t, e[column])
                ax.plot(tt, y, color=color, ls=ls, label=label)
        ax.set_ylabel("energy [J/m in 2D, J in 3D]")
        ax.set_title("Interfaces (all): stored, dissipated by slip, absorbed by the contact dashpots (cumulative)")
        ax.legend(loc="upper left", fontsize=8)
    ax = axes[-1]
    if "relative_balance_error" in e:
        tt, y = thin(t, e["relative_balance_error"])
        ax.plot(tt, y, color="0.3", lw=0.6)
        ax.set_title(f"balance error over the largest energy so far (largest {np.max(np.abs(y)):.2e}; round-off: a few 1e-15)")
    ax.set_ylabel("relative balance error [-]")
    ax.set_xlabel("time [s]")
    for a in axes:
        a.grid(alpha=0.3)
    return fig


def plot_energy(run, plots, written):
    if not os.path.isfile(os.path.join(run.path, "energy.csv")):
        note("no energy.csv: energy plot skipped")
        return
    e = run.energy()
    if not len(e) or "time" not in e:
        note("energy.csv has no rows: energy plot skipped")
        return
    save(figure_energy(e), os.path.join(plots, "energy.png"), written)


def layer_argument(text):
    try:
        h, vs = (float(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"--layer {text}: allowed: H,VS (thickness [m], shear-wave speed [m/s])")
    if not (h > 0 and vs > 0):
        raise argparse.ArgumentTypeError(f"--layer {text}: allowed: H > 0 and VS > 0")
    return h, vs


def make_figures(out, plots, reference="free_field", layer=None):
    """Writes every figure of the run folder OUT into PLOTS; returns the paths written."""
    written = []
    run = RunFolder(out)
    info = run_info(run)
    stations = read_stations(run)
    coordinates = station_coordinates(run)
    order = station_order(list(stations), coordinates)
    motion = read_input_motion(run)
    if stations or motion is not None:
        save(figure_stations(stations, order, motion, info), os.path.join(plots, "stations_acceleration.png"), written)
    else:
        note("no station records (stations/*.csv or stations.h5) and no input motion: station plot skipped")
    fig = figure_pore_pressure(stations, order)
    if fig is not None:
        save(fig, os.path.join(plots, "stations_pore_pressure.png"), written)
    periods, spectra = station_spectra(stations, order, motion)
    if spectra:
        os.makedirs(plots, exist_ok=True)
        write_spectra_csv(os.path.join(plots, "spectra.csv"), periods, spectra)
        written.append(os.path.join(plots, "spectra.csv"))
        save(figure_spectra(periods, spectra, info, layer), os.path.join(plots, "spectra.png"), written)
        fig = figure_amplification(periods, spectra, info, layer, reference)
        if fig is not None:
            save(fig, os.path.join(plots, "amplification.png"), written)
        else:
            note("no input motion (input_motion.csv): amplification skipped")
        fig = figure_transfer(periods, spectra, info, reference)
        if fig is not None:
            save(fig, os.path.join(plots, "transfer_ratio.png"), written)
    else:
        note("no station records and no input motion: response spectra skipped")
    plot_interfaces(run, plots, written, rocking_angles(run, stations, coordinates))
    plot_energy(run, plots, written)
    return written


def main():
    parser = argparse.ArgumentParser(description="Plots the results of a slipwave run as PNG files.")
    parser.add_argument("out", metavar="OUT", help="the -output_dir of the run")
    parser.add_argument("--out", dest="plots", metavar="DIR", help="where to write the figures (default OUT/plots)")
    parser.add_argument("--reference", default="free_field", metavar="STATION",
                        help="the free-field surface station (default free_field): bold in the amplification, "
                             "the denominator of the transfer ratio")
    parser.add_argument("--layer", type=layer_argument, metavar="H,VS",
                        help="the soil layer's thickness [m] and shear-wave speed [m/s]: its period 4 H / VS is "
                             "marked on the spectra")
    args = parser.parse_args()
    if not os.path.isdir(args.out):
        print(f"plot_results: error: {args.out} is not a directory", file=sys.stderr)
        return 1
    written = make_figures(args.out, args.plots or os.path.join(args.out, "plots"), args.reference, args.layer)
    if not written:
        print(f"plot_results: error: nothing to plot in {args.out} (no stations, interfaces or energy.csv)",
              file=sys.stderr)
        return 1
    print(f"plot_results: {len(written)} file(s) written:")
    for path in written:
        print(f"  {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

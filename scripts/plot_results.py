#!/usr/bin/python3
"""Plots the results of a slipwave run as PNG figures (matplotlib, no display needed).

usage: /usr/bin/python3 scripts/plot_results.py OUT [--out DIR] [--reference STATION]

OUT is the -output_dir of a run. Figures go to OUT/plots/ (or DIR):
  stations_acceleration.png     one row per station: horizontal and vertical acceleration as
                                computed (unfiltered); the title gives the highest frequency
                                the mesh resolves (OUT/run_info.json): content above it is
                                numerical, not physical
  spectra.png, spectra.csv      5 %-damped pseudo-acceleration response spectra PSA(T) [g]
                                of every station's horizontal acceleration, T = 0.02 to 5 s
                                (exact piecewise-linear oscillator step, response_spectrum.py)
  transfer_ratio.png            PSA(station) / PSA(reference station) of every other station:
                                the structure / free-field spectral ratio (--reference NAME,
                                default free_field; skipped without that station)
  interface_<name>_history.png  accumulated slip (the slip path) and opening (mean and max
                                over the pairs), the net tangential offset (mean slip), and
                                the fraction of pairs in stick / slip / open vs time
  interface_<name>_profile.png  accumulated slip and opening of every pair at the last output
                                step, and the accumulated slip in space and time
  energy.png                    the energy budget, with the balance error on a second axis
  stations_pore_pressure.png    saturated scenes: the excess pore pressure (over the
                                hydrostatic one of -water_table) [kPa] at every station,
                                compression positive

Works for 2D and 3D output. What is absent (no stations, no interface, no energy.csv) is
skipped with a message. Prints the list of files written; exits 1 if nothing was plotted.
The output may be plotted while the run is going (the XDMF lists the finished steps).
"""
import argparse
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
from response_spectrum import default_periods, pseudo_acceleration_spectrum, resample_uniform  # noqa: E402
from slipwave import INTERFACE_STATUS, RunFolder  # noqa: E402

try:
    import h5py  # noqa: F401
except ImportError:  # only the interface plots and stations.h5 need it
    h5py = None

STANDARD_GRAVITY = 9.80665  # m/s^2 per g
SPECTRUM_DAMPING = 0.05
MAX_POINTS = 20000  # a time series longer than this is thinned for plotting (every k-th sample)
STATUS_NAMES = INTERFACE_STATUS
STATUS_COLORS = ("tab:green", "tab:orange", "tab:red")


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


# ---------------------------------------------------------------------------------------
# Stations


def read_stations(run):
    """{name: station Table} of the stations with rows (stations/*.csv, else stations.h5)."""
    try:
        stations = run.stations()
    except ImportError:  # stations.h5 alone, and no h5py
        return {}
    return {name: data for name, data in stations.items() if len(data) and "t" in data}


def resolution_note(out):
    """The title's statement of what the mesh resolves, from OUT/run_info.json."""
    try:
        info = RunFolder(out).run_info()
        # Spectral elements (degree p > 1) count GLL nodes per wavelength.
        points = f"GLL nodes at degree {info['element_degree']}" if "element_degree" in info else "points"
        return (f"mesh resolves up to {info['resolved_frequency_hz']:.3g} Hz "
                f"({info['points_per_wavelength']:g} {points} per S wavelength in '{info['slowest_region']}'); "
                "content above is numerical")
    except (OSError, ValueError, KeyError):
        return "resolved frequency unknown (no run_info.json)"


def plot_pore_pressure(plots, written, stations):
    """Saturated scenes only: the stations' column p."""
    names = [n for n in stations if "p_excess" in stations[n]]
    if not names:
        return
    fig, ax = plt.subplots(figsize=(11, 4))
    for name in names:
        tt, p = thin(stations[name]["t"], stations[name]["p_excess"])
        ax.plot(tt, p / 1e3, lw=0.8, label=name)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("excess pore pressure [kPa]")
    ax.set_title("Excess pore pressure at the stations (over the hydrostatic; compression positive)")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    save(fig, os.path.join(plots, "stations_pore_pressure.png"), written)


def plot_stations(out, plots, written, stations):
    if not stations:
        note("no station records (stations/*.csv or stations.h5): station plot skipped")
        return
    names = list(stations)
    fig, axes = plt.subplots(len(names), 2, figsize=(11, 2.4 * len(names) + 1.0), sharex=True, squeeze=False)
    for row, name in enumerate(names):
        data = stations[name]
        comps = [c for c in "xyz" if f"a_{c}" in data]
        vertical = comps[-1]  # the vertical axis is the last one
        t = data["t"]
        ax_h, ax_v = axes[row]
        for c in comps[:-1]:
            tt, a = thin(t, data[f"a_{c}"])
            ax_h.plot(tt, a, lw=0.8, label=f"a_{c}")
        tt, a = thin(t, data[f"a_{vertical}"])
        ax_v.plot(tt, a, lw=0.8, color="tab:purple", label=f"a_{vertical}")
        ax_h.set_title(f"station '{name}': horizontal acceleration")
        ax_v.set_title(f"station '{name}': vertical acceleration")
        for ax in (ax_h, ax_v):
            ax.set_ylabel("acceleration [m/s²]")
            ax.grid(alpha=0.3)
            ax.legend(loc="upper right", fontsize=8)
    for ax in axes[-1]:
        ax.set_xlabel("time [s]")
    fig.suptitle(f"Station accelerations as computed, unfiltered ({len(names)} station{'s' if len(names) > 1 else ''}; "
                 f"vertical includes gravity if applied)\n{resolution_note(out)}")
    fig.tight_layout()
    save(fig, os.path.join(plots, "stations_acceleration.png"), written)


def station_spectra(stations):
    """{(station, component): PSA [g]} of the horizontal components, and the periods [s]."""
    periods = default_periods()
    spectra = {}
    for name, data in stations.items():
        comps = [c for c in "xyz" if f"a_{c}" in data]
        if len(data["t"]) < 2:
            continue
        for c in comps[:-1]:
            dt, acc = resample_uniform(data["t"], data[f"a_{c}"])
            spectra[(name, c)] = pseudo_acceleration_spectrum(acc, dt, periods, SPECTRUM_DAMPING) / STANDARD_GRAVITY
    return periods, spectra


def plot_spectra(plots, written, periods, spectra):
    if not spectra:
        note("no station records: response spectra skipped")
        return
    os.makedirs(plots, exist_ok=True)
    keys = list(spectra)
    path = os.path.join(plots, "spectra.csv")
    header = "period_s," + ",".join(f"{name}_a_{c}_psa_g" for name, c in keys)
    np.savetxt(path, np.column_stack([periods] + [spectra[k] for k in keys]), delimiter=",", header=header,
               comments="", fmt="%.6g")
    written.append(path)
    fig, ax = plt.subplots(figsize=(10, 5.5))
    for name, c in keys:
        ax.plot(periods, spectra[(name, c)], label=f"{name} a_{c}")
    ax.set_xscale("log")
    ax.set_xlabel("period T [s]")
    ax.set_ylabel("pseudo-acceleration PSA [g]")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    ax.set_title(f"{100 * SPECTRUM_DAMPING:g} %-damped pseudo-acceleration response spectra of the stations")
    fig.tight_layout()
    save(fig, os.path.join(plots, "spectra.png"), written)


def plot_transfer(plots, written, periods, spectra, reference):
    ref = {c: s for (name, c), s in spectra.items() if name == reference}
    if not ref:
        note(f"no station '{reference}' (the free-field reference, --reference): transfer ratio skipped")
        return
    others = [(name, c) for (name, c) in spectra if name != reference and c in ref]
    if not others:
        note(f"no station other than '{reference}': transfer ratio skipped")
        return
    fig, ax = plt.subplots(figsize=(10, 5.5))
    for name, c in others:
        ax.plot(periods, spectra[(name, c)] / ref[c], label=f"{name} / {reference} (a_{c})")
    ax.axhline(1, color="k", lw=0.6)
    ax.set_xscale("log")
    ax.set_xlabel("period T [s]")
    ax.set_ylabel("PSA ratio [-]")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    ax.set_title(f"Transfer ratio: {100 * SPECTRUM_DAMPING:g} %-damped PSA of each station over the free field '{reference}'")
    fig.tight_layout()
    save(fig, os.path.join(plots, "transfer_ratio.png"), written)


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


def plot_interfaces(run, plots, written):
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
        plot_interface_history(name, data, plots, written)
        plot_interface_profile(name, data, plots, written)


def scalar_field(data, name):
    """[nsteps, npairs] of a field; a vector field gives its magnitude; None if absent."""
    f = data["fields"].get(name)
    if f is None:
        return None
    return f[:, :, 0] if f.shape[2] == 1 else np.linalg.norm(f, axis=2)


def plot_interface_history(name, data, plots, written):
    t = data["times"]
    npairs = data["geometry"].shape[0]
    fig, axes = plt.subplots(3, 1, figsize=(10, 9), sharex=True)
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
    ax = axes[2]
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
    fig.tight_layout()
    save(fig, os.path.join(plots, f"interface_{name}_history.png"), written)


def plot_interface_profile(name, data, plots, written):
    t = data["times"]
    xyz = data["geometry"]
    npairs = xyz.shape[0]
    slip = scalar_field(data, "accumulated_slip")
    if slip is None:
        slip = scalar_field(data, "slip")
    opening = scalar_field(data, "opening")
    if slip is None and opening is None:
        note(f"interface '{name}': no slip or opening field: profile skipped")
        return
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
    fig = plt.figure(figsize=(11, 8.5))
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
    fig.tight_layout()
    save(fig, os.path.join(plots, f"interface_{name}_profile.png"), written)


# ---------------------------------------------------------------------------------------
# Energy


def plot_energy(run, plots, written):
    if not os.path.isfile(os.path.join(run.path, "energy.csv")):
        note("no energy.csv: energy plot skipped")
        return
    e = run.energy()
    if not len(e) or "time" not in e:
        note("energy.csv has no rows: energy plot skipped")
        return
    t = e["time"]
    fig, ax = plt.subplots(figsize=(10, 5.5))
    curves = [
        ("kinetic", "kinetic", "tab:blue", "-"),
        ("strain", "strain", "tab:orange", "-"),
        ("input_work", "input work (incident wave, cumulative)", "tab:green", "-"),
        ("external_work", "external work (gravity, tractions, supports, cumulative)", "tab:olive", "-"),
        ("absorbed", "absorbed by the dashpots (cumulative)", "tab:red", "-"),
        ("damped", "Rayleigh damping (cumulative)", "tab:brown", "-"),
        ("anelastic", "constant-Q damping (work on the memory variables, cumulative)", "tab:gray", "-"),
        ("interface_stored", "interface stored", "tab:pink", "--"),
        ("interface_dissipated", "interface dissipated (cumulative)", "tab:purple", "--"),
        ("contact_damped", "contact dashpots (cumulative)", "tab:cyan", "--"),
    ]
    for column, label, color, ls in curves:
        if column in e and (column in ("kinetic", "strain", "input_work") or np.any(e[column] != 0)):
            tt, y = thin(t, e[column])
            ax.plot(tt, y, color=color, ls=ls, label=label)
    if "interface_stored" in e and "interface_dissipated" in e:
        total = e["interface_stored"] + e["interface_dissipated"]
        if np.any(total != 0):
            tt, y = thin(t, total)
            ax.plot(tt, y, color="k", ls=":", label="interface stored + dissipated")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("energy [J per m in 2D, J in 3D]")
    ax.grid(alpha=0.3)
    handles, labels = ax.get_legend_handles_labels()
    if "balance_error" in e:
        ax2 = ax.twinx()
        tt, y = thin(t, e["balance_error"])
        ax2.plot(tt, y, color="0.6", lw=0.5, alpha=0.8, label="balance error (right axis)")
        ax.set_zorder(ax2.get_zorder() + 1)  # energies drawn over the (noisy) error
        ax.patch.set_visible(False)
        ax2.set_ylabel("balance error [J]", color="0.4")
        h2, l2 = ax2.get_legend_handles_labels()
        handles += h2
        labels += l2
        rel = e.get("relative_balance_error")
        if rel is not None:
            ax.set_title(f"Energy budget (largest relative balance error {np.max(np.abs(rel)):.2e})")
        else:
            ax.set_title("Energy budget")
    else:
        ax.set_title("Energy budget")
    ax.legend(handles, labels, loc="upper left", fontsize=8)
    fig.tight_layout()
    save(fig, os.path.join(plots, "energy.png"), written)


def main():
    parser = argparse.ArgumentParser(description="Plots the results of a slipwave run as PNG files.")
    parser.add_argument("out", metavar="OUT", help="the -output_dir of the run")
    parser.add_argument("--out", dest="plots", metavar="DIR", help="where to write the figures (default OUT/plots)")
    parser.add_argument("--reference", default="free_field", metavar="STATION",
                        help="the free-field station the transfer ratio divides by (default free_field)")
    args = parser.parse_args()
    if not os.path.isdir(args.out):
        print(f"plot_results: error: {args.out} is not a directory", file=sys.stderr)
        return 1
    plots = args.plots or os.path.join(args.out, "plots")
    written = []
    run = RunFolder(args.out)
    stations = read_stations(run)
    plot_stations(args.out, plots, written, stations)
    plot_pore_pressure(plots, written, stations)
    periods, spectra = station_spectra(stations)
    plot_spectra(plots, written, periods, spectra)
    plot_transfer(plots, written, periods, spectra, args.reference)
    plot_interfaces(run, plots, written)
    plot_energy(run, plots, written)
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

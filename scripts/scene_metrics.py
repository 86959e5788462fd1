#!/usr/bin/python3
"""What an earthquake engineer reads first from a run of a block on soil (2D).

usage: /usr/bin/python3 scripts/scene_metrics.py OUT [--interface base] [--lowpass-hz F] [--json FILE]

From the interface output (interface_<name>.xmf and its HDF5 files) and the stations of OUT
(read with the python/slipwave package). What the run did not write is skipped (a note on
stderr): the interface answers need interface_<name>, the rocking angle the stations
block_base_left and block_base_right, the others block_top and free_field.

Sliding (s(t): the mean over the pairs of the tangential jump, structure minus soil, at each
output step):
  net_slip            s at the last output step: the net offset [m]
  accumulated_slip    the slip path, largest over the pairs at the end (sum of |slip
                      increments|, back and forth counted) [m]
  largest_slip_excursion  the largest one-way slide: the largest |s(t_j) - s(t_i)| between
                      consecutive reversals t_i < t_j of s. The reversals are the turning
                      points of s, the first and last output steps included, after every
                      back-and-forth smaller than 5 % of the range of s has been removed,
                      smallest first (the range filter of rainflow counting), so that the
                      elastic jitter of the jump during stick does not cut one slide in
                      two [m]
  mean_slip_range     max - min of s over time: the width of the band the block wandered
                      in (the study's "excursion", docs/convergence-study.md) [m]
Rocking and uplift:
  peak_uplift         the largest opening of any pair at any output step [m]
  peak_rocking_angle  max |u_v(block_base_right) - u_v(block_base_left)| / their distance
                      over time [rad] (stations at the base corners, inside the block)
  tilt_after_shaking  (u_v(block_base_right) - u_v(block_base_left)) / their distance, signed
                      (counter-clockwise positive), its time mean over the last 2 s
                      (tail_window): the permanent tilt once the rocking settles [rad]
  rocking_at_end      the same angle's half range (max - min) / 2 over the last 2 s: the
                      swing left about that tilt; larger than |tilt_after_shaking|: the run
                      ended while the block still rocked [rad]
  (u_v: the vertical displacement, u_y in 2D, u_z in 3D)
Accelerations (horizontal, a_x):
  peak_structure_acceleration  max |a_x| at the station block_top, unfiltered [m/s^2]: not a
                      convergent quantity (each landing is a velocity jump, a Dirac in
                      acceleration); use the low-passed peak or the spectra below
  free_field_pga      max |a_x| at the station free_field, unfiltered [m/s^2]
  block_top_psa_<T>s, free_field_psa_<T>s  5 %-damped pseudo-acceleration of block_top (the
                      floor response spectrum) and of free_field at T = 0.05, 0.1, 0.2, 0.3,
                      0.5, 1 and 2 s (scripts/response_spectrum.py) [m/s^2]
  block_top_peak_acceleration_lowpassed, free_field_peak_acceleration_lowpassed
                      max |a_x| after a zero-phase low-pass at lowpass_frequency_hz: the
                      gain is 1 / (1 + (f / f_c)^8), what a 4th-order Butterworth run
                      forward and backward gives (1/2 at f_c, 1/257 at 2 f_c), applied in
                      the frequency domain to the record padded with zeros to twice its
                      length or more [m/s^2]
  lowpass_frequency_hz  f_c of the low-passed peaks: the resolved frequency of this run,
                      or --lowpass-hz [Hz]
  resolved_frequency_hz  the mesh's resolved frequency vs_min / (8 h_min) (p vs_min /
                      (8 h_e) at degree p; run_info.json gives vs_min / (10 h_min) at p = 1) [Hz]
  high_frequency_share_<station>  for every station of the run: the share of its horizontal
                      acceleration power (Parseval, over the whole record) above the
                      resolved frequency: motion the mesh cannot carry faithfully [-]
  high_frequency_share_<station>_y  the same for the vertical acceleration a_y (0 when a_y
                      is zero throughout, as in a column held vertically) [-]
  high_frequency_share_<station>_total  the same for the acceleration vector (the power of
                      a_x and a_y summed): where one component is small (the vertical at a
                      free-field station under SV), its share says little, the vector's does [-]
"""
import argparse
import json
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "python"))
from response_spectrum import pseudo_acceleration_spectrum, resample_uniform  # noqa: E402
from slipwave import RunFolder  # noqa: E402

# s: from the stiff short-period band to the soil layer's own period (4 H / vs = 0.6 s) and
# beyond; 0.1, 0.3 and 1 s were the earlier free-field keys and are kept.
SPECTRUM_PERIODS = (0.05, 0.1, 0.2, 0.3, 0.5, 1.0, 2.0)
SPECTRUM_STATIONS = ("block_top", "free_field")
# Back-and-forth of s smaller than this share of its range is not a reversal.
EXCURSION_GATE = 0.05


def station(run, name):
    if name not in run.station_names():
        raise SystemExit(f"scene_metrics: error: station '{name}' is missing ({os.path.join(run.path, 'stations', name + '.csv')})")
    return run.station(name)


# The final window of tilt_after_shaking and rocking_at_end [s] (app/run_answers.cpp's).
SETTLE_WINDOW = 2.0


def tail_window(t, v, window=SETTLE_WINDOW):
    """(mean, half range) of v over [t_end - window, t_end]: the trapezoidal time mean and
    (max - min) / 2, the window's start interpolated on its segment; the whole history when
    it is shorter; a single sample is its own mean (numerics/tail_window.hpp)."""
    t, v = np.asarray(t, float), np.asarray(v, float)
    if len(t) == 0:
        return 0.0, 0.0
    start = t[-1] - window
    first = int(np.searchsorted(t, start, side="right"))
    tw, vw = t[first:], v[first:]
    if first > 0 and (len(tw) == 0 or tw[0] > start):
        v0 = v[first - 1] + (start - t[first - 1]) / (t[first] - t[first - 1]) * (v[first] - v[first - 1])
        tw, vw = np.concatenate(([start], tw)), np.concatenate(([v0], vw))
    span = tw[-1] - tw[0]
    mean = float(np.sum(0.5 * (vw[1:] + vw[:-1]) * np.diff(tw)) / span) if span > 0 else float(v[-1])
    return mean, float(0.5 * (vw.max() - vw.min()))


def high_frequency_share(t, a, f_cut, *more):
    """Share of sum |A(f)|^2 above f_cut, A the discrete Fourier transform of a on its own
    uniform samples (Parseval: the share of the signal's power); with more components (a_y,
    ...), of their summed power, the share of the vector's; 0 for records of zeros."""
    high = total = 0.0
    for component in (a,) + more:
        dt, acc = resample_uniform(t, component)
        power = np.abs(np.fft.rfft(acc)) ** 2
        f = np.fft.rfftfreq(len(acc), dt)
        high += power[f > f_cut].sum()
        total += power.sum()
    return float(high / total) if total > 0 else 0.0


def low_passed(t, a, f_cut):
    """(dt, a low-passed at f_cut [Hz], zero phase): gain 1 / (1 + (f/f_cut)^8), the squared
    magnitude of a 4th-order Butterworth filter, i.e. the filter run forward and backward.
    The record is padded with zeros to a power of two at least twice its length, so that the
    end of the record does not wrap onto its start."""
    dt, acc = resample_uniform(t, a)
    n = len(acc)
    nfft = 1 << int(np.ceil(np.log2(max(2 * n, 2))))
    spectrum = np.fft.rfft(acc, nfft)
    f = np.fft.rfftfreq(nfft, dt)
    return dt, np.fft.irfft(spectrum / (1.0 + (f / f_cut) ** 8), nfft)[:n]


def low_passed_peak(t, a, f_cut):
    """max |a| after low_passed [same unit as a]."""
    return float(np.max(np.abs(low_passed(t, a, f_cut)[1])))


def reversals(s, gate):
    """Indices of the reversals of the history s: its turning points (the first and last
    sample included; a plateau counts at its first sample), after every back-and-forth
    smaller than `gate` has been removed, smallest first. An interior pair of turning points
    whose difference is the smallest of all and below gate goes (the legs on either side are
    no smaller, so the rest still alternates); a first or last leg below gate loses its
    turning point, the record's start and end stay."""
    s = np.asarray(s, float)
    if len(s) < 3:
        return list(range(len(s)))
    steps = np.flatnonzero(np.diff(s) != 0) + 1  # first samples of the runs of equal values
    runs = np.concatenate(([0], steps))
    rising = np.sign(np.diff(s[runs]))
    turns = [int(runs[i + 1]) for i in range(len(rising) - 1) if rising[i] != rising[i + 1]]
    keep = [0] + turns + ([len(s) - 1] if not turns or turns[-1] != len(s) - 1 else [])
    while len(keep) > 2:
        legs = np.abs(np.diff(s[keep]))
        k = int(np.argmin(legs))
        if legs[k] >= gate:
            break
        if k == 0:
            del keep[1]
        elif k == len(legs) - 1:
            del keep[-2]
        else:
            del keep[k:k + 2]
    return keep


def largest_excursion(s, gate_share=EXCURSION_GATE):
    """The largest |s(t_j) - s(t_i)| between consecutive reversals of s (reversals with a
    gate of gate_share times the range of s): the largest one-way slide [unit of s]."""
    s = np.asarray(s, float)
    span = float(np.ptp(s)) if len(s) else 0.0
    if span == 0.0:
        return 0.0
    return float(np.max(np.abs(np.diff(s[reversals(s, gate_share * span)]))))


def resolved_frequency(run):
    """vs_min / (8 h_min) from run_info.json, whose resolved frequency is vs_min / (10 h_min)."""
    info = run.run_info()
    return info["resolved_frequency_hz"] * info["points_per_wavelength"] / 8


def psa_keys(name, t, a, periods=SPECTRUM_PERIODS):
    """{'<name>_psa_<T>s': 5 %-damped PSA of a at T} for each period T [s]."""
    dt, acc = resample_uniform(t, a)
    return {f"{name}_psa_{T:g}s": float(v) for T, v in zip(periods, pseudo_acceleration_spectrum(acc, dt, periods))}


def station_measures(records, f_resolved, f_lowpass=None, rocking_span=5.5):
    """The answers read from station records alone. records: {station name: Table with t,
    u_y, a_x, a_y}; f_resolved: the resolved frequency [Hz]; f_lowpass: the low-pass's
    corner [Hz] (default f_resolved); rocking_span: the x distance of block_base_left and
    block_base_right [m] (the default scene's 5.5). Keys as in the module docstring."""
    f_lowpass = f_resolved if f_lowpass is None else f_lowpass
    m = {}
    if "block_base_left" in records and "block_base_right" in records:
        left, right = records["block_base_left"], records["block_base_right"]
        span = rocking_span
        up = "u_z" if "u_z" in left else "u_y"  # the vertical: z in 3D
        m["peak_rocking_angle"] = float(np.max(np.abs(right[up] - left[up])) / span)
        m["tilt_after_shaking"], m["rocking_at_end"] = tail_window(left["t"], (right[up] - left[up]) / span)
    if "block_top" in records:
        m["peak_structure_acceleration"] = float(np.max(np.abs(records["block_top"]["a_x"])))
    if "free_field" in records:
        m["free_field_pga"] = float(np.max(np.abs(records["free_field"]["a_x"])))
    for name in SPECTRUM_STATIONS:
        if name in records:
            r = records[name]
            m.update(psa_keys(name, r["t"], r["a_x"]))
            m[f"{name}_peak_acceleration_lowpassed"] = low_passed_peak(r["t"], r["a_x"], f_lowpass)
    m["lowpass_frequency_hz"] = float(f_lowpass)
    m["resolved_frequency_hz"] = float(f_resolved)
    for name, r in records.items():
        m[f"high_frequency_share_{name}"] = high_frequency_share(r["t"], r["a_x"], f_resolved)
        m[f"high_frequency_share_{name}_y"] = high_frequency_share(r["t"], r["a_y"], f_resolved)
        m[f"high_frequency_share_{name}_total"] = high_frequency_share(r["t"], r["a_x"], f_resolved, r["a_y"])
    return m


def interface_measures(frames):
    """The sliding and uplift answers from an interface's frames (Frames of interface_<name>)."""
    slip = frames.stacked(["slip", "opening"])
    mean_slip = slip["slip"][:, :, 0].mean(axis=1)
    return {
        "net_slip": float(mean_slip[-1]),
        "accumulated_slip": float(np.max(frames.field("accumulated_slip", -1)[:, 0])),
        "largest_slip_excursion": largest_excursion(mean_slip),
        "mean_slip_range": float(np.ptp(mean_slip)),
        "peak_uplift": float(np.max(slip["opening"][:, :, 0])),
    }


def metrics(out, interface="base", lowpass_hz=None, notes=None):
    """Every answer the run folder OUT allows, as {key: float}; what is skipped is appended to
    `notes` (a list) when given."""
    run = RunFolder(out)
    notes = [] if notes is None else notes
    m = {}
    if interface in run.interface_names():
        frames = run.interface(interface)
        if not len(frames):
            raise SystemExit(f"scene_metrics: error: no output steps in {os.path.join(run.path, f'interface_{interface}.xmf')}")
        m.update(interface_measures(frames))
    else:
        notes.append(f"no interface '{interface}' in {run.path}: no slip or uplift answers")
    names = run.station_names()
    if not names:
        if not m:
            raise SystemExit(f"scene_metrics: error: {run.path} holds neither interface_{interface}.xmf nor stations; allowed: the output folder of a run with them")
        notes.append(f"no stations in {run.path}: no acceleration answers")
        return m
    for wanted in ("block_top", "free_field", "block_base_left", "block_base_right"):
        if wanted not in names:
            notes.append(f"no station '{wanted}': its answers are skipped")
    span = 5.5
    if "block_base_left" in names and "block_base_right" in names and run.station_coordinates("block_base_left") is not None:
        span = abs(run.station_coordinates("block_base_right")[0] - run.station_coordinates("block_base_left")[0])
    m.update(station_measures({name: run.station(name) for name in names}, resolved_frequency(run), lowpass_hz, span))
    return m


def unit(key):
    """The unit of an answer of metrics()."""
    if key.startswith("high_frequency_share"):
        return "-"
    if key.endswith("_hz"):
        return "Hz"
    if key in ("peak_rocking_angle", "tilt_after_shaking", "rocking_at_end"):
        return "rad"
    if key in ("net_slip", "accumulated_slip", "largest_slip_excursion", "mean_slip_range", "peak_uplift"):
        return "m"
    return "m/s^2"


def main():
    parser = argparse.ArgumentParser(description="Slip, uplift, rocking, spectra and accelerations of a run.")
    parser.add_argument("out", metavar="OUT")
    parser.add_argument("--interface", default="base")
    parser.add_argument("--lowpass-hz", type=float, help="corner of the low-passed peaks [Hz] (default: the run's resolved frequency)")
    parser.add_argument("--json", metavar="FILE", help="also write the numbers as JSON")
    args = parser.parse_args()
    if args.lowpass_hz is not None and not args.lowpass_hz > 0:
        raise SystemExit(f"scene_metrics: error: --lowpass-hz {args.lowpass_hz:g}; allowed: a frequency > 0 Hz")
    notes = []
    m = metrics(args.out, args.interface, args.lowpass_hz, notes)
    for note in notes:
        print(f"scene_metrics: {note}", file=sys.stderr)
    for key, value in m.items():
        print(f"{key:40s} {value: .5g} {unit(key)}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(m, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())

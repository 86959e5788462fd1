#!/usr/bin/python3
"""What an earthquake engineer reads first from a run of a block on soil (2D).

usage: /usr/bin/python3 scripts/scene_metrics.py OUT [--interface base] [--json FILE]

From the interface output (interface_<name>.xmf and its HDF5 files) and the stations of OUT
(read with the python/slipwave package):
  net_slip            net tangential offset at the end: the mean over the pairs of the
                      tangential jump (structure minus soil) at the last output step [m]
  accumulated_slip    the slip path, largest over the pairs at the end (sum of |slip
                      increments|, back and forth counted) [m]
  peak_uplift         the largest opening of any pair at any output step [m]
  peak_rocking_angle  max |u_y(block_base_right) - u_y(block_base_left)| / their distance
                      over time [rad] (stations at the base corners, inside the block)
  peak_structure_acceleration  max |a_x| at the station block_top [m/s^2]
  free_field_pga      max |a_x| at the station free_field [m/s^2]
  free_field_psa_<T>  5 %-damped pseudo-acceleration of free_field at T = 0.1, 0.3, 1 s [m/s^2]
  high_frequency_share_<station>  share of the horizontal acceleration power (Parseval, over
                      the whole record) above the mesh's resolved frequency vs_min / (8 h_min),
                      at free_field and block_top: motion the mesh cannot carry faithfully [-]
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

SPECTRUM_PERIODS = (0.1, 0.3, 1.0)  # s: short, near the block-soil and the layer periods


def station(run, name):
    if name not in run.station_names():
        raise SystemExit(f"scene_metrics: error: station '{name}' is missing ({os.path.join(run.path, 'stations', name + '.csv')})")
    return run.station(name)


def high_frequency_share(t, a, f_cut):
    """Share of sum |A(f)|^2 above f_cut, A the discrete Fourier transform of a on its own
    uniform samples (Parseval: the share of the signal's power)."""
    dt, acc = resample_uniform(t, a)
    power = np.abs(np.fft.rfft(acc)) ** 2
    f = np.fft.rfftfreq(len(acc), dt)
    return float(power[f > f_cut].sum() / power.sum())


def resolved_frequency(run):
    """vs_min / (8 h_min) from run_info.json, whose resolved frequency is vs_min / (10 h_min)."""
    info = run.run_info()
    return info["resolved_frequency_hz"] * info["points_per_wavelength"] / 8


def metrics(out, interface="base"):
    run = RunFolder(out)
    frames = run.interface(interface)
    if not len(frames):
        raise SystemExit(f"scene_metrics: error: no output steps in interface_{interface}.xmf")
    m = {
        "net_slip": float(np.mean(frames.field("slip", -1)[:, 0])),
        "accumulated_slip": float(np.max(frames.field("accumulated_slip", -1)[:, 0])),
        "peak_uplift": float(np.max(frames.stacked(["opening"])["opening"][:, :, 0])),
    }
    left, right = station(run, "block_base_left"), station(run, "block_base_right")
    # The station's x is not in its CSV: the scene puts them at x = -2.75 and 2.75.
    span = 5.5
    m["peak_rocking_angle"] = float(np.max(np.abs(right["u_y"] - left["u_y"])) / span)
    m["peak_structure_acceleration"] = float(np.max(np.abs(station(run, "block_top")["a_x"])))
    ff = station(run, "free_field")
    m["free_field_pga"] = float(np.max(np.abs(ff["a_x"])))
    dt, acc = resample_uniform(ff["t"], ff["a_x"])
    psa = pseudo_acceleration_spectrum(acc, dt, SPECTRUM_PERIODS)
    for T, value in zip(SPECTRUM_PERIODS, psa):
        m[f"free_field_psa_{T:g}s"] = float(value)
    f_cut = resolved_frequency(run)
    for name in ("free_field", "block_top"):
        s = station(run, name)
        m[f"high_frequency_share_{name}"] = high_frequency_share(s["t"], s["a_x"], f_cut)
    return m


UNITS = {"net_slip": "m", "accumulated_slip": "m", "peak_uplift": "m", "peak_rocking_angle": "rad",
         "peak_structure_acceleration": "m/s^2", "free_field_pga": "m/s^2",
         "high_frequency_share_free_field": "-", "high_frequency_share_block_top": "-"}


def main():
    parser = argparse.ArgumentParser(description="Slip, uplift, rocking and accelerations of a run.")
    parser.add_argument("out", metavar="OUT")
    parser.add_argument("--interface", default="base")
    parser.add_argument("--json", metavar="FILE", help="also write the numbers as JSON")
    args = parser.parse_args()
    m = metrics(args.out, args.interface)
    for key, value in m.items():
        print(f"{key:32s} {value: .5g} {UNITS.get(key, 'm/s^2')}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(m, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())

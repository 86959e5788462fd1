#!/usr/bin/python3
"""Numbers of one run of the default scene for the convergence study (docs/convergence-study.md).

usage: /usr/bin/python3 bench/study/study_metrics.py OUT [--json FILE]

scene_metrics.py's numbers, plus: the block-top 5 %-damped PSA at 0.1, 0.3, 1 s, the
largest single excursion of the mean tangential jump (max - min of the mean slip over time),
the peak accelerations of block_top and free_field low-passed at the mesh's resolved
frequency vs_min/(8 h) (4th-order Butterworth, zero phase, in the frequency domain), and the
share of acceleration power above that frequency at every station.
"""
import argparse
import json
import os
import sys

import numpy as np

SCRIPTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
sys.path.insert(0, os.path.join(SCRIPTS, "..", "python"))
import scene_metrics as sm  # noqa: E402
from response_spectrum import pseudo_acceleration_spectrum, resample_uniform  # noqa: E402
from slipwave import RunFolder  # noqa: E402

STATIONS = ("block_top", "block_base", "block_base_left", "block_base_right", "free_field", "bedrock")


def low_passed_peak(t, a, f_cut):
    dt, acc = resample_uniform(t, a)
    spec = np.fft.rfft(acc)
    f = np.fft.rfftfreq(len(acc), dt)
    gain = 1.0 / (1.0 + (f / f_cut) ** 8)  # |Butterworth 4|^2: zero phase
    return float(np.max(np.abs(np.fft.irfft(spec * gain, len(acc)))))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("out")
    p.add_argument("--json")
    args = p.parse_args()
    run = RunFolder(args.out)
    m = sm.metrics(args.out)
    f_cut = sm.resolved_frequency(run)
    m["f_resolved"] = f_cut
    s = sm.station(run, "block_top")
    dt, acc = resample_uniform(s["t"], s["a_x"])
    for T, v in zip((0.1, 0.3, 1.0), pseudo_acceleration_spectrum(acc, dt, (0.1, 0.3, 1.0))):
        m[f"block_top_psa_{T:g}s"] = float(v)
    m["block_top_peak_lowpass"] = low_passed_peak(s["t"], s["a_x"], f_cut)
    ff = sm.station(run, "free_field")
    m["free_field_peak_lowpass"] = low_passed_peak(ff["t"], ff["a_x"], f_cut)
    for name in STATIONS:
        st = sm.station(run, name)
        m[f"hf_{name}"] = sm.high_frequency_share(st["t"], st["a_x"], f_cut)
        m[f"hf_y_{name}"] = sm.high_frequency_share(st["t"], st["a_y"], f_cut) if np.any(st["a_y"]) else 0.0
    mean_slip = run.interface("base").stacked(["slip"])["slip"][:, :, 0].mean(axis=1)
    m["largest_excursion"] = float(mean_slip.max() - mean_slip.min())
    m["slip_peak_abs"] = float(np.max(np.abs(mean_slip)))
    for k, v in m.items():
        print(f"{k:32s} {v: .5g}")
    if args.json:
        json.dump(m, open(args.json, "w"), indent=1)


if __name__ == "__main__":
    main()

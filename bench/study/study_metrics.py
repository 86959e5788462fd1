#!/usr/bin/python3
"""Numbers of one run of the default scene for the convergence study (docs/convergence-study.md).

usage: /usr/bin/python3 bench/study/study_metrics.py OUT [--json FILE]

scripts/scene_metrics.py's answers, plus the names the study's tables were first written with
(bench/study/study_table.py): f_resolved (vs_min/(8 h)), block_top_peak_lowpass and
free_field_peak_lowpass (scene_metrics' ..._peak_acceleration_lowpassed at that frequency),
hf_<station> and hf_y_<station> (its high_frequency_share_<station>[_y]), largest_excursion
(its mean_slip_range: max - min of the mean tangential jump) and slip_peak_abs (the largest
|mean tangential jump|).
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
from slipwave import RunFolder  # noqa: E402


def main():
    p = argparse.ArgumentParser()
    p.add_argument("out")
    p.add_argument("--json")
    args = p.parse_args()
    run = RunFolder(args.out)
    m = sm.metrics(args.out)
    m["f_resolved"] = sm.resolved_frequency(run)
    m["block_top_peak_lowpass"] = m["block_top_peak_acceleration_lowpassed"]
    m["free_field_peak_lowpass"] = m["free_field_peak_acceleration_lowpassed"]
    for key in [k for k in m if k.startswith("high_frequency_share_") and not k.endswith("_total")]:
        station = key[len("high_frequency_share_"):]
        m["hf_y_" + station[:-2] if station.endswith("_y") else "hf_" + station] = m[key]
    m["largest_excursion"] = m["mean_slip_range"]
    mean_slip = run.interface("base").stacked(["slip"])["slip"][:, :, 0].mean(axis=1)
    m["slip_peak_abs"] = float(np.max(np.abs(mean_slip)))
    for k, v in m.items():
        print(f"{k:32s} {v: .5g}")
    if args.json:
        json.dump(m, open(args.json, "w"), indent=1)


if __name__ == "__main__":
    main()

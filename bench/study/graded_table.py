#!/usr/bin/python3
"""The table of the graded-cell studies of the default scene (bench/cases/default_scene_graded.sh,
bench/cases/default_scene_mass_scaling.sh): each run's block and free-field answers (from
WORK/TAG.json, bench/study/study_metrics.py, and the first large rocking cycle from
WORK/TAG/rigid_block.csv), Richardson's estimate from the three LEVELS runs (coarsest first,
each cell size half the previous; scripts/convergence_check.py's grid_band, the rule of make
run's bands) and every run's distance from it; with --reference, from the estimates in that
JSON file ({answer key: value}) as well. Rows to CSV (benchmark,case,metric,value,unit).

usage: graded_table.py WORK BENCHMARK CSV NP --tags T1,T2,... --levels C,M,F [--reference FILE]
"""
import argparse, json, sys
import numpy as np
sys.path.insert(0, "scripts")
from convergence_check import grid_band

p = argparse.ArgumentParser()
p.add_argument("work"); p.add_argument("benchmark"); p.add_argument("csv"); p.add_argument("np")
p.add_argument("--tags", required=True); p.add_argument("--levels", required=True); p.add_argument("--reference")
a = p.parse_args()
tags, levels = a.tags.split(","), a.levels.split(",")
walls = dict(line.split() for line in open(f"{a.work}/walls.txt"))
def first_cycle(tag):
    # the largest angle of the first large cycle, 2.3-2.8 s (docs/default-scene.md)
    r = np.genfromtxt(f"{a.work}/{tag}/rigid_block.csv", delimiter=",", names=True)
    w = (r["t"] >= 2.3) & (r["t"] <= 2.8)
    return float(r["theta_z"][w].max()) if w.any() else float("nan")
answers = {t: json.load(open(f"{a.work}/{t}.json")) for t in tags}
for t in tags:
    answers[t]["first_cycle"] = first_cycle(t)
reference = json.load(open(a.reference)) if a.reference else {}
keys = [("peak_rocking_angle", 1e3, "largest angle [mrad]"), ("first_cycle", 1e3, "first large cycle [mrad]")] + \
       [(f"block_top_psa_{p}s", 1, f"block-top PSA {p} s [m/s2]") for p in ("0.1", "0.3", "0.5", "1", "2")] + \
       [(f"free_field_psa_{p}s", 1, f"free-field PSA {p} s [m/s2]") for p in ("0.3", "1")]
print("wall [s]: " + ", ".join(f"{t} {walls[t]}" for t in tags))
head = "| answer | " + " | ".join(tags) + " | order | estimate | " + " | ".join(f"{t} from it" for t in tags)
if reference:
    head += " | reference | " + " | ".join(f"{t} from the reference" for t in tags)
print(head + " |")
print("|---" * (head.count("|")) + "|")
rows = []
dev = lambda v, e: [100 * (x - e) / abs(e) if e == e and e != 0 else float("nan") for x in v]
for key, scale, label in keys:
    v = [answers[t][key] * scale for t in tags]
    g = [answers[t][key] * scale for t in reversed(levels)]  # finest first
    band = grid_band(g, [2.0, 2.0], 2.0)
    est = band["extrapolated"] if band else float("nan")
    order = f"{band['order_observed']:.2f}" if band and band["order_observed"] is not None else (band["note"] if band else "")
    line = f"| {label} | " + " | ".join(f"{x:.4g}" for x in v) + f" | {order} | {est:.4g} | " + " | ".join(f"{d:+.1f} %" for d in dev(v, est))
    if reference:
        ref = reference.get(key, float("nan")) * scale
        line += f" | {ref:.4g} | " + " | ".join(f"{d:+.1f} %" for d in dev(v, ref))
    print(line + " |")
    rows += [(key, t, x) for t, x in zip(tags, v)] + [(key, "estimate", est)]
if a.csv:
    with open(a.csv, "a") as out:
        for key, case, x in rows:
            out.write(f"{a.benchmark},{case},{key},{x},\n")
        for t in tags:
            out.write(f"{a.benchmark},{t},wall_time_{a.np}_ranks,{walls[t]},s\n")

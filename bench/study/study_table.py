"""Markdown table of the study runs: /usr/bin/python3 bench/study/study_table.py [TAG ...] (reads $STUDY_DIR, default /tmp/study)."""
import json, sys, os
D = os.environ.get("STUDY_DIR", "/tmp/study")
keys = [("accumulated_slip", 100, "slip path [cm]"), ("net_slip", 100, "net [cm]"), ("largest_excursion", 100, "excursion [cm]"),
        ("peak_uplift", 100, "uplift [cm]"), ("peak_rocking_angle", 1000, "rocking [mrad]"),
        ("block_top_psa_0.1s", 1, "top PSA 0.1 s"), ("block_top_psa_0.3s", 1, "top PSA 0.3 s"), ("block_top_psa_1s", 1, "top PSA 1 s"),
        ("block_top_peak_lowpass", 1, "top peak LP"), ("peak_structure_acceleration", 1, "top peak"),
        ("free_field_pga", 1, "FF PGA"), ("free_field_psa_0.1s", 1, "FF PSA 0.1"), ("free_field_psa_0.3s", 1, "FF PSA 0.3"), ("free_field_psa_1s", 1, "FF PSA 1"),
        ("hf_block_base_left", 100, "HF base_left x [%]"), ("hf_y_block_base_left", 100, "HF base_left y [%]"), ("hf_block_top", 100, "HF top [%]"), ("hf_free_field", 100, "HF FF [%]")]
idx = {}
for line in open(f"{D}/index.txt"):
    tag, np_, rc, wall, opts = line.rstrip("\n").split("|", 4)
    idx[tag] = (wall.split("=")[1], opts)
tags = sys.argv[1:] or list(idx)
print("| run | wall [s] | " + " | ".join(k[2] for k in keys) + " |")
print("|---" * (len(keys) + 2) + "|")
for t in tags:
    f = f"{D}/{t}.json"
    if not os.path.exists(f): continue
    m = json.load(open(f))
    print(f"| {t} | {idx.get(t, ('?',))[0]} | " + " | ".join(f"{m[k] * s:.4g}" for k, s, _ in keys) + " |")

# What of the default scene's answer does not depend on the numerics (issue 21, parts 1 and 3), on its
# linear variant (config/scenes/default_linear.yaml, the scene of the study; the yielding scene's own study is open),
# over its first 3 s (the record's peak at 2.1 s, the first slips, the largest uplift at
# 2.4-3.0 s), on 2 ranks; the full 15 s study is in docs/convergence-study.md and docs/default-scene.md.
#  1. The contact model: the interface twice as stiff (-interface_base_penalty_length 0.015,
#     half the default width/200) moves every answer of scripts/scene_metrics.py by less
#     than 5 % (the issue's bound; 15 s: slip path 4.7 %, the rest <= 1.5 %), except the
#     unfiltered block-top peak (a landing is a velocity jump: no mesh or stiffness
#     converges it; the low-passed peak is checked instead) and the high-frequency shares
#     (they describe the mesh, they are not answers).
#  2. The site response on the scene's 1 m mesh: the free-field PGA, PSA at 0.3 and 1 s and
#     low-passed peak within 5 % of the 0.5 m mesh (-mesh_box_faces 244,120; 15 s: <= 2.2 %).
#     Uplift, rocking and the block's spectra are not within 5 % at 1 m (15 s: 13-28 % to
#     h/2) and are not checked here: make run states their band.
set -eu
. tests/tools/lib.sh
opts="-options_file config/scenes/default_linear.yaml -ts_max_time 3 -output_fields 0 -progress_interval 1e7"
$MPIEXEC -n 2 $SW $opts -output_dir "$WORK/h" > "$WORK/h.log"
$MPIEXEC -n 2 $SW $opts -interface_base_penalty_length 0.015 -output_dir "$WORK/stiff" > "$WORK/stiff.log"
# The 0.5 m run's free-field station alone is compared: no interface frames but the first and
# the last (-output_interval 3; the stations are sampled every step all the same).
$MPIEXEC -n 2 $SW $opts -mesh_box_faces 244,120 -output_interval 3 -output_dir "$WORK/h2" > "$WORK/h2.log"
grep -q "penalty rule physical, length 0.03 m = width 6 m / 200" "$WORK/h.log"
$PY - "$WORK" <<'PY'
import sys
sys.path.insert(0, "scripts")
import scene_metrics as sm
work = sys.argv[1]
# One low-pass corner for all three (the 1 m mesh's resolved frequency), so the peaks compare.
f_cut = sm.resolved_frequency(sm.RunFolder(f"{work}/h"))
m = {run: sm.metrics(f"{work}/{run}", "base", f_cut) for run in ("h", "stiff", "h2")}
ok = True
def check(label, a, b, bound=0.05):
    global ok
    d = abs(b / a - 1) if a else abs(b)
    ok &= d <= bound
    print(f"{'ok' if d <= bound else 'FAIL'} {label}: {a:.5g} -> {b:.5g} ({d:.1%}, allowed {bound:.0%})")
for key in m["h"]:
    if key.startswith("high_frequency_share") or key in ("peak_structure_acceleration", "resolved_frequency_hz", "lowpass_frequency_hz"):
        continue
    check(f"stiffness x 2: {key}", m["h"][key], m["stiff"][key])
for key in ("free_field_pga", "free_field_psa_0.3s", "free_field_psa_1s", "free_field_peak_acceleration_lowpassed"):
    check(f"h -> h/2: {key}", m["h"][key], m["h2"][key])
sys.exit(0 if ok else 1)
PY

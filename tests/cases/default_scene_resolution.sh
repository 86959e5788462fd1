# What of the default scene's answer does not depend on the numerics (issue 21, parts 1 and 3):
# the yielding scene (config/scenes/default.yaml) over its first 2.8 s (the record's peak at
# 2.1 s and the block's first large rocking cycle, 4.0 mrad at 2.6 s), on 2 ranks; the full
# 15 s study is in docs/convergence-study.md ("The yielding scene").
#  1. The contact model: the interface twice as stiff (-interface_base_penalty_length 0.015,
#     half the default width/200) moves every answer of scripts/scene_metrics.py by less
#     than 5 % (the issue's bound; measured <= 1.1 %, 15 s: <= 0.9 %), except the unfiltered
#     block-top peak (a velocity jump is not an answer; the low-passed peak is checked), the
#     high-frequency shares (they describe the mesh) and the three sub-millimetre "slip" and
#     "uplift" measures: the block neither slides nor lifts, and what they read (0.01-0.04 mm)
#     is the penalty springs' own compression, which halves with their stiffness by
#     definition (measured 49.4-50.0 %; checked as such, within 5 % of one half).
#  2. The site on the scene's 1 m mesh against the 0.5 m mesh (-mesh_box_faces 244,120): the
#     free-field PSA at 0.2-2 s and its peak low-passed at the 1 m mesh's 25 Hz within 5 %
#     (measured with the clay's mean dilatation: PSA <= 1.8 %, low-passed peak 4.5 %; 3.7 %
#     and 2.3 % with fully integrated cells). What is not within 5 % over this window is
#     printed, not checked: the block's peak rocking (+12.8 % to h/2), its spectra (0.1-28 %)
#     and the free field's PSA below 0.2 s (9-23 %): the yielding
#     under the block's edges has no length that the mesh resolves; make run states their
#     band (scripts/convergence_check.py) and docs/convergence-study.md their study.
set -eu
. tests/tools/lib.sh
opts="-options_file config/scenes/default.yaml -ts_max_time 2.8 -output_fields 0 -progress_interval 1e7"
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
def check(label, a, b, bound=0.05, expected=1.0):
    global ok
    d = abs(b / a / expected - 1) if a else abs(b)
    ok &= d <= bound
    print(f"{'ok' if d <= bound else 'FAIL'} {label}: {a:.5g} -> {b:.5g} ({d:.1%} from {expected:g} x, allowed {bound:.0%})")
springs = ("net_slip", "largest_slip_excursion", "mean_slip_range", "peak_uplift")
for key in m["h"]:
    if key.startswith("high_frequency_share") or key in ("peak_structure_acceleration", "resolved_frequency_hz", "lowpass_frequency_hz", "accumulated_slip"):
        continue
    check(f"stiffness x 2: {key}", m["h"][key], m["stiff"][key], expected=0.5 if key in springs else 1.0)
# No pair slid: the slip path is zero at both stiffnesses.
ok &= m["h"]["accumulated_slip"] == 0 and m["stiff"]["accumulated_slip"] == 0
print(f"slip path {m['h']['accumulated_slip']:g}, {m['stiff']['accumulated_slip']:g} m (no pair slides)")
site = ["free_field_psa_0.2s", "free_field_psa_0.3s", "free_field_psa_0.5s", "free_field_psa_1s", "free_field_psa_2s", "free_field_peak_acceleration_lowpassed"]
for key in site:
    check(f"h -> h/2: {key}", m["h"][key], m["h2"][key])
print("not converged on 1 m cells over this window (stated, not checked):")
for key in ("peak_rocking_angle", "block_top_psa_0.1s", "block_top_psa_0.5s", "block_top_psa_1s", "block_top_peak_acceleration_lowpassed", "free_field_psa_0.05s", "free_field_psa_0.1s"):
    a, b = m["h"][key], m["h2"][key]
    print(f"  {key}: {a:.5g} -> {b:.5g} ({b / a - 1:+.1%})")
sys.exit(0 if ok else 1)
PY

# What of the default scene's answer does not depend on the numerics (issue 21, parts 1 and 3):
# the yielding scene (config/scenes/default.yaml) over its first 2.8 s (the record's peak at
# 2.1 s and the block's first large rocking cycle, 3.4 mrad at 2.7 s), on 2 ranks; the full
# 15 s study is in docs/convergence-study.md ("The yielding scene").
#  1. The contact model: the interface twice as stiff (-interface_base_penalty_length 0.015,
#     half the default width/200) moves every answer of scripts/scene_metrics.py by less
#     than 5 % (the issue's bound; measured with the scene of 2026-11-28: the tilt after
#     shaking, a 2 s mean of 11 microrad, 1.2 %, every other answer <= 0.1 %), except the unfiltered
#     block-top peak (a velocity jump is not an answer; the low-passed peak is checked), the
#     high-frequency shares (they describe the mesh) and the three sub-millimetre "slip" and
#     "uplift" measures: the block neither slides nor lifts, and what they read (0.01-0.04 mm)
#     is the penalty springs' own compression, which halves with their stiffness by
#     definition (measured 50.0-50.6 %; checked as such, within 5 % of one half).
#  2. The site on the scene's 1 m cells against 0.5 m cells, the full 15 s: the scene less its
#     block, interface and stations, on a column 4 m wide with the scene's free-field sides
#     (the site is layered: a narrow column is the same 1D site; one rank each, together).
#     Its surface PSA at 0.2-2 s and its peak low-passed at the 1 m mesh's 25 Hz within 5 %
#     (measured with the scene's clay: PSA <= 0.4 %, low-passed peak 3.6 %). Printed, not
#     checked: PSA(0.05 s) and PSA(0.1 s) (+18 %, +8 %): periods the 1 m mesh carries at 4
#     and 2 cells per wavelength of the softened clay, and the yielding soil's spikes. The
#     block's own answers at 0.5 m (rocking, spectra: not within 5 %, docs/default-scene.md)
#     take the full scene: bench/cases/default_scene_convergence.sh, and make run's band.
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
opts="-options_file config/scenes/default.yaml -ts_max_time 2.8 -output_fields 0 -progress_interval 1e7"
$MPIEXEC -n 2 $SW $opts -output_dir "$WORK/h" > "$WORK/h.log"
$MPIEXEC -n 2 $SW $opts -interface_base_penalty_length 0.015 -output_dir "$WORK/stiff" > "$WORK/stiff.log"
grep -vE "^(mesh_file|regions|material_block|material_soil_far|interface|station)" config/scenes/default.yaml > "$WORK/site.yaml"
site="-options_file $WORK/site.yaml -input_record config/records/el_centro_1940_ns.csv -regions rock,soil_low,soil_mid,soil,air -void_regions air -mesh_dim 2
 -region_rock_box -2,2,-20,0 -region_soil_low_box -2,2,0,10 -region_soil_mid_box -2,2,10,20 -region_soil_box -2,2,20,30 -region_air_box -2,2,30,40 -mesh_box_lower -2,-20
 -mesh_box_upper 2,40 -station_coordinates 0,30 -station_names free_field -output_fields 0 -progress_interval 1e7"
together $SW $site -mesh_box_faces 4,60 -output_dir "$WORK/site_h" > "$WORK/site_h.log"
together $SW $site -mesh_box_faces 8,120 -output_dir "$WORK/site_h2" > "$WORK/site_h2.log"
together_wait
grep -q "penalty rule physical, length 0.03 m = width 6 m / 200" "$WORK/h.log"
$PY - "$WORK" <<'PY'
import sys
sys.path.insert(0, "scripts")
import scene_metrics as sm
work = sys.argv[1]
f_cut = sm.resolved_frequency(sm.RunFolder(f"{work}/h"))
m = {run: sm.metrics(f"{work}/{run}", "base", f_cut) for run in ("h", "stiff")}
site = {run: sm.station_measures({"free_field": sm.RunFolder(f"{work}/{run}").station("free_field")}, f_cut) for run in ("site_h", "site_h2")}
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
for key in ("free_field_psa_0.2s", "free_field_psa_0.3s", "free_field_psa_0.5s", "free_field_psa_1s", "free_field_psa_2s", "free_field_peak_acceleration_lowpassed"):
    check(f"site, 1 m -> 0.5 m: {key}", site["site_h"][key], site["site_h2"][key])
print("the site's short periods, 1 m -> 0.5 m (stated, not checked):")
for key in ("free_field_psa_0.05s", "free_field_psa_0.1s", "free_field_pga"):
    a, b = site["site_h"][key], site["site_h2"][key]
    print(f"  {key}: {a:.5g} -> {b:.5g} ({b / a - 1:+.1%})")
sys.exit(0 if ok else 1)
PY

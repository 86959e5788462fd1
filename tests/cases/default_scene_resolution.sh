# What of the default scene's answer does not depend on the numerics (issue 21, parts 1 and 3):
# the yielding scene (config/scenes/default.yaml) over its first 2.8 s (the record's peak at
# 2.1 s and the block's first large rocking cycle, 3.1 mrad at 2.7 s), on 2 ranks; the full
# 15 s study is in docs/default-scene.md and docs/convergence-study.md.
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
#     block's answers are part 3's.
#  3. The block's answers against the next finer cells where they matter: the scene's mesh
#     file with the window's cells graded to 0.0625 m instead of 0.125 m (gmsh -setnumber
#     fine 0.0625 config/scenes/default.geo; the far field stays 1 m, part 2 covers it): every
#     block answer of scripts/scene_metrics.py (rocking angle, the rocking left and the tilt
#     over the last 2 s, the block-top PSA at 0.05-2 s and its low-passed peak) within 5 % (the
#     issue's bound; over the first 4 s the same two levels differ by 0.2-2.1 %,
#     docs/convergence-study.md, "Which limit"; measured here 0.0-1.1 %), and the free
#     field's the same to 1 % (0.0-0.5 %: its cells, 34 m from the window, are the same at both
#     levels; what reaches it from the block is the scattered field, about 3 % of its motion by
#     the L2 check of default_scene.sh (2.7 %), so a 5 % change there is 0.15 % of it).
#     The tilt after shaking of a 2.8 s run is the mean of
#     a block still swinging (-0.10 mrad against a half range of 4.1 mrad): its change is judged
#     against the swing, within 5 % of it (measured 0.2 %; as a fraction of itself 7.5 %; the
#     full 15 s tilt, 0.44 mrad after the strong motion, is make run's answer, with its band).
#     Printed, not checked: the sub-millimetre slip and uplift measures (the springs'
#     compression, 7-8 %).
#     The full 15 s of the scene and its 2 m companion: make run and
#     bench/cases/default_scene_convergence.sh.
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
opts="-options_file config/scenes/default.yaml -ts_max_time 2.8 -output_fields 0 -progress_interval 1e7"
$MPIEXEC -n 2 $SW $opts -output_dir "$WORK/h" > "$WORK/h.log"
$MPIEXEC -n 2 $SW $opts -interface_base_penalty_length 0.015 -output_dir "$WORK/stiff" > "$WORK/stiff.log"
gmsh -2 config/scenes/default.geo -setnumber fine 0.0625 -format msh41 -o "$WORK/fine.msh" > "$WORK/fine.gmsh.log"
$MPIEXEC -n 2 $SW $opts -mesh_file "$WORK/fine.msh" -output_dir "$WORK/fine" > "$WORK/fine.log"
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
m = {run: sm.metrics(f"{work}/{run}", "base", f_cut) for run in ("h", "stiff", "fine")}
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
print("the block's answers, the window's cells 0.125 m -> 0.0625 m:")
for key in m["h"]:
    if key.startswith("high_frequency_share") or key in ("peak_structure_acceleration", "resolved_frequency_hz", "lowpass_frequency_hz", "accumulated_slip"):
        continue
    if key in springs:
        print(f"  {key}: {m['h'][key]:.5g} -> {m['fine'][key]:.5g} ({m['fine'][key] / m['h'][key] - 1:+.1%}; stated, not checked)")
    elif key == "tilt_after_shaking":
        # Mid-shaking (the last 2 s of 2.8 s) the mean tilt is a small remainder of the swing:
        # its change is judged against the swing it is the mean of.
        d = abs(m["fine"][key] - m["h"][key]) / m["h"]["rocking_at_end"]
        ok &= d <= 0.05
        print(f"{'ok' if d <= 0.05 else 'FAIL'} window 0.125 m -> 0.0625 m: {key}: {m['h'][key]:.5g} -> {m['fine'][key]:.5g} ({d:.1%} of the swing, +-{m['h']['rocking_at_end']:.4g} rad; allowed 5%)")
    else:
        check(f"window 0.125 m -> 0.0625 m: {key}", m["h"][key], m["fine"][key], bound=0.01 if key.startswith("free_field") else 0.05)
for key in ("free_field_psa_0.2s", "free_field_psa_0.3s", "free_field_psa_0.5s", "free_field_psa_1s", "free_field_psa_2s", "free_field_peak_acceleration_lowpassed"):
    check(f"site, 1 m -> 0.5 m: {key}", site["site_h"][key], site["site_h2"][key])
print("the site's short periods, 1 m -> 0.5 m (stated, not checked):")
for key in ("free_field_psa_0.05s", "free_field_psa_0.1s", "free_field_pga"):
    a, b = site["site_h"][key], site["site_h2"][key]
    print(f"  {key}: {a:.5g} -> {b:.5g} ({b / a - 1:+.1%})")
sys.exit(0 if ok else 1)
PY

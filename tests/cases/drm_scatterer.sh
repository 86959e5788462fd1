# Domain Reduction Method with a scatterer (issue 12 item 1: "only the scattered field reaches
# the absorbing boundary"): a stiff footing (10 m x 5 m, vs 1200) embedded at the surface of a
# half-space (rho 2000, vp 400, vs 200), plane SV at 20 deg, Ricker f0 = 3 Hz, h = 1.25 m.
# A narrow model (120 m x 60 m) and a wide one (360 m x 150 m, whose boundary echoes of the
# scattered wave reach the stations after the compared window: 2 x 150 m / 400 m/s after the
# scattering, t > 1.45 s in the narrow model's clock) must give the same motion around the footing.
# The two models' clocks differ by the free field's delay between their reference points
# (upstream, deepest e nodes: (-58.75, 58.75) and (-178.75, 148.75)): p dx + q dz.
# What the narrow model's absorbing boundary sends back can only be part of the scattered
# field (a dashpot reflects at most what reaches it, |R| <= 1): the difference must stay below
# the scattered field itself (the wide model minus the same model without the footing), the
# criterion of tests/cases/free_field_reflection.sh. Measured: about 1/6 of it.
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
common="-regions soil,footing -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -region_footing_box -5,5,-5,0
 -bc_left_type absorbing -bc_right_type absorbing -bc_bottom_type absorbing -input_method drm -drm_wave sv -drm_incidence_angle 20 -drm_stf ricker
 -drm_f0 3 -drm_t0 0.4 -drm_amplitude 0.1 -output_fields 0 -progress_interval 100000
 -station_coordinates 0,0,-20,0,20,0,0,-20 -station_names top,left,right,below"
stiff="-material_footing_rho 2400 -material_footing_vp 2000 -material_footing_vs 1200"
soft="-material_footing_rho 2000 -material_footing_vp 400 -material_footing_vs 200"
narrow="-region_soil_box -60,60,-60,0 -mesh_box_faces 96,48 -mesh_box_lower -60,-60 -mesh_box_upper 60,0 -ts_max_time 1.45"
wide="-region_soil_box -180,180,-150,0 -mesh_box_faces 288,120 -mesh_box_lower -180,-150 -mesh_box_upper 180,0 -ts_max_time 2.1"
# The three runs are independent (one rank each): two at a time, the wide one first
# (tests/tools/together.sh).
together $SW $common $stiff $wide -output_dir "$WORK/wide" > "$WORK/wide.log"
together $SW $common $stiff $narrow -output_dir "$WORK/narrow" > "$WORK/narrow.log"
together $SW $common $soft $narrow -output_dir "$WORK/free" > "$WORK/free.log"
together_wait
$PY - "$WORK" <<'PY'
import sys
import numpy as np
w = sys.argv[1]
p, q = np.sin(np.radians(20)) / 200, np.cos(np.radians(20)) / 200
shift = p * (178.75 - 58.75) + q * (148.75 - 58.75)
r = lambda d, n: np.genfromtxt(f"{w}/{d}/stations/{n}.csv", delimiter=",", names=True)
ok = True
for n in ("top", "left", "right", "below"):
    a, b, f = r("narrow", n), r("wide", n), r("free", n)
    t = a["t"]
    diff = max(np.abs(a[c] - np.interp(t + shift, b["t"], b[c])).max() for c in ("v_x", "v_y"))
    scat = max(np.abs(np.interp(t + shift, b["t"], b[c]) - np.interp(t, f["t"], f[c])).max() for c in ("v_x", "v_y"))
    peak = max(np.abs(a[c]).max() for c in ("v_x", "v_y"))
    print(f"footing: {n}: narrow - wide {diff / peak:.2e} of the peak, scattered field {scat / peak:.2e} (bound: below the scattered field)")
    ok &= diff < scat
sys.exit(0 if ok else 1)
PY

# Free-field lateral boundaries add no spurious reflection (issue 5 item 2). Site: 30 m of soil
# (vs 200) on 10 m of rock (vs 800) over the absorbing base, SV Ricker
# f0 = 2 Hz; the narrow model is 20 m wide with free-field sides.
# 1. Scatterer-free: the 2D model must move exactly like a 1D column (the same site with one
#    cell and the vertical motion held everywhere, i.e. rollers): the side force is built so
#    that a height-only motion is an exact discrete solution (here with 2 % Rayleigh damping), so the records (centre and
#    both edges) agree to round-off. Bound 1e-10 of each quantity's peak (issue: 1 %; u and v
#    agree to ~1e-12, a carries the round-off of K u over m).
# 2. A stiff footing (4 m x 2 m, vs 1200) embedded at the surface centre scatters the wave.
#    Reference: the same footing in a 400 m wide model with rollers, whose sides are 190 m
#    from the stations, so their reflections arrive after 2 x 190 m / 200 m/s = 1.9 s after
#    the scattering (t > 2.6 s, beyond the 2.5 s compared); no damping here. What differs between the two models
#    is what the free-field sides send back of the scattered wave. A dashpot boundary reflects
#    at most the wave that reaches it (|R| <= 1), so the difference is bounded by the scattered
#    field itself; the test requires it below 1 % of the peak surface velocity (issue) and
#    below the scattered field's own peak near the side (wide model minus the free field).
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
site="-regions rock,soil,footing -material_soil_rho 1900 -material_soil_vp 500 -material_soil_vs 200 -material_rock_rho 2400 -material_rock_vp 1600
 -material_rock_vs 800 -region_footing_box -2,2,28,30 -bc_bottom_type absorbing -input_wave sv -input_boundary bottom -input_stf ricker -input_f0 2
 -input_t0 0.6 -input_amplitude 0.1 -ts_max_time 2.5 -output_fields 0 -progress_interval 100000"
damped="-damping_ratio 0.02 -damping_frequencies 1,8 -ts_dt 1.5e-4"
undamped="-ts_dt 3.5e-4"
soilfoot="-material_footing_rho 1900 -material_footing_vp 500 -material_footing_vs 200"
stiff="-material_footing_rho 2400 -material_footing_vp 2000 -material_footing_vs 1200"
narrow="-mesh_box_faces 20,40 -mesh_box_lower -10,-10 -mesh_box_upper 10,30 -region_soil_box -10,10,0,30 -bc_left_type freefield -bc_right_type freefield
 -station_coordinates -10,30,-9,30,0,30,10,30,0,10 -station_names left,edge,centre,right,centre_10"
# The five runs are independent (one rank each): two at a time, the wide one first
# (tests/tools/together.sh); the checks after them.
together $SW $site $undamped $stiff -mesh_box_faces 400,40 -mesh_box_lower -200,-10 -mesh_box_upper 200,30 -region_soil_box -200,200,0,30 \
  -bc_left_type fixed -bc_left_components y -bc_right_type fixed -bc_right_components y \
  -station_coordinates -10,30,-9,30,0,30,10,30,0,10 -station_names left,edge,centre,right,centre_10 -output_dir "$WORK/wide" > "$WORK/wide.log"
together $SW $site $damped $soilfoot $narrow -output_dir "$WORK/free" > "$WORK/free.log"
# The 1D column: one cell (inside the footing box, which has the soil here), the x-motion only;
# stations at the same heights.
together $SW $site $damped $soilfoot -mesh_box_faces 1,40 -mesh_box_lower -2,-10 -mesh_box_upper -1,30 -region_soil_box -10,10,0,30 -constrain_components y \
  -station_coordinates -2,30,-2,30,-2,30,-2,30,-2,10 -station_names left,edge,centre,right,centre_10 -output_dir "$WORK/column" > "$WORK/column.log"
together $SW $site $undamped $soilfoot $narrow -output_dir "$WORK/free0" > "$WORK/free0.log"
together $SW $site $undamped $stiff $narrow -output_dir "$WORK/narrow" > "$WORK/narrow.log"
together_wait
$CHECK stations-equal "$WORK/column" "$WORK/free" --names left,edge,centre,right,centre_10 --tol 1e-10
$PY - "$WORK" <<'PY'
import sys
import numpy as np
w = sys.argv[1]
r = lambda d, n: np.genfromtxt(f"{w}/{d}/stations/{n}.csv", delimiter=",", names=True)
ok = True
peak = np.abs(r("free0", "centre")["v_x"]).max()
for n in ("left", "edge", "centre", "right"):
    a, b, f = r("narrow", n), r("wide", n), r("free0", n)
    diff = max(np.abs(a[c] - b[c]).max() for c in ("v_x", "v_y")) / peak
    scat = max(np.abs(b[c] - f[c]).max() for c in ("v_x", "v_y")) / peak
    print(f"footing: station {n}: narrow (free-field sides) - wide (rollers) {diff:.2e} of the peak (bound 1e-2 and the scattered field {scat:.2e})")
    ok &= diff <= 1e-2 and diff <= scat
sys.exit(0 if ok else 1)
PY

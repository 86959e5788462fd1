# Darendeli's curve from each element's own sigma'_0 (issue 22: "mean effective stress from the
# geostatic stage"): -material_<r>_mean_effective_stress geostatic. The site of
# tests/cases/hysteretic_free_field.sh (30 m of soil, vs 200, over rock; 2 % constant-Q) with
# the soil a PI 15 clay under gravity (9.81), a geostatic stage, then the Ricker SV pulse of
# 0.3 m/s; free-field sides, 1 m cells.
# 1. The stage's sigma'_0 = rho g d K / M in a laterally confined layer (sigma_h = lambda/M
#    sigma_v; K / M = 0.78667 for vp 500, vs 200): the report's range is the top and the
#    bottom elements', at depths d = 0.5 and 29.5 m: 7.3314 and 432.55 kPa (bound 1e-4: the
#    static solve's tolerance).
# 2. The free-field columns compute their sigma'_0 from their own weight, the interior from the
#    stage's stresses: a laterally uniform site then moves as one, the side stations as the
#    centre's to round-off (1e-10 of the peak of u_x, v_x, a_x; measured 3e-14, 2e-13, 4e-11).
#    With the columns at the 1 atm curve instead (their scales left out), 4 % of the peak
#    velocity: the check sees a column that does not follow.
#    The same at element degree 2 (2 m elements, the GLL points; measured 5e-13, 6e-11).
# 3. 1 and 2 ranks: the same stations (1e-10, a: 1e-9, as tests/cases/hysteretic_ranks.sh).
# 4. A restart from step 3500 writes the straight run's stations and energy byte for byte (the
#    scales come from the checkpoint: the stage does not run again).
# 5. The curve's dependence matters: the surface peak velocity against the same site with one
#    sigma'_0 at mid-depth (186 kPa, K0 = 0.5 as the default scene's sublayers) is printed
#    (measured +12.2 %; on 0.5 m cells +11.3 %, each peak within 0.6 % of the 1 m one).
# 6. Without the geostatic stage, or with a strength cap, the run stops at once with one line,
#    before the output folder is made (core/option_rules.cpp).
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
site="-regions rock,soil -material_soil_rho 1900 -material_soil_vp 500 -material_soil_vs 200 -material_soil_damping_ratio 0.02
 -material_soil_model hysteretic -material_soil_backbone darendeli -material_soil_plasticity_index 15
 -material_rock_rho 2400 -material_rock_vp 1600 -material_rock_vs 800 -material_rock_damping_ratio 0.02 -bc_bottom_type absorbing
 -input_boundary bottom -input_wave sv -input_stf ricker -input_f0 2 -input_t0 0.6 -input_amplitude 0.3 -ts_max_time 2.1 -ts_dt 3e-4
 -output_fields 0 -progress_interval 100000
 -mesh_box_faces 20,40 -mesh_box_lower -10,-10 -mesh_box_upper 10,30 -region_soil_box -10,10,0,30 -bc_left_type freefield -bc_right_type freefield
 -station_coordinates -10,30,-9,30,0,30,10,30,0,10 -station_names left,edge,centre,right,centre_10"
geo="$site -gravity 9.81 -geostatic_stage true -material_soil_mean_effective_stress geostatic"
together $SW $geo -output_dir "$WORK/geo" > "$WORK/geo.log"
together $SW $site -material_soil_mean_effective_stress 186.4e3 -output_dir "$WORK/uniform" > "$WORK/uniform.log"
together_wait
together $SW $geo -ts_max_steps 3500 -checkpoint_interval 3500 -output_dir "$WORK/first" > /dev/null
together $SW $geo -element_degree 2 -mesh_box_faces 10,20 -ts_dt 2e-4 -output_dir "$WORK/geo_p2" > /dev/null
together_wait
if $SW $site -gravity 9.81 -material_soil_mean_effective_stress geostatic -output_dir "$WORK/no_stage" > /dev/null 2> "$WORK/no_stage.err"; then
  echo "geostatic sigma'_0 without the stage was accepted"; exit 1
fi
grep "sigma'_0 from the geostatic stage" "$WORK/geo.log"
$PY - "$WORK" <<'PY'
import re, sys
import numpy as np
work = sys.argv[1]
ok = True
def report(what, good, detail):
    global ok
    ok = ok and good
    print(f"{'ok' if good else 'FAILED'}: {what}: {detail}")
line = [l for l in open(f"{work}/geo.log") if "from the geostatic stage" in l and "kPa" in l][0]
low, high = (float(x) * 1e3 for x in re.search(r"stage ([0-9.e+-]+) \.\. ([0-9.e+-]+) kPa", line).groups())
rho, vp, vs, g = 1900.0, 500.0, 200.0, 9.81
mu, M = rho * vs**2, rho * vp**2
ratio = (M - 2 * mu + 2 * mu / 3) / M  # K / M
for name, got, depth in (("top", low, 0.5), ("bottom", high, 29.5)):
    want = rho * g * depth * ratio
    report(f"sigma'_0 of the {name} element", abs(got - want) <= 1e-4 * want, f"{got:.6g} Pa against rho g d K/M = {want:.6g} Pa (d = {depth} m; bound 1e-4)")
def stations(run):
    return {n: np.loadtxt(f"{work}/{run}/stations/{n}.csv", delimiter=",", skiprows=1) for n in ("left", "edge", "centre", "right")}
for run in ("geo", "geo_p2"):
    s = stations(run)
    for n in ("left", "edge", "right"):
        worst = max(np.abs(s[n][:, j] - s["centre"][:, j]).max() / np.abs(s["centre"][:, j]).max() for j in (1, 3))
        worst_a = np.abs(s[n][:, 5] - s["centre"][:, 5]).max() / np.abs(s["centre"][:, 5]).max()
        report(f"{run}: {n} against centre", worst <= 1e-10 and worst_a <= 1e-9, f"u_x, v_x {worst:.2e} (bound 1e-10), a_x {worst_a:.2e} (bound 1e-9) of the peak")
s = stations("geo")
peak_geo = np.abs(s["centre"][:, 3]).max()
peak_uniform = np.abs(stations("uniform")["centre"][:, 3]).max()
print(f"surface peak v_x: {peak_geo:.4f} m/s with each element's sigma'_0, {peak_uniform:.4f} m/s with 186.4 kPa everywhere ({100 * (peak_geo / peak_uniform - 1):+.1f} %)")
sys.exit(0 if ok else 1)
PY
# 3. Ranks.
$MPIEXEC -n 2 $SW $geo -output_dir "$WORK/geo_np2" > /dev/null
$CHECK stations-equal "$WORK/geo" "$WORK/geo_np2" --names left,edge,centre,right,centre_10 --tol 1e-10 --tol-a 1e-9
# 4. Restart.
cp -r "$WORK/first" "$WORK/resumed"
$SW $geo -restart "$WORK/resumed/checkpoint.bin" -output_dir "$WORK/resumed" | grep -E "^restart|^done"
cmp "$WORK/resumed/energy.csv" "$WORK/geo/energy.csv"
for s in left edge centre right centre_10; do cmp "$WORK/resumed/stations/$s.csv" "$WORK/geo/stations/$s.csv"; done
echo "restart: energy.csv and the five stations byte for byte equal to the straight run"
# 6. The refusals.
cat "$WORK/no_stage.err"
[ "$(wc -l < "$WORK/no_stage.err")" -eq 1 ]
grep -q "^slipwave: error: -material_soil_mean_effective_stress = geostatic without the geostatic stage" "$WORK/no_stage.err"
[ ! -e "$WORK/no_stage" ] || { echo "the refused run left its output folder"; exit 1; }
if $SW $geo -material_soil_strength 5e4 -output_dir "$WORK/capped" 2> "$WORK/capped.err" > /dev/null; then echo "a cap with geostatic sigma'_0 was accepted"; exit 1; fi
cat "$WORK/capped.err"
grep -q "^slipwave: error: -material_soil_strength with -material_soil_mean_effective_stress geostatic" "$WORK/capped.err"
[ ! -e "$WORK/capped" ] || { echo "the refused run left its output folder"; exit 1; }

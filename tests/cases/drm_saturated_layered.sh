# Domain Reduction Method on a layered saturated site (issue 24 part 5: the undrained free field
# of each saturated layer, docs/drm.md "Saturated sites"): 30 m of saturated soil (rho 1900,
# drained vp 400, vs 200) on a saturated stiffer layer (rho 2100, drained vp 1200, vs 600), both
# n 0.4 with incompressible grains and K_f 1e8 Pa (M = K_f / n = 2.5e8 Pa), hydraulic
# conductivity 0 (undrained), 2D, 120 m x 60 m, h = 1.25 m, absorbing sides and base, the DRM
# layer 2 cells in, Ricker f0 = 2 Hz; SV at 15 deg, P at 20 deg and vertical P (every wave
# propagates in both layers: undrained vp 540.0 and 1248.6 m/s).
# Reference: undrained, each layer is an elastic one with lambda + alpha^2 M, so the surface
# motion is the Thomson-Haskell propagator's (tests/tools/haskell_propagator.py, an
# independent implementation: state-vector propagation) with the undrained P speeds; the
# incident wave is given at the reference point (the upstream e nodes and the deepest e
# nodes, e = h), as in drm_layered_oblique.sh.
# The reference tells the layers apart: with the drained P speeds the P 20 deg surface motion
# is 48 % off, with the lower layer's alone drained 4.1 % (measured): above the bound.
# Bounds (issue: 2 % inside, 1 % outside): both surface velocity components at three points
# within 2 % relative L2; outside the layer (the first ring of cells) the velocity below 1 % of
# the incident peak and the excess pore pressure below 1 % of its peak at the interior
# stations; the energy balance to 1e-9 (the layer's forces and pressure sources are input
# work). Measured: inside 0.14-0.58 %, outside at most 0.49 % (velocity) and 0.66 % (pressure),
# energy 2e-14.
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
sat="-material_%s_saturated -material_%s_porosity 0.4 -material_%s_fluid_bulk_modulus 1e8 -material_%s_hydraulic_conductivity 0"
model="-regions rock,soil -material_soil_rho 1900 -material_soil_vp 400 -material_soil_vs 200 -material_rock_rho 2100 -material_rock_vp 1200
 -material_rock_vs 600 $(printf -- "$sat" soil soil soil soil) $(printf -- "$sat" rock rock rock rock) -fluid_cavitation_pressure none
 -region_soil_box -60,60,-30,0 -mesh_box_faces 96,48 -mesh_box_lower -60,-60 -mesh_box_upper 60,0
 -bc_left_type absorbing -bc_right_type absorbing -bc_bottom_type absorbing -input_method drm -drm_stf ricker -drm_f0 2 -drm_t0 0.6
 -drm_amplitude 0.1 -ts_max_time 4 -output_fields 0 -progress_interval 100000
 -station_coordinates -40,0,0,0,40,0,0,-15,0,-45,-59.5,-20,59.5,-45,0,-59.5,-59.5,-59.5
 -station_names a,b,c,mid,deep,left_out,right_out,base_out,corner_out"
together $SW $model -drm_wave sv -drm_incidence_angle 15 -output_dir "$WORK/sv" > "$WORK/sv.log"
together $SW $model -drm_wave p -drm_incidence_angle 20 -output_dir "$WORK/p" > "$WORK/p.log"
together $SW $model -drm_wave p -drm_incidence_angle 0 -output_dir "$WORK/p0" > "$WORK/p0.log"
together_wait
cat "$WORK/sv.log" "$WORK/p.log"
for run in sv p p0; do $CHECK energy "$WORK/$run/energy.csv" --max-error 1e-9; done
$PY - "$WORK" <<'PY'
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
from haskell_propagator import surface_velocity_ricker
w, e = sys.argv[1], 1.25
M = 1e8 / 0.4
vp_soil, vp_rock = np.sqrt((1900 * 400**2 + M) / 1900), np.sqrt((2100 * 1200**2 + M) / 2100)  # undrained (alpha = 1)
print(f"undrained vp: soil {vp_soil:.1f} m/s, rock {vp_rock:.1f} m/s")
ok = True
for run, wave, angle in (("sv", "sv", 15), ("p", "p", 20), ("p0", "p", 0)):
    for n, x in (("a", -40.0), ("b", 0.0), ("c", 40.0)):
        d = np.genfromtxt(f"{w}/{run}/stations/{n}.csv", delimiter=",", names=True)
        ref = surface_velocity_ricker(d["t"], 2.0, 0.6, 0.1, [(30.0, 1900, vp_soil, 200)], (2100, vp_rock, 600), wave, angle, 30 - e, x + 60 - e)
        err = np.sqrt(np.sum((d["v_x"] - ref[0]) ** 2 + (d["v_y"] - ref[1]) ** 2) / np.sum(ref[0] ** 2 + ref[1] ** 2))
        print(f"{wave} {angle} deg: surface x = {x:g}: relative L2 error against the undrained propagator {err:.2e} (bound 2e-2)")
        ok &= err <= 2e-2
    p_peak = max(np.abs(np.genfromtxt(f"{w}/{run}/stations/{n}.csv", delimiter=",", names=True)["p_excess"]).max() for n in ("mid", "deep"))
    for n in ("left_out", "right_out", "base_out", "corner_out"):
        d = np.genfromtxt(f"{w}/{run}/stations/{n}.csv", delimiter=",", names=True)
        peak = max(np.abs(d["v_x"]).max(), np.abs(d["v_y"]).max()) / 0.1
        pp = np.abs(d["p_excess"]).max() / p_peak
        print(f"{wave} {angle} deg: {n}: velocity peak {peak:.2e} of the incident peak, excess pore pressure {pp:.2e} of its peak inside ({p_peak:.4g} Pa) (bounds 1e-2)")
        ok &= peak <= 1e-2 and pp <= 1e-2
sys.exit(0 if ok else 1)
PY

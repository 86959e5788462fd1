#!/usr/bin/env bash
# Sliding threshold of a block on saturated soil under its own weight (issue 10, interface
# test), on a drained and on a noflow interface. A dry block (2 m x 0.5 m, rho 2400) rests on
# a 0.5 m saturated base (mixture rho 2000, stiff skeleton vp 3000, vs 1800, porosity 0.3,
# k = 0, water) through a Mohr-Coulomb interface (phi = 30 deg, c = 0, psi = 0, E = G = 1e10
# Pa/m); the water table is 0.25 m above the interface, so the pore pressure at the contact is
# p_h = rho_f g 0.25 = 2452.5 Pa (the uplift of a foundation below the water table). The
# geostatic stage brings it to rest under gravity; then the base is driven horizontally with a
# slowly ramped acceleration a(t) = 5 t m/s^2 (its quasi-static: the block on its stick springs
# rings at 460 Hz).
# Expected (effective-stress Mohr-Coulomb, rigid block of mass m = 1200 kg per m, weight
# W = m g = 11772 N per m of width, contact area A = 2 m^2 per m):
#  1. geostatic state: the total normal traction carries the weight, mean sigma_N = -W/A =
#     -11772 Pa (within 1 %), and the effective one is sigma_N + p = -(W/A - p_h) = -9319.5 Pa
#     (within 1 %); the mean is over the pairs with their lumped areas (0.125 m at the ends,
#     0.25 m inside).
#  2. drained interface (excess pore pressure 0 at the contact, p = p_h): the block slips when
#     m a = tan(phi) (W - A p_h), a* = 4.4838 m/s^2 (g tan(phi) = 5.664 on total stress);
#     after that its acceleration stays at a*. Onset (the base's acceleration when the relative
#     velocity reaches 1e-4 m/s: 6 ms or 0.7 % late in the rigid-plastic model) and the mean
#     block acceleration after it, each within 2 %.
#  3. noflow interface (k = 0: the contact keeps the excess pressure the ramp's undrained
#     loading of the base makes): the onset follows the same criterion with the pore pressure
#     of the pairs' soil nodes at that instant, a* = tan(phi) (W - sum_p A_p p_p) / m, within
#     2 %, and it differs from the drained onset by more than 2 % (the excess pressure is
#     measured, not assumed zero). After the onset the noflow contact is not checked here:
#     sliding on undrained soil is saturated_interface_sliding.sh's (the friction lag,
#     docs/saturated-soil.md).
#  4. The energy balance closes to 1e-9 in both runs.
set -eu
. tests/tools/lib.sh
printf 'time,acceleration\n0,0\n2,10\n' > "$WORK/ramp.csv"
stations="-station_side soil -station_coordinates 1,0,1,0.75"
names="base,block"
for j in 0 1 2 3 4 5 6 7 8; do stations="$stations,$(echo "$j * 0.25" | bc -l),0.5"; names="$names,c$j"; done
O="-mesh_box_faces 8,4 -mesh_box_upper 2,1 -regions base,block -region_block_box 0,2,0.5,1
 -material_base_rho 2000 -material_base_vp 3000 -material_base_vs 1800 -material_base_saturated -material_base_porosity 0.3 -material_base_hydraulic_conductivity 0
 -material_block_rho 2400 -material_block_vp 3000 -material_block_vs 1800
 -interfaces slide -interface_slide_regions base,block -interface_slide_phi 30 -interface_slide_psi 0 -interface_slide_c 0 -interface_slide_E 1e10 -interface_slide_G 1e10
 -gravity 9.81 -water_table 0.75 -geostatic_stage -bc_bottom_type_x velocity -bc_bottom_type_y fixed -bc_bottom_stf record -bc_bottom_record $WORK/ramp.csv
 -bc_bottom_baseline_correction 0 -ts_max_time 1.1 -output_interval 0.1 -progress_interval 100000 $stations -station_names $names"
for fluid in drained noflow; do
  $SW $O -interface_slide_fluid $fluid -output_dir "$WORK/$fluid" > "$WORK/$fluid.log" || { cat "$WORK/$fluid.log"; exit 1; }
  grep -E "^geostatic|^interface slide:" "$WORK/$fluid.log"
  $CHECK energy "$WORK/$fluid/energy.csv" --max-error 1e-9
done
$PY - "$WORK" <<'PY'
import math
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
from frames import Frames
work = sys.argv[1]
tan_phi, g, m, area, p_h = math.tan(math.radians(30)), 9.81, 2400 * 2 * 0.5, 2.0, 1000 * 9.81 * 0.25
W = m * g
A_p = np.array([0.125] + [0.25] * 7 + [0.125])  # lumped contact areas of the 9 pairs [m^2 per m]
ok, onset = True, {}
def check(what, got, want, tol):
    global ok
    err = abs(got / want - 1)
    ok &= err <= tol
    print(f"  {what}: {got:.6g} (expected {want:.6g}), error {err:.2e} (bound {tol:g})")
for fluid in ("drained", "noflow"):
    st = {n: np.genfromtxt(f"{work}/{fluid}/stations/{n}.csv", delimiter=",", names=True) for n in ["base", "block"] + [f"c{j}" for j in range(9)]}
    t, base, block = st["base"]["t"], st["base"], st["block"]
    p = np.array([st[f"c{j}"]["p"] for j in range(9)])
    f = Frames(f"{work}/{fluid}", "interface_slide")
    order = np.argsort(f.geometry[:, 0])  # pairs left to right, as the stations c0 .. c8
    sn = f.field("sigma_N", 0)[:, 0][order]
    # The interface output's own pore pressure and effective traction (soil side of each pair)
    # against the stations on the pairs' soil nodes.
    check("interface output: geostatic mean pore pressure [Pa]", np.sum(A_p * f.field("pore_pressure", 0)[:, 0][order]) / area, np.sum(A_p * p[:, 0]) / area, 1e-9)
    sn_eff = f.field("sigma_N_effective", 0)[:, 0][order]
    print(f"{fluid}:")
    check("geostatic mean total normal traction [Pa]", np.sum(A_p * sn) / area, -W / area, 0.01)
    check("geostatic mean effective normal traction [Pa]", np.sum(A_p * (sn + p[:, 0])) / area, -(W / area - p_h), 0.01)
    check("  the same from the interface output's sigma_N_effective [Pa]", np.sum(A_p * sn_eff) / area, -(W / area - p_h), 0.01)
    i = int(np.argmax(np.abs(block["v_x"] - base["v_x"]) > 1e-4))
    onset[fluid] = base["a_x"][i]
    expected = tan_phi * (W - np.sum(A_p * p[:, i])) / m
    print(f"  onset at t = {t[i]:.4f} s, contact pore pressure sum {np.sum(A_p * p[:, i]):.1f} N/m (A p_h = {area * p_h:.1f})")
    check("sliding threshold: base acceleration at the onset [m/s^2]", onset[fluid], expected, 0.02)
    if fluid == "drained":
        check("  (drained: the closed form tan(phi) (W - A p_h) / m)", expected, tan_phi * (W - area * p_h) / m, 1e-9)
        after = t > t[i] + 0.02
        check("block acceleration while sliding [m/s^2]", block["a_x"][after].mean(), tan_phi * (W - area * p_h) / m, 0.02)
diff = abs(onset["noflow"] / onset["drained"] - 1)
print(f"noflow vs drained onset: {onset['noflow']:.4f} vs {onset['drained']:.4f} m/s^2, {diff:.1%} apart (must be > 2 %)")
sys.exit(0 if ok and diff > 0.02 else 1)
PY

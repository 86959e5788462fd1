#!/usr/bin/env bash
# Scene config/scenes/foundation_saturated.yaml (the default scene's block foundation on a
# saturated sand layer, water table at the surface, El Centro at 0.3 g, free-field sides), with a
# noflow and with a drained interface. Coarsened to 2 m cells (the block 8 m wide, 4 cells, so
# its edges lie on nodes) and shortened to the first 6 s (the strong motion's start, where the
# block slides). Checks, with where each expected number comes from:
#  1. Geostatic state: the interface's area-weighted mean normal traction (lumped widths 1 m
#     at the block's edges, 2 m inside) equals the block's weight per area
#     rho g h = 2400 * 9.81 * 10 = 235440 Pa within 1 %; the water table is at the contact, so
#     the pore pressure there is p_h = 0 and this is also the effective traction (the soil-side
#     station block_base reads p = 0 at t = 0, to 1e-6 of rho g h).
#  2. The energy balance closes with the Darcy dissipation booked (bound 1e-12, the saturated
#     tests' level; interfaces that stick, slip and reopen included), and Darcy takes a share.
#  3. The interface's fluid condition is in effect: drained holds the excess pore pressure at
#     the contact's soil nodes at 0 (block_base, soil side: |p_excess| <= 1e-6 of rho g h);
#     noflow seals the water table under the block, so excess pressure builds at the contact
#     (> 10 % of rho g h) and 1 m below the block's edges it peaks higher than with the
#     drained contact 1 m above (draining time 1 m^2 / c_v = 0.2 s, c_v = 4.5 m^2/s from the
#     report, against shaking periods of 0.2-1 s: at least 1.3 x).
#  4. The block slides on both (accumulated slip > 1 cm at some pair), and the slip differs
#     between the two (the fluid condition changes the friction), by more than 1 mm somewhere.
set -eu
. tests/tools/lib.sh
O="-options_file config/scenes/foundation_saturated.yaml -mesh_box_faces 60,30 -region_block_box -4,4,30,40 -ts_max_time 6 -output_interval 0.1 -progress_interval 100
 -station_side soil -station_coordinates 0,30,-3,29,3,29 -station_names block_base,soil_left,soil_right"
for fluid in noflow drained; do
  $SW $O -interface_base_fluid $fluid -output_dir "$WORK/$fluid" > "$WORK/$fluid.log" || { cat "$WORK/$fluid.log"; exit 1; }
  grep -E "pore fluid boundaries|^geostatic|^interface base:|^done" "$WORK/$fluid.log"
  $CHECK energy "$WORK/$fluid/energy.csv" --max-error 1e-12
done
$PY - "$WORK" <<'PY'
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
from frames import Frames
work = sys.argv[1]
weight = 2400 * 9.81 * 10.0
ok = True
def expect(cond, text):
    global ok
    ok &= bool(cond)
    print(("  " if cond else "  FAILED: ") + text)
peak, slips = {}, {}
for fluid in ("noflow", "drained"):
    print(fluid + ":")
    f = Frames(f"{work}/{fluid}", "interface_base")
    x = f.geometry[:, 0]
    sn = f.field("sigma_N", 0)[:, 0]
    slips[fluid] = np.array([a.ravel() for a in f.series("accumulated_slip")])
    # The law's normal traction is the effective one, sigma_N + p of the soil side's pairs.
    expect(np.allclose(f.field("sigma_N_effective", -1), f.field("sigma_N", -1) + f.field("pore_pressure", -1), rtol=0, atol=1e-9 * weight),
           "interface output: sigma_N_effective = sigma_N + pore_pressure")
    w = np.where(np.isclose(np.abs(x), 4.0), 1.0, 2.0)
    mean = np.sum(w * sn) / np.sum(w)
    expect(abs(mean / -weight - 1) <= 0.01, f"geostatic mean normal traction {mean:.0f} Pa (weight/area {-weight:.0f}), error {abs(mean / -weight - 1):.2e} (bound 1e-2)")
    base = np.genfromtxt(f"{work}/{fluid}/stations/block_base.csv", delimiter=",", names=True)
    expect(abs(base["p"][0]) <= 1e-6 * weight, f"pore pressure at the contact at t = 0: {base['p'][0]:.3g} Pa")
    energy = np.genfromtxt(f"{work}/{fluid}/energy.csv", delimiter=",", names=True)
    share = energy["darcy_dissipated"][-1] / energy["input_work"][-1]
    expect(share > 0, f"Darcy dissipation {energy['darcy_dissipated'][-1]:.4g} J/m, {share:.2%} of the input work")
    contact = np.abs(base["p_excess"]).max()
    below = max(np.abs(np.genfromtxt(f"{work}/{fluid}/stations/{s}.csv", delimiter=",", names=True)["p_excess"]).max() for s in ("soil_left", "soil_right"))
    peak[fluid] = below
    print(f"  peak excess pore pressure: contact {contact:.4g} Pa, 1 m below the edges {below:.4g} Pa")
    if fluid == "drained":
        expect(contact <= 1e-6 * weight, "drained contact: no excess pore pressure there")
    else:
        expect(contact > 0.1 * weight, "noflow contact: excess pore pressure builds under the block (> 10 % of rho g h)")
    expect(slips[fluid].max() > 0.01, f"largest accumulated slip {slips[fluid].max() * 1000:.1f} mm (> 10 mm)")
ratio = peak["noflow"] / peak["drained"]
expect(ratio >= 1.3, f"excess pressure 1 m below the edges, noflow / drained: {ratio:.2f} (>= 1.3)")
diff = np.abs(slips["noflow"][-1] - slips["drained"][-1]).max()
expect(diff > 1e-3, f"final slip, noflow - drained: largest difference {diff * 1000:.1f} mm over the pairs (> 1 mm); mean slip {slips['noflow'][-1].mean() * 1000:.1f} vs {slips['drained'][-1].mean() * 1000:.1f} mm")
sys.exit(0 if ok else 1)
PY

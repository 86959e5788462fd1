#!/usr/bin/env bash
# The interface law in effective stress: interface_incline_block.sh (a 1 m x 1 m stiff block,
# rho 2400, on a 0.5 m stiff base, gravity tilted by beta = 30 deg, Mohr-Coulomb interface
# phi = 20 deg, c = 0, E = G = 1e10 Pa/m, starting from sigma_N0 = -rho g H cos(beta)) with
# the base saturated (k = 0) under a water table at elevation 1.0 m (measured against the
# tilted gravity) and the interface drained (-interface_slide_fluid drained), so the pore
# pressure at the two pairs' soil nodes (x = 0 and 1, y = 0.5; A = 0.5 m^2 each) is the
# hydrostatic p_h = rho_f g (1.0 - z), z = -x sin(beta) + y cos(beta): 5562 and 10467 Pa.
# Expected (rigid block, Coulomb sliding on the effective normal force; both pairs stay in
# effective compression, the smaller margin being 8617 - 5562 Pa):
#   a = g sin(beta) - tan(phi) (W cos(beta) - sum_p A_p p_h,p) / m = 3.0285 m/s^2,
# against 1.8128 m/s^2 on total stress. interface_checks.py incline takes the pore pressure
# as the equivalent cohesion c = -tan(phi) sum_p A_p p_h,p / A. Bound 0.5 % as the dry test.
# (With the default noflow interface the undrained base's excess pressure adds to p_h and the
# block slides 4 % faster; no closed form for that, so it is not checked here.)
set -eu
. tests/tools/lib.sh
beta=30; phi=20
read -r gx gy sn0 ceq <<<"$($PY -c "
import math
b = math.radians($beta)
ph = [1000 * 9.81 * (1.0 - (-x * math.sin(b) + 0.5 * math.cos(b))) for x in (0.0, 1.0)]
print(math.sin(b), -math.cos(b), -2400 * 9.81 * 1.0 * math.cos(b), -math.tan(math.radians($phi)) * sum(0.5 * p for p in ph))")"
block="-mesh_box_faces 1,6 -mesh_box_upper 1,1.5 -regions base,block -region_block_box 0,1,0.5,1.5
 -material_base_rho 2400 -material_base_vp 3000 -material_base_vs 1800 -material_base_saturated -material_base_porosity 0.3 -material_base_hydraulic_conductivity 0
 -material_block_rho 2400 -material_block_vp 3000 -material_block_vs 1800
 -interfaces slide -interface_slide_regions base,block -interface_slide_phi $phi -interface_slide_psi 0 -interface_slide_E 1e10 -interface_slide_G 1e10
 -interface_slide_sigma_N0 $sn0 -gravity 9.81 -gravity_direction $gx,$gy -water_table 1.0 -bc_bottom_type fixed -ts_max_time 0.5 -output_fields 0
 -progress_interval 100 -station_coordinates 0.5,1.0 -station_names centre"
$SW $block -interface_slide_fluid drained -output_dir "$WORK/drained" > "$WORK/drained.log" || { cat "$WORK/drained.log"; exit 1; }
grep -E "^interface slide|pore fluid" "$WORK/drained.log"
$PY tests/tools/interface_checks.py incline "$WORK/drained/stations/centre.csv" --beta $beta --phi $phi --c "$ceq" --area 1 --mass 2400 --t1 0.05 --t2 0.5 --tol 0.005

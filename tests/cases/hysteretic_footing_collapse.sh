#!/usr/bin/env bash
# A footing's collapse load on a yielding soil (-material_<r>_dilatation, issue 21): the
# elements must let the soil flow at constant volume, or they lock and carry any load.
# A rigid strip footing, B = 2 m wide (0.5 m tall, glued to the soil: rough), on a weightless
# soil 12 m x 6 m (rho 1800, vp 245, vs 100 m/s: Gmax 18 MPa), hysteretic with an MKZ
# hyperbola (gamma_r 5e-3) capped at tau_max = k = 20 kPa (reached at a strain of 1.4e-3: an
# elastic-plastic soil of strength k), fixed sides and bottom (absorbing ones cannot hold a
# static load), no damping (constant-Q memory relaxes the soil's stress under a held load, and
# its strength with it). A vertical force ramped over 2 s to f q_u B, then held to 3 s.
# Expected (Prandtl 1920; Hill 1950; Chen 1975, "Limit analysis and soil plasticity", 3.5):
# the limit pressure of a strip on a weightless plane-strain solid of shear strength k (von
# Mises: k = sqrt(J2) at flow, where s_zz = 0) is q_u = (2 + pi) k = 102.8 kPa, rough or smooth.
# A finite element solution approaches it from above as the cells shrink.
#  1. mean dilatation (the default of a hysteretic region): at 0.95 q_u the footing comes to
#     rest on 0.25 m cells (B/h = 8; settlement speed over the last 0.5 s below 1 mm/s and
#     less than 0.1 m settled; measured 7.2 mm); at 1.2 q_u it fails (more than B/4 = 0.5 m
#     settled at 3 s; measured 1.4 m; 1.1 q_u crept at 1.6 mm/s: the collapse load on B/h = 8
#     lies at 1.1-1.2 q_u).
#  2. Gauss points (-material_soil_dilatation gauss, full integration): it locks: 1.2 q_u is
#     held (measured 11.1 mm settled): the collapse it predicts is not the soil's (Nagtegaal,
#     Parks & Rice 1974).
#  3. energy balance to 1e-9 in every run; the 0.95 q_u run on 2 ranks as on 1 to 1e-9.
# FOOTING_FINE=1 (bench/cases/hysteretic_footing_collapse.sh: 8 times the cost) adds the
# 0.125 m cells (B/h = 16): mean at rest at 0.95 q_u (measured 8.6 mm), collapsed at 1.1 q_u
# (0.65 m; 1.05 q_u is held: the collapse load there lies at 1.05-1.1 q_u, nearer q_u), and
# Gauss points still holding 1.2 q_u (16.5 mm): refining does not cure the locking.
set -eu
. tests/tools/lib.sh
printf 'time,value\n0,0\n2,1\n' > "$WORK/ramp.csv"
QU=$($PY -c "import math; print((2 + math.pi) * 20e3 * 2)")
O="-mesh_box_lower 0,0 -mesh_box_upper 12,6.5 -regions soil,air,footing -region_soil_box 0,12,0,6 -region_air_box 0,12,6,6.5 -region_footing_box 5,7,6,6.5 -void_regions air
 -material_soil_rho 1800 -material_soil_vp 245 -material_soil_vs 100 -material_soil_model hysteretic -material_soil_backbone mkz -material_soil_reference_strain 5e-3 -material_soil_strength 20e3
 -material_footing_rho 2400 -material_footing_vp 3000 -material_footing_vs 1800 -material_footing_model rigid
 -bc_left_type fixed -bc_right_type fixed -bc_bottom_type fixed
 -structure_load_region footing -structure_load_stf record -structure_load_record $WORK/ramp.csv
 -ts_max_time 3 -output_fields 0 -progress_interval 1000000 -station_interval 0.005 -station_side structure -station_coordinates 6,6.25 -station_names footing"
run() { # NAME FACES LOAD/q_u [options]
  name=$1 faces=$2 load=$($PY -c "print(-$3 * $QU)"); shift 3
  $SW $O -mesh_box_faces "$faces" -structure_load_force 0,"$load" -output_dir "$WORK/$name" "$@" > "$WORK/$name.log" || { cat "$WORK/$name.log"; exit 1; }
  $CHECK energy "$WORK/$name/energy.csv" --max-error 1e-9
}
run mean_h_095 48,26 0.95
run mean_h_120 48,26 1.2
run gauss_h_120 48,26 1.2 -material_soil_dilatation gauss
if [ -n "${FOOTING_FINE:-}" ]; then
  run mean_h2_095 96,52 0.95
  run mean_h2_110 96,52 1.1
  run gauss_h2_120 96,52 1.2 -material_soil_dilatation gauss
fi
$MPIEXEC -n 2 $SW $O -mesh_box_faces 48,26 -structure_load_force 0,"$($PY -c "print(-0.95 * $QU)")" -output_dir "$WORK/mean_h_095_np2" > "$WORK/mean_h_095_np2.log" || { cat "$WORK/mean_h_095_np2.log"; exit 1; }
grep -qE "region soil .*; mean dilatation" "$WORK/mean_h_095.log" || { echo "FAIL: the report does not say the mean dilatation"; exit 1; }
grep -q "strength 2e+04 Pa" "$WORK/mean_h_095.log" || { echo "FAIL: the model's strength is not the cap, 20 kPa"; exit 1; }
$PY - "$WORK" "${FOOTING_FINE:-}" <<'PY'
import sys
import numpy as np
work, fine = sys.argv[1], bool(sys.argv[2])
sys.path.insert(0, "tests/tools")
from verdict import Verdict
verdict = Verdict()
check = verdict.check
def footing(name):
    a = np.genfromtxt(f"{work}/{name}/rigid_footing.csv", delimiter=",", names=True)
    t, settled = a["t"], -a["u_y"]
    return settled, (np.interp(3.0, t, settled) - np.interp(2.5, t, settled)) / 0.5, float(np.interp(3.0, t, settled))
rest = [("mean_h_095", "mean, B/h = 8, 0.95 q_u"), ("gauss_h_120", "Gauss points, B/h = 8, 1.2 q_u")]
collapse = [("mean_h_120", "mean, B/h = 8, 1.2 q_u")]
if fine:
    rest += [("mean_h2_095", "mean, B/h = 16, 0.95 q_u"), ("gauss_h2_120", "Gauss points, B/h = 16, 1.2 q_u")]
    collapse += [("mean_h2_110", "mean, B/h = 16, 1.1 q_u")]
for name, what in rest:
    _, v, s = footing(name)
    check(f"{what}: at rest", abs(v) < 1e-3 and s < 0.1, f"settled {1e3 * s:.1f} mm, {1e3 * v:.3f} mm/s over 2.5-3 s (bounds 1 mm/s, 0.1 m)")
for name, what in collapse:
    _, v, s = footing(name)
    check(f"{what}: collapse", s > 0.5, f"settled {s:.3f} m at 3 s (bound B/4 = 0.5 m), {v:.3f} m/s")
one, _, _ = footing("mean_h_095")
two, _, _ = footing("mean_h_095_np2")
d = np.max(np.abs(one - two)) / np.max(np.abs(one))
check("2 ranks as 1", d < 1e-9, f"{d:.1e} of the settlement (bound 1e-9)")
verdict.exit()
PY

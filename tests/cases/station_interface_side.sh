# Stations on an interface (issue 8, part 5). The footing of tests/cases/interface_mpi.sh
# (thrown at (1, -0.5) m/s onto a Mohr-Coulomb interface: pairs stick, slip and open), with a
# station `base` on the interface at (10, 10), where soil and footing cells hold different
# nodes of a split pair, and two stations 1e-6 m above and below it, each inside one body.
#  1. On 1, 2 and 3 ranks `base` records the structure side (the default of -station_side)
#     and the report says so; the records agree to round-off, 1e-10 of each quantity's peak
#     (the same sums in a different order, as tests/cases/mpi_ranks.sh).
#  2. What `base` records is the footing's motion: it equals `above` to 1e-5 of the peak (the
#     other nodes of the cell weigh 1e-6 m / 0.5 m = 2e-6 there), and differs from `below`
#     (the soil) by more than 1e-2 of the peak, as the pairs slip and open.
#  3. With -station_side soil (on 2 ranks) it records the soil: it equals `below` to 1e-5.
set -eu -o pipefail
. tests/tools/lib.sh
opts="-mesh_box_faces 40,22 -mesh_box_upper 20,11 -regions soil,footing -region_soil_box 0,20,0,11 -region_footing_box 8,12,10,11
 -material_soil_rho 2000 -material_soil_E 1e8 -material_soil_nu 0.3 -material_footing_rho 2500 -material_footing_E 3e10 -material_footing_nu 0.2
 -interfaces base -interface_base_regions soil,footing -interface_base_phi 30 -bc_bottom_type fixed -initial_velocity_footing 1,-0.5
 -ts_max_time 0.2 -output_fields 0 -progress_interval 100000
 -station_coordinates 10,10,10,10.000001,10,9.999999 -station_names base,above,below"
for n in 1 2 3; do
  $MPIEXEC -n $n $SW $opts -output_dir "$WORK/np$n" > "$WORK/np$n.log"
  grep "station base" "$WORK/np$n.log"
  grep -q "station base at (10, 10) lies on interface base (split nodes): records the structure side (footing)" "$WORK/np$n.log"
  ! grep -q "station above\|station below" "$WORK/np$n.log"
done
for n in 2 3; do $CHECK stations-equal "$WORK/np1" "$WORK/np$n" --names base,above,below --tol 1e-10; done
$MPIEXEC -n 2 $SW $opts -station_side soil -output_dir "$WORK/soil" | grep "station base"
$PY - "$WORK" <<'PY'
import sys
import numpy as np
work = sys.argv[1]
def rec(d, name):
    return np.genfromtxt(f"{work}/{d}/stations/{name}.csv", delimiter=",", skip_header=1)[:, 1:]
def diff(a, b):
    # Largest difference of u, v and a, each scaled by its own peak (2D: 2 columns each).
    return max(np.max(np.abs(a[:, k:k + 2] - b[:, k:k + 2])) / np.max(np.abs(a[:, k:k + 2])) for k in (0, 2, 4))
base, above, below = rec("np1", "base"), rec("np1", "above"), rec("np1", "below")
d_above, d_below, d_soil = diff(base, above), diff(base, below), diff(rec("soil", "base"), rec("soil", "below"))
print(f"structure side: base vs above {d_above:.2e} (bound 1e-5), base vs below {d_below:.2e} (need > 1e-2); soil side: base vs below {d_soil:.2e} (bound 1e-5)")
sys.exit(0 if d_above <= 1e-5 and d_below > 1e-2 and d_soil <= 1e-5 else 1)
PY

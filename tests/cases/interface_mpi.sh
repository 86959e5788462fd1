# Rank independence with the interface cut by the partition. A stiff footing (4 m x 1 m,
# E 3e10) embedded in the surface of a 20 m x 11 m soil (E 1e8, nu 0.3, fixed base), thrown at
# (1, -0.5) m/s through a Mohr-Coulomb interface (phi 30): pairs stick, slip and open. On 2
# ranks METIS puts the small footing on the rank of the soil under part of it, so pairs have
# their two nodes on different ranks: the report line "N pairs have their two nodes on
# different ranks" must give N > 0 (else the test proves nothing). The law is applied per pair
# from the same jumps, so every force is the same sum in a different order: the station
# records must agree to round-off, 1e-10 of each quantity's peak (as tests/cases/mpi_ranks.sh,
# issue 2), and so must the interface output per pair id at every frame (sigma_N,
# accumulated_slip, opening, status), each to 1e-10 of its peak. The accumulated slip must reach
# 1 mm and some pairs must be open, so sliding and opening are both exercised.
# The default contact damping (0.1) is on: its dashpots act across the cut pairs too, and the
# energy budget with their work booked (contact_damped, which must be > 0) closes to 1e-9.
set -eu -o pipefail
. tests/tools/lib.sh
IC="$PY tests/tools/contact_checks.py"
# -energy_interval 1: this test reads the ledger at every step (row count, per-step rows).
opts="-mesh_box_faces 40,22 -mesh_box_upper 20,11 -regions soil,footing -region_soil_box 0,20,0,11 -region_footing_box 8,12,10,11
 -material_soil_rho 2000 -material_soil_E 1e8 -material_soil_nu 0.3 -material_footing_rho 2500 -material_footing_E 3e10 -material_footing_nu 0.2
 -interfaces base -interface_base_regions soil,footing -interface_base_phi 30 -bc_bottom_type fixed -initial_velocity_footing 1,-0.5
 -ts_max_time 0.2 -output_interval 0.005 -progress_interval 100 -energy_interval 1
 -station_coordinates 10,11,10,10,2,11 -station_names footing_top,soil_under,soil_far"
$SW $opts -output_dir "$WORK/np1"
$MPIEXEC -n 2 $SW $opts -output_dir "$WORK/np2" | tee "$WORK/np2.log"
cut=$(sed -n 's/.* \([0-9][0-9]*\) pairs have their two nodes on different ranks.*/\1/p' "$WORK/np2.log")
echo "pairs with their two nodes on different ranks on 2 ranks: ${cut:-none} (need > 0)"
[ -n "$cut" ] && [ "$cut" -gt 0 ]
$CHECK stations-equal "$WORK/np1" "$WORK/np2" --names footing_top,soil_under,soil_far --tol 1e-10
$IC interface-equal "$WORK/np1" "$WORK/np2" --name base --fields sigma_N,accumulated_slip,opening,status --tol 1e-10 \
  --min-peak 1e-3 --min-peak-fields accumulated_slip
$IC open-traction "$WORK/np2" --name base --min-open 10
$CHECK energy "$WORK/np2/energy.csv" --max-error 1e-9 --min-rows 1000
$PY -c "
import sys, numpy as np
d = np.genfromtxt('$WORK/np2/energy.csv', delimiter=',', names=True)
print(f'contact dashpots took {d[\"contact_damped\"][-1]:.4e} J (need > 0)')
sys.exit(0 if d['contact_damped'][-1] > 0 else 1)"

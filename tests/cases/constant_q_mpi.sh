# Constant-Q damping on 1 and 2 ranks (issue 8): the memory variables live on each rank's cells
# and their forces are summed like K u, so the station records agree to round-off: 1e-10 of
# the peak of each quantity (the bound of tests/cases/mpi_ranks.sh). The site is 2D (a stiff
# footing on a damped layer, elastic rock; absorbing sides) so the partition cuts damped and
# elastic cells; 2 % Rayleigh damping on top, so both kinds of damping run together.
# The energy ledger must close with the memory forces booked as `anelastic`: relative balance
# error <= 1e-9 (the bound of tests/cases/energy_closed.sh), on both runs.
set -eu
. tests/tools/lib.sh
site="-regions rock,soil,footing -material_soil_rho 1900 -material_soil_vp 500 -material_soil_vs 200 -material_soil_damping_ratio 0.05
 -material_rock_rho 2400 -material_rock_vp 1600 -material_rock_vs 800 -material_footing_rho 2400 -material_footing_vp 2000 -material_footing_vs 1200
 -region_footing_box -2,2,28,30 -mesh_box_faces 20,40 -mesh_box_lower -10,-10 -mesh_box_upper 10,30 -region_soil_box -10,10,0,30
 -bc_bottom_type absorbing -bc_left_type absorbing -bc_right_type absorbing -input_boundary bottom -input_wave sv -input_stf ricker -input_f0 2
 -input_t0 0.6 -input_amplitude 0.1 -damping_ratio 0.02 -damping_frequencies 1,8 -ts_max_time 1.5 -output_fields 0 -progress_interval 100000
 -station_coordinates -10,30,0,30,10,30,-10,0 -station_names left,centre,right,left_base"
$SW $site -output_dir "$WORK/1" > "$WORK/1.log"
$MPIEXEC -n 2 $SW $site -output_dir "$WORK/2" > "$WORK/2.log"
$CHECK stations-equal "$WORK/1" "$WORK/2" --names left,centre,right,left_base --tol 1e-10
$CHECK energy "$WORK/1/energy.csv" --max-error 1e-9
$CHECK energy "$WORK/2/energy.csv" --max-error 1e-9
$PY - "$WORK" <<'PY'
import sys
import numpy as np
d = np.genfromtxt(f"{sys.argv[1]}/1/energy.csv", delimiter=",", names=True)
a, net = d["anelastic"][-1], d["input_work"][-1] - d["absorbed"][-1]
print(f"energy: the constant-Q mechanisms took {a:.4e} J of the {net:.4e} J kept by the model (input work - absorbed; Rayleigh {d['damped'][-1]:.4e} J)")
sys.exit(0 if a > 0 else 1)
PY

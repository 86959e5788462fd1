# Divergence guard. No legal input can overflow the model any more: every number is bounded by
# the rule table and a record with absurd values (1e308 m/s^2) is refused when it is read,
# naming the file and line, before any step or output (so the guard's non-finite path, which
# names the node, field and input, is a defence against defects only). What a run can still
# reach is the guard's energy check: kinetic + strain energy above -energy_growth_limit times
# the energy put in. On the 1D column (100 m, absorbing base, Ricker 0.1 m/s at 5 Hz) the
# stored energy reaches half the input work while the pulse is inside the column (the base
# dashpot takes the other half of the equivalent force's work as the wave enters; measured
# 0.499), so a limit of 0.3 must stop the run with its one line (step, time, energies, the
# step against the stable limit), exit non-zero, and leave only finite values in its output
# files; at the default limit 2 the same run completes.
set -eu
. tests/tools/lib.sh
printf 't,a\n0,0\n0.01,1e308\n0.02,1e308\n1,1e308\n' > "$WORK/huge.csv"
col="-mesh_box_faces 1,100 -mesh_box_upper 1,100 -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200
 -bc_bottom_type absorbing -input_wave sv -input_boundary bottom -constrain_components y -ts_max_time 0.6"
if $SW $col -input_stf record -input_record "$WORK/huge.csv" -input_baseline_correction 0 -output_dir "$WORK/huge" 2> "$WORK/err_huge.txt"; then
  echo "the absurd record was accepted"; exit 1
fi
cat "$WORK/err_huge.txt"
grep -Eq "^slipwave: error: -input_record \(CSV\): .*/huge\.csv:3: acceleration 1e\+?308 m/s\^2 is absurd" "$WORK/err_huge.txt"
[ "$(wc -l < "$WORK/err_huge.txt")" -eq 1 ]
[ ! -e "$WORK/huge/energy.csv" ]
ricker="-input_stf ricker -input_f0 5 -input_t0 0.24 -input_amplitude 0.1"
if $SW $col $ricker -energy_growth_limit 0.3 -energy_interval 1 -output_dir "$WORK/out" 2> "$WORK/err.txt"; then
  echo "the run did not stop"; exit 1
fi
cat "$WORK/err.txt"
grep -Eq "^slipwave: error: diverged at step [0-9]+, t = [0-9.e+-]+ s: kinetic \+ strain energy [0-9.e+-]+ J exceeds 0\.3 x the energy put in \([0-9.e+-]+ J\); the time step [0-9.e+-]+ s may be above the stable limit [0-9.e+-]+ s" "$WORK/err.txt"
[ "$(wc -l < "$WORK/err.txt")" -eq 1 ]
$PY scripts/check_output.py "$WORK/out"
$SW $col $ricker -output_dir "$WORK/default" > "$WORK/default.log"
grep -q "^done:" "$WORK/default.log"

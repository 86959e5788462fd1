# Divergence guard: an incident-wave record of 1e308 m/s^2 overflows the input force on the
# first step. The run must stop with one line giving the step, the time, the node with its
# coordinates, the field and the component, and the input that caused it (the incident wave,
# with its record file), exit non-zero, and leave only finite values in its output files
# (the guard runs before any output of the step). The input force acts on the bottom
# boundary only, so after one step the first non-finite node lies at y = 0. The guard runs at
# every energy evaluation (-energy_interval, default 10 steps, and every output time): pinned
# to 1 here, it stops the run at step 1; at the default it stops it at the latest at step 10,
# still before the first output frame after the overflow.
set -eu
. tests/tools/lib.sh
printf 't,a\n0,0\n0.01,1e308\n0.02,1e308\n1,1e308\n' > "$WORK/huge.csv"
if $SW -mesh_box_faces 1,20 -mesh_box_upper 1,100 -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 \
   -bc_bottom_type absorbing -input_wave sv -input_boundary bottom -input_stf record -input_record "$WORK/huge.csv" \
   -input_baseline_correction 0 -constrain_components y -ts_max_time 0.5 -energy_interval 1 -output_dir "$WORK/out" 2> "$WORK/err.txt"; then
  echo "the run did not stop"; exit 1
fi
cat "$WORK/err.txt"
grep -Eq "^slipwave: error: diverged at step 1, t = [0-9.e+-]+ s: (displacement|velocity|acceleration) is not finite at node [0-9]+ \([0-9.e+-]+, 0\), component [xy] .*; caused by the incident wave \(-input_stf: record .*/huge\.csv .*input force not finite" "$WORK/err.txt"
[ "$(wc -l < "$WORK/err.txt")" -eq 1 ]
$PY scripts/check_output.py "$WORK/out"
if $SW -mesh_box_faces 1,20 -mesh_box_upper 1,100 -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 \
   -bc_bottom_type absorbing -input_wave sv -input_boundary bottom -input_stf record -input_record "$WORK/huge.csv" \
   -input_baseline_correction 0 -constrain_components y -ts_max_time 0.5 -output_dir "$WORK/out10" 2> "$WORK/err10.txt"; then
  echo "the run did not stop (default -energy_interval)"; exit 1
fi
cat "$WORK/err10.txt"
grep -Eq "^slipwave: error: diverged at step ([1-9]|10), t = .*caused by the incident wave" "$WORK/err10.txt"
$PY scripts/check_output.py "$WORK/out10"

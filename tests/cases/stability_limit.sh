# Stability: the Gershgorin bound on omega_max is rigorous, so (1) a -ts_dt 1 % above the
# reported limit is refused with a message giving both numbers, and (2) a long run (20,000
# steps) at the limit itself (safety factor 1) stays bounded: the closed-system energy
# identity holds to round-off (1e-9) and the divergence guard never fires. (3) A -ts_dt that
# does not divide -ts_max_time (0.3 s / 7e-4 s = 428.6) is rounded down to 429 equal steps,
# said, and the balance closes to round-off (kept, the shortened last step left ~1e-6).
set -eu
. tests/tools/lib.sh
opts="-mesh_box_faces 10,10 -mesh_box_upper 10,10 -regions soil -material_soil_rho 2000 -material_soil_vp 1000 -material_soil_vs 400 -bc_bottom_type fixed -output_fields 0 -progress_interval 100"
limit=$($SW $opts -dry_run | sed -n 's/^  stable step: \([0-9.e+-]*\) s.*/\1/p')
[ -n "$limit" ] || { echo "no stable step in the dry-run report"; exit 1; }
above=$($PY -c "print(1.01*$limit)")
if $SW $opts -ts_dt "$above" -ts_max_time 0.01 -output_dir "$WORK/above" 2> "$WORK/above.err"; then
  echo "a step 1% above the limit ($above > $limit) was accepted"; exit 1
fi
cat "$WORK/above.err"
grep -q "^slipwave: error: -ts_dt = .* is above the stable limit" "$WORK/above.err"
[ "$(wc -l < "$WORK/above.err")" -eq 1 ]
# -energy_interval 1: this test reads the ledger at every step (row count, per-step rows).
$SW $opts -time_step_safety 1 -initial_velocity 0.1,0 -ts_max_steps 20000 -ts_max_time 1e9 -energy_interval 1 -output_dir "$WORK/long"
$CHECK energy "$WORK/long/energy.csv" --max-error 1e-9 --min-rows 20001
$SW $opts -initial_velocity 0.1,0 -ts_dt 7e-4 -ts_max_time 0.3 -energy_interval 1 -output_dir "$WORK/rounded" > "$WORK/rounded.log"
grep "rounded down" "$WORK/rounded.log"
grep -q "^  -ts_dt = 0.0007 s rounded down to 0.000699300699 s: 429 equal steps" "$WORK/rounded.log"
grep -q "^done: 429 steps" "$WORK/rounded.log"
$CHECK energy "$WORK/rounded/energy.csv" --max-error 1e-12 --min-rows 430

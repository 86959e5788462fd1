# Issue 5: the foundation with a tied interface equals the unsplit model. The default scene
# (coarsened, 3 s, geostatic stage, strong SV wave) with the interface made unbreakable
# (c = 1e12 Pa, phi = 0, tensile strength 1e12 Pa, e_ini = 1 m) against the same scene
# without -interfaces (so block and soil share nodes). The only difference left is the
# penalty's compliance, which scales as 1/K: the station differences must fall by the
# factor the penalty grows (10x from penalty factor 30 to 300: ratio within 8 .. 12.5), and
# at factor 300 (interface 300x stiffer than a layer of soil one cell thick) stay below 2 %
# of each quantity's peak. All runs use the same step (-ts_dt 1e-4, below every limit).
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
grep -v "^interface" config/scenes/default_linear.yaml > "$WORK/unsplit.yaml"
O="-mesh_box_faces 61,30 -ts_max_time 3 -output_fields 0 -progress_interval 100 -ts_dt 1e-4"
together $SW -options_file "$WORK/unsplit.yaml" -input_record config/records/el_centro_1940_ns.csv $O -output_dir "$WORK/unsplit" > "$WORK/unsplit.log"
tie="-interface_base_phi 0 -interface_base_c 1e12 -interface_base_tensile_strength 1e12 -interface_base_e_ini 1"
for f in 30 300; do
  together $SW -options_file config/scenes/default_linear.yaml $O $tie -interface_base_penalty_rule mesh -interface_base_penalty_factor $f -output_dir "$WORK/tied$f" > "$WORK/tied$f.log"
done
together_wait
names=block_top,block_base_left,block_base_right,free_field,bedrock
d30=$($CHECK stations-equal "$WORK/unsplit" "$WORK/tied30" --names $names --tol 1 | sed 's/.*difference \([0-9.e+-]*\) .*/\1/')
d300=$($CHECK stations-equal "$WORK/unsplit" "$WORK/tied300" --names $names --tol 1 | sed 's/.*difference \([0-9.e+-]*\) .*/\1/')
$PY - "$d30" "$d300" <<'PY'
import sys
d30, d300 = float(sys.argv[1]), float(sys.argv[2])
ratio = d30 / d300
print(f"tied vs unsplit: {d30:.3e} (penalty x30), {d300:.3e} (x300), ratio {ratio:.2f}")
sys.exit(0 if 8 <= ratio <= 12.5 and d300 <= 0.02 else 1)
PY

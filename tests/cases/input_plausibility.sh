#!/usr/bin/env bash
# Values that run but are probably unit mistakes warn on stderr, one line each, and the run
# goes on (exit 0); a record's header unit is honoured. Dry runs of the 1D column of the error
# catalogue (src/physics/plausible_values.hpp, src/input/ground_motion_record.hpp):
# 1. The valid material (rho 2000, vp 400, vs 200) with a Ricker input: no stderr at all.
# 2. -material_soil_vs 0.2 (meant as km/s): "... looks like km/s: 0.2 km/s is 200 m/s".
# 3. -material_soil_rho 1.9 (meant as g/cm^3): "... 1.9 g/cm^3 is 1900 kg/m^3".
# 4. A record whose header says acceleration_cm_s2, peak 341.6 (no baseline correction): read
#    in cm/s^2, PGA 341.6 / 100 / 9.80665 = 0.3483 g (the issue's El Centro peak), no warning.
# 5. The same values under the header "acceleration" (m/s^2): PGA 34.83 g, one warning naming
#    the cm/s^2 reading 0.3483 g.
set -eu
. tests/tools/lib.sh
base="-mesh_box_faces 1,100 -mesh_box_upper 1,100 -regions soil -bc_bottom_type absorbing -input_wave sv -input_boundary bottom
 -constrain_components y -ts_max_time 0.1 -output_fields false -dry_run -output_overwrite -output_dir $WORK/out"
soil="-material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200"
run() { # name, arguments: stdout to $WORK/name.log, stderr to $WORK/name.err
  local name=$1; shift
  $SW $base "$@" > "$WORK/$name.log" 2> "$WORK/$name.err" || { echo "FAIL: $name: exit status $?"; cat "$WORK/$name.err"; exit 1; }
}
warns() { # name, expected regex of its one stderr line
  [ "$(grep -c '' "$WORK/$1.err")" -eq 1 ] && grep -Eq "^slipwave: warning: $2" "$WORK/$1.err" || { echo "FAIL: $1: expected one warning /$2/:"; cat "$WORK/$1.err"; exit 1; }
  echo "ok: $1: $(cat "$WORK/$1.err")"
}
run valid $soil -input_stf ricker
[ ! -s "$WORK/valid.err" ] || { echo "FAIL: a plausible scene warns:"; cat "$WORK/valid.err"; exit 1; }
echo "ok: a plausible scene: no warning"
run vs_km $soil -material_soil_vp 0.4 -material_soil_vs 0.2 -input_stf ricker
warns vs_km "-material_soil_vs = 0\.2 m/s is below any soil \(30 m/s\) and looks like km/s: 0\.2 km/s is 200 m/s$"
run rho_g $soil -material_soil_rho 1.9 -input_stf ricker
warns rho_g "-material_soil_rho = 1\.9 kg/m\^3 is below any soil \(500 kg/m\^3\) and looks like g/cm\^3 \(t/m\^3\): 1\.9 g/cm\^3 is 1900 kg/m\^3$"
printf 'time_s,acceleration_cm_s2\n0,0\n0.01,341.6\n0.02,-120\n0.03,0\n' > "$WORK/cm.csv"
sed '1s/.*/time_s,acceleration/' "$WORK/cm.csv" > "$WORK/si.csv"
run cm $soil -input_stf record -input_record "$WORK/cm.csv" -input_baseline_correction false
[ ! -s "$WORK/cm.err" ] || { echo "FAIL: the cm/s^2 record warns:"; cat "$WORK/cm.err"; exit 1; }
grep -q "(CSV in cm/s^2, 4 samples, 0 to 0.03 s); PGA 0.3483 g" "$WORK/cm.log" || { echo "FAIL: the cm/s^2 header is not honoured:"; grep record "$WORK/cm.log"; exit 1; }
echo "ok: acceleration_cm_s2 read in cm/s^2: PGA 0.3483 g"
run si $soil -input_stf record -input_record "$WORK/si.csv" -input_baseline_correction false
warns si "-input_record: PGA 34\.83 g is above any recorded earthquake \(about 3 g\): a unit mistake\? \(cm/s\^2 taken for m/s\^2: 0\.3483 g; .*\(.*si\.csv read in m/s\^2, scale factor 1\)$"

#!/usr/bin/env bash
# Tied interface: a vertically incident SV Ricker wave (f0 = 5 Hz, absorbing base, 1D column
# 1 cell wide, 100 m, rho 2000, vs 200, -constrain_components y) crosses a horizontal
# interface at y = 50 m between two identical soil layers. The interface cannot fail
# (c = 1e12 Pa, phi = 0), so it is a pair of penalty springs; the station records must equal
# those of the same mesh (same regions, same step) without -interfaces.
#
# Tolerance, derived: a spring layer of shear stiffness K [Pa/m] between equal media of
# impedance Z = rho vs transmits a plane wave of angular frequency w with
# T = 1/(1 + i w Z/(2K)) and reflects R = 1 - T, so the records differ by at most
# |1 - T| <= w Z/(2K) of the peak, evaluated at the Ricker top frequency 2.7638 f0 = 13.82 Hz
# (w = 86.83 rad/s; the spectrum holds < 1 % above it and |1 - T| grows with w), Z = 4e5:
#   penalty factor  30: K = G = 30 mu/h = 3.36e9 Pa/m  -> w Z/(2K) = 5.17e-3
#   penalty factor 300: K = 3.36e10 Pa/m              -> 5.17e-4
# (mu/h = 8e7/0.714 m; 140 rows so a node row lies at y = 50 m). Measured: the largest
# difference of u_x and v_x at the surface and at 25 m depth below the interface, relative to
# each record's peak. The error is first order in 1/K: a 10x stiffer penalty must give a
# 10x smaller error (allowed 8..12.5). All three runs use -ts_dt 1e-4 s (below half the
# stable step of the stiffer interface, 2.05e-4 s), so the time discretisation is the same
# and the difference is the interface's alone.
set -eu
. tests/tools/lib.sh
column="-mesh_box_faces 1,140 -mesh_box_upper 1,100 -regions lower,upper -region_upper_box 0,1,50,100
 -material_lower_rho 2000 -material_lower_vp 400 -material_lower_vs 200 -material_upper_rho 2000 -material_upper_vp 400 -material_upper_vs 200
 -bc_bottom_type absorbing -input_wave sv -input_boundary bottom -input_stf ricker -input_f0 5 -input_t0 0.24 -input_amplitude 0.1
 -constrain_components y -ts_max_time 2 -ts_dt 1e-4 -output_fields 0 -progress_interval 100 -station_coordinates 0.5,100,0.5,25 -station_names top,below"
$SW $column -output_dir "$WORK/ref" > "$WORK/ref.log"
for f in 30 300; do
  $SW $column -interfaces tie -interface_tie_regions lower,upper -interface_tie_c 1e12 -interface_tie_phi 0 -interface_tie_penalty_rule mesh -interface_tie_penalty_factor $f \
    -output_dir "$WORK/f$f" > "$WORK/f$f.log"
  grep "interface tie: E = " "$WORK/f$f.log"
  grep -q "^interface tie: 2 stick, 0 slip, 0 open at the end; dissipated 0 J" "$WORK/f$f.log" || { echo "FAIL: the tied interface slipped or opened"; tail -4 "$WORK/f$f.log"; exit 1; }
done
# K as the run reports it (the auto penalty), checked against factor x mu/h first.
K30=$(sed -n 's/.* G = \([0-9.e+-]*\) Pa\/m (auto).*/\1/p' "$WORK/f30.log"); K300=$(sed -n 's/.* G = \([0-9.e+-]*\) Pa\/m (auto).*/\1/p' "$WORK/f300.log")
$PY -c "import sys; k = [float(x) for x in sys.argv[1:]]; mh = 2000 * 200**2 / (100 / 140); sys.exit(0 if all(abs(a / (f * mh) - 1) < 1e-3 for a, f in zip(k, (30, 300))) else 'FAIL: G is not factor x mu/h')" $K30 $K300
$PY tests/tools/interface_checks.py tied "$WORK/ref" --dirs-if "$WORK/f30" "$WORK/f300" --K $K30 $K300 --names top,below \
  --quantities u_x,v_x --omega "$($PY -c 'import math; print(2 * math.pi * 2.7638 * 5)')" --Z 4e5 --ratio-min 0.8 --ratio-max 1.25

#!/usr/bin/env bash
# Tied interface at element degree 4 (issue 14): interface_tied.sh (an SV Ricker, f0 = 5 Hz,
# up a 100 m column through a horizontal tied interface at y = 50 m between identical layers;
# the same closed form and bounds) with 36 elements of degree 4 (h_e = 100/36 m, the column as
# wide, 4x fewer node rows than its 140 cells) instead of 140 cells. A spring layer of shear
# stiffness K between equal media of impedance Z transmits T = 1/(1 + i w Z/(2K)), so the
# records differ from the run without the interface by at most w Z/(2K) of their peak, and
# 10x the penalty gives 10x less (ratio within 0.8..1.25 of 10). The auto penalty at degree p
# is K = factor x mu (p^2 + p + 1)/(3 h_e) = factor x 8e7 x 7 x 36/100 = factor x 2.016e8 Pa/m
# (numerics/gll_basis.hpp; 30 -> 6.048e9 Pa/m), checked against the log first. The interface nodes are 2
# x 5 GLL pairs (the column is one element wide). All runs use -ts_dt 4.5e-5 s, below half the
# stable step with the stiffer interface (9.51e-5 s), so the difference is the interface's alone.
set -eu
. tests/tools/lib.sh
column="-mesh_box_faces 1,36 -mesh_box_upper 2.7777777777777777,100 -element_degree 4 -regions lower,upper -region_upper_box 0,3,50,100
 -material_lower_rho 2000 -material_lower_vp 400 -material_lower_vs 200 -material_upper_rho 2000 -material_upper_vp 400 -material_upper_vs 200
 -bc_bottom_type absorbing -input_wave sv -input_boundary bottom -input_stf ricker -input_f0 5 -input_t0 0.24 -input_amplitude 0.1
 -constrain_components y -ts_max_time 2 -ts_dt 4.5e-5 -output_fields 0 -progress_interval 100 -station_coordinates 0.5,100,0.5,25 -station_names top,below"
$SW $column -output_dir "$WORK/ref" > "$WORK/ref.log"
for f in 30 300; do
  $SW $column -interfaces tie -interface_tie_regions lower,upper -interface_tie_c 1e12 -interface_tie_phi 0 -interface_tie_penalty_rule mesh -interface_tie_penalty_factor $f \
    -output_dir "$WORK/f$f" > "$WORK/f$f.log"
  grep "interface tie: E = " "$WORK/f$f.log"
  grep -q "^interface tie: 5 stick, 0 slip, 0 open at the end; dissipated 0 J" "$WORK/f$f.log" || { echo "FAIL: the tied interface slipped or opened"; tail -4 "$WORK/f$f.log"; exit 1; }
done
K30=$(sed -n 's/.* G = \([0-9.e+-]*\) Pa\/m (auto).*/\1/p' "$WORK/f30.log"); K300=$(sed -n 's/.* G = \([0-9.e+-]*\) Pa\/m (auto).*/\1/p' "$WORK/f300.log")
$PY -c "import sys; k = [float(x) for x in sys.argv[1:]]; mh = 2000 * 200**2 * (4 * 4 + 4 + 1) / (3 * 100 / 36); sys.exit(0 if all(abs(a / (f * mh) - 1) < 1e-3 for a, f in zip(k, (30, 300))) else 'FAIL: G is not factor x mu (p^2+p+1)/(3 h_e)')" $K30 $K300
$PY tests/tools/interface_checks.py tied "$WORK/ref" --dirs-if "$WORK/f30" "$WORK/f300" --K $K30 $K300 --names top,below \
  --quantities u_x,v_x --omega "$($PY -c 'import math; print(2 * math.pi * 2.7638 * 5)')" --Z 4e5 --ratio-min 0.8 --ratio-max 1.25
# 2 ranks (the partition cuts the column; the report says whether pairs straddle it): the
# stations agree with 1 rank to 1e-10 of each quantity's peak.
$MPIEXEC -n 2 $SW $column -interfaces tie -interface_tie_regions lower,upper -interface_tie_c 1e12 -interface_tie_phi 0 -interface_tie_penalty_rule mesh -interface_tie_penalty_factor 30 \
  -output_dir "$WORK/f30_np2" | grep "interface tie: E = "
$CHECK stations-equal "$WORK/f30" "$WORK/f30_np2" --names top,below --tol 1e-10

#!/usr/bin/env bash
# Newmark sliding block through the whole simulation (scene config/scenes/sliding_block.yaml):
# a 1 m x 1 m stiff block (rho 2400, vs 1800 m/s) on a horizontal Mohr-Coulomb interface
# (phi = atan 0.2, c = 0, psi = 0: N = tan phi = 0.2) over a thin, equally stiff base whose
# bottom moves with a rectangular acceleration pulse A = 0.4 g for t_p = 0.2 s (prescribed
# velocity from a time,acceleration record, no baseline correction). Vertical motion is held
# everywhere, so the interface keeps the block's weight, sigma_N0 = -rho g H = -23544 Pa.
#
# Expected (Newmark 1965, rigid block, rigid-plastic contact): V = A g t_p = 0.7848 m/s,
# permanent slip V^2/(2 g N) (1 - N/A) = 78.48 mm, sliding stops at t = V/(N g) = 0.4 s.
# Bound 2 % (issue), met only if the stick phase is stiff: the block (mass rho H per m^2)
# on the penalty spring G rings at w = sqrt(G/(rho H)); starting from rest under the base
# acceleration A g it needs wt = acos(1 - N/A) = pi/3 to reach the friction limit, and
# arrives there with a relative velocity (A g/w) sin(pi/3) instead of the rigid model's
# (A - N) g pi/(3w). That excess, carried through the sliding time V/(N g), adds
#   (A g/w)(sin(pi/3) - (1 - N/A) pi/3) V/(N g) = 0.27 mm = 0.34 %    for G = 1e10 Pa/m,
# and the block's own flexibility (shear travel 4H/vs = 2.2 ms << t_p) adds a like amount:
# 0.55 % is measured (estimate + measured: G = 1e8: 3.36 %, 3.34 %; 1e9: 1.06 %, 1.16 %;
# 1e11: 0.11 %, 0.42 %: the flexibility floor). So the penalty is 1e10 Pa/m
# (its stable-step cost, printed in the log, is 11 %). Rows of 0.25 m: 4 in the block.
# The dissipated energy must be N |sigma_N| x slip (per m of width) to 1e-3: the plastic
# work of a constant friction force.
set -eu
. tests/tools/lib.sh
newmark_pulse "$WORK/pulse.csv"
$SW -options_file config/scenes/sliding_block.yaml -bc_bottom_record "$WORK/pulse.csv" -output_dir "$WORK/out" > "$WORK/run.log"
cat "$WORK/run.log"
$PY tests/tools/interface_checks.py newmark --out-dir "$WORK/out" --interface slide --base "$WORK/out/stations/base.csv" \
  --block "$WORK/out/stations/mid.csv" --energy "$WORK/out/energy.csv" --A 0.4 --N 0.2 --tp 0.2 --sigma-n 23544 --area 1 \
  --t-settled 0.45 --tol 0.02 --stuck-tol 1e-2

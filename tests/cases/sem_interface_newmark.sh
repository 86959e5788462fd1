#!/usr/bin/env bash
# The Newmark sliding block of interface_newmark_block.sh (same scene, expected numbers and
# bounds: Newmark 1965, permanent slip 78.48 mm within 2 %; dissipation = friction x slip to
# 1e-3) at element degree 4 with 3 elements of 0.5 m over the height (2x fewer rows than its
# 6; the block is one element wide either way), so the interface is 5 GLL node pairs with GLL
# areas of the 1 m face. Measured at p = 4: slip 78.93 mm (0.57 %). On 2 ranks the
# displacements must agree with 1 rank to 1e-10 of the slip (measured 1.3e-14 m) and the
# velocities to 1e-9 of V = 0.7848 m/s: the sums in another order differ by round-off, which
# the stiff penalty's ringing (G = 1e10, 52 914 steps of 11 us) carries along: |dv| grows
# steadily from 1e-9 m/s^2 differences in a at t = 0.015 s to 3.1e-10 m/s at the end
# (4e-10 of V; degree 1 on its 6 rows: 3.2e-11 m/s after 10 832 steps). No pair is cut by the
# partition here (interface_mpi.sh covers cut pairs).
set -eu
. tests/tools/lib.sh
newmark_pulse "$WORK/pulse.csv"
O="-options_file config/scenes/sliding_block.yaml -bc_bottom_record $WORK/pulse.csv -mesh_box_faces 1,3 -element_degree 4"
$SW $O -output_dir "$WORK/out" > "$WORK/run.log"
$PY tests/tools/interface_checks.py newmark --out-dir "$WORK/out" --interface slide --base "$WORK/out/stations/base.csv" \
  --block "$WORK/out/stations/mid.csv" --energy "$WORK/out/energy.csv" --A 0.4 --N 0.2 --tp 0.2 --sigma-n 23544 --area 1 \
  --t-settled 0.45 --tol 0.02 --stuck-tol 1e-2
$MPIEXEC -n 2 $SW $O -output_fields 0 -output_dir "$WORK/two" > /dev/null
$PY - "$WORK" <<'PY'
import sys
import numpy as np
w = sys.argv[1]
du = dv = 0.0
for s in ("base", "mid", "top"):
    one = np.genfromtxt(f"{w}/out/stations/{s}.csv", delimiter=",", names=True)
    two = np.genfromtxt(f"{w}/two/stations/{s}.csv", delimiter=",", names=True)
    du = max(du, float(np.abs(one["u_x"] - two["u_x"]).max()))
    dv = max(dv, float(np.abs(one["v_x"] - two["v_x"]).max()))
print(f"1 vs 2 ranks: largest station u difference {du:.2e} m (bound 1e-10 of the 78.48 mm slip), v difference {dv:.2e} m/s (bound 1e-9 of V = 0.7848 m/s)")
sys.exit(0 if du <= 78.48e-3 * 1e-10 and dv <= 0.7848e-9 else 1)
PY

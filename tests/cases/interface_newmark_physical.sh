#!/usr/bin/env bash
# Issue 21, part 1: the physical `auto` penalty is the same contact model on any mesh. The
# Newmark sliding block of interface_newmark_block.sh (config/scenes/sliding_block.yaml:
# 1 m x 1 m block, rho 2400, vs 1800 m/s, phi = atan 0.2, base pulse A = 0.4 g for 0.2 s;
# expected permanent slip V^2/(2 g N)(1 - N/A) = 78.48 mm, sliding stops at V/(N g) = 0.4 s,
# Newmark 1965), with E, G = auto from -interface_slide_penalty_length 0.7776 m instead of
# the scene's explicit numbers: G = mu/L = 2400 x 1800^2 / 0.7776 = 1e10 Pa/m, the stiffness
# whose stick error interface_newmark_block.sh derives (0.34 % + the block's flexibility,
# 0.55 % measured; E = (lambda+2mu)/L does not act: the vertical motion is held). Run on the
# scene's mesh (rows of 0.25 m) and on the mesh twice as fine (0.125 m, 2 x 12 cells): both
# must meet the same bounds as interface_newmark_block.sh (slip within 2 %, the block stuck
# after 0.45 s, dissipation N |sigma_N| slip to 1e-3), the penalty printed by the report
# must be the same 1e10 Pa/m on both, and the two slips must agree to 0.5 % (the mesh moves
# only the block's flexibility term).
set -eu
. tests/tools/lib.sh
newmark_pulse "$WORK/pulse.csv"
phys="-interface_slide_E auto -interface_slide_G auto -interface_slide_penalty_rule physical -interface_slide_penalty_length 0.7776"
for m in "1,6" "2,12"; do
  run="$WORK/m${m/,/x}"
  $SW -options_file config/scenes/sliding_block.yaml $phys -mesh_box_faces $m -bc_bottom_record "$WORK/pulse.csv" -output_dir "$run" > "$run.log"
  grep "interface slide: " "$run.log"
  grep -q "interface slide: E = 2.778e+10 Pa/m (auto), G = 1e+10 Pa/m (auto) (penalty rule physical, length 0.7776 m given" "$run.log"
  $PY tests/tools/interface_checks.py newmark --out-dir "$run" --interface slide --base "$run/stations/base.csv" \
    --block "$run/stations/mid.csv" --energy "$run/energy.csv" --A 0.4 --N 0.2 --tp 0.2 --sigma-n 23544 --area 1 \
    --t-settled 0.45 --tol 0.02 --stuck-tol 1e-2
done
$PY - "$WORK" <<'PY'
import sys
sys.path.insert(0, "python")
import numpy as np
from slipwave import RunFolder
s = [float(np.max(RunFolder(f"{sys.argv[1]}/{m}").interface("slide").field("accumulated_slip", -1))) for m in ("m1x6", "m2x12")]
d = abs(s[1] / s[0] - 1)
print(f"{'ok' if d <= 5e-3 else 'FAIL'} slip {s[0] * 1e3:.3f} mm (0.25 m rows) and {s[1] * 1e3:.3f} mm (0.125 m rows): {d:.2%} apart (allowed 0.5 %)")
sys.exit(0 if d <= 5e-3 else 1)
PY

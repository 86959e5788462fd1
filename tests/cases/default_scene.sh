# The default scene (issue 5): footing on a layer over bedrock, geostatic stage, SV wave, on
# 2 ranks. It must run to the end, the energy budget must close to 1 % (issue bound; the
# discrete identity makes it round-off), the footing must slide (accumulated slip > 1 cm)
# and lift its heel (some pair open at some output step), and the output must parse.
set -eu
. tests/tools/lib.sh
$MPIEXEC -n 2 $SW -options_file config/scenes/default.yaml -output_dir "$WORK" | grep -vE "^step"
$CHECK energy "$WORK/energy.csv" --max-error 1e-2 --min-rows 40000
$PY scripts/check_output.py "$WORK"
$PY scripts/check_output.py "$WORK" --grid interface_base
$PY - "$WORK/interface_base.h5" <<'PY'
import sys
import h5py
import numpy as np
with h5py.File(sys.argv[1]) as f:
    steps = sorted(f["/fields/status"].keys())
    slip = max(f["/fields/accumulated_slip/" + k][:].max() for k in steps)
    opened = sum(int(np.any(f["/fields/status/" + k][:] == 2)) for k in steps)
print(f"largest accumulated slip {slip:.3f} m, {opened} of {len(steps)} output steps with an open pair")
sys.exit(0 if slip > 0.01 and opened > 0 else 1)
PY

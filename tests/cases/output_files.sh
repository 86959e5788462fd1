# Output: a short 2-rank run of the default scene writes volume.xmf/h5 that
# scripts/check_output.py parses (every DataItem points to an existing dataset of the
# declared shape and precision, values finite, topology in range, times increasing), the
# expected frames (t = 0 and every 0.1 s to 0.5 s: 6), station CSV/HDF5 and energy.csv.
set -eu
. tests/tools/lib.sh
# -energy_interval 1: this test reads the ledger at every step (row count, per-step rows).
$MPIEXEC -n 2 $SW -options_file config/scenes/site_response_2d.yaml -ts_max_time 0.5 -output_interval 0.1 -energy_interval 1 -output_dir "$WORK"
$PY scripts/check_output.py "$WORK" --expect-steps 6 --expect-fields displacement,velocity,acceleration,stress,region
$PY - "$WORK" <<'PY'
import sys, h5py, numpy as np
d = sys.argv[1]
with h5py.File(f"{d}/stations.h5") as f:
    for name in ("surface", "layer_base", "bedrock_base"):
        n = f[name]["time"].shape[0]
        for q in ("displacement", "velocity", "acceleration"):
            assert f[name][q].shape == (n, 2), (name, q, f[name][q].shape)
            assert np.all(np.isfinite(f[name][q][:]))
e = np.genfromtxt(f"{d}/energy.csv", delimiter=",", names=True)
assert e.shape[0] == n, (e.shape, n)
print("stations.h5 and energy.csv: OK,", n, "samples")
PY

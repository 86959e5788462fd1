#!/usr/bin/env bash
# Runs test_field_writer on 1 and 2 ranks, checks both outputs with scripts/check_output.py
# requires the HDF5 files (mesh file + one per frame) written by 1 and 2 ranks to hold identical
# datasets, and makes sure
# check_output.py rejects a corrupted index.
set -euo pipefail
BUILD=${BUILD:-build}
bin="$BUILD/tests/unit/test_field_writer"
[ -x "$bin" ] || { echo "missing $bin: run make build-only"; exit 1; }
out="$BUILD/tests/field_writer_parallel"
rm -rf "$out"
root_flag=""; [ "$(id -u)" = 0 ] && root_flag="--allow-run-as-root"
for np in 1 2; do
  log=$(mpiexec --oversubscribe $root_flag -n "$np" "$bin" -output_dir "$out/np$np" 2>&1) || { echo "$log"; echo "FAIL: $np ranks exited non-zero"; exit 1; }
  echo "$log"
  if grep -q '^not ok' <<<"$log"; then echo "FAIL: a check failed on $np ranks"; exit 1; fi
  for grid in quad2d hex3d; do
    /usr/bin/python3 scripts/check_output.py "$out/np$np/$grid" --expect-steps 3 --expect-fields displacement,pressure,stress,damage
  done
  /usr/bin/python3 scripts/check_output.py "$out/np$np/line2d" --grid interface --expect-steps 3 --expect-fields displacement,pressure,stress,damage
done
/usr/bin/python3 - "$out" <<'PY'
import glob, os, sys, h5py, numpy as np
out = sys.argv[1]
for grid, stem in (("quad2d", "volume"), ("hex3d", "volume"), ("line2d", "interface")):
    # The mesh file and every frame file, by their path relative to the grid's folder.
    files = sorted(os.path.relpath(p, f"{out}/np1/{grid}") for p in [f"{out}/np1/{grid}/{stem}.h5"] + glob.glob(f"{out}/np1/{grid}/{stem}/*.h5"))
    count = 0
    for rel in files:
        with h5py.File(f"{out}/np1/{grid}/{rel}") as a, h5py.File(f"{out}/np2/{grid}/{rel}") as b:
            names = []
            a.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
            others = []
            b.visititems(lambda n, o: others.append(n) if isinstance(o, h5py.Dataset) else None)
            if sorted(names) != sorted(others):
                sys.exit(f"FAIL: {grid}/{rel}: datasets differ between 1 and 2 ranks: {sorted(names)} vs {sorted(others)}")
            for n in names:
                if a[n].dtype != b[n].dtype or not np.array_equal(a[n][()], b[n][()]):
                    sys.exit(f"FAIL: {grid}/{rel}: {n} differs between 1 and 2 ranks")
            count += len(names)
    # 2 mesh datasets + 3 frames x 4 fields (see test_field_writer.cpp).
    if count != 14 or len(files) != 4:
        sys.exit(f"FAIL: {grid}: {len(files)} files, {count} datasets; expected 4 files, 14 datasets")
    print(f"{grid}: {len(files)} files, {count} datasets identical on 1 and 2 ranks")
PY
# check_output.py itself must notice a declared shape that the dataset does not have.
bad="$out/bad_dims"
cp -r "$out/np1/quad2d" "$bad"
sed -i '0,/Dimensions="6 3"/s//Dimensions="6 2"/' "$bad/volume.xmf"
if /usr/bin/python3 scripts/check_output.py "$bad"; then echo "FAIL: check_output.py accepted wrong Dimensions"; exit 1; fi
echo "PASS"

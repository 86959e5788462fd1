#!/usr/bin/env bash
# The split 8x8 mesh (soil y < 4 | block y > 4, 9 pairs) distributed over 2 ranks, twice:
# with -petscpartitioner_type metis (METIS tends to give the soil and the block one rank each,
# since the split mesh is two bodies; then every pair's structure node lives on the other rank)
# and with a forced partition x < 4 | x > 4 that cuts the interface. InterfacePairsBuild must
# give each pair exactly one owner, dofs that point at the right vertex copy, and the serial
# areas/normals (checks inside test_interface_split -distribute, printed by rank 0).
set -euo pipefail
BUILD=${BUILD:-build}
bin="$BUILD/tests/unit/test_interface_split"
[ -x "$bin" ] || { echo "missing $bin: run make build-only"; exit 1; }
root_flag=""; [ "$(id -u)" = 0 ] && root_flag="--allow-run-as-root"
out=$(mpiexec --oversubscribe $root_flag -n 2 "$bin" -distribute -petscpartitioner_type metis 2>&1) || { echo "$out"; echo "FAIL: mpiexec exited non-zero"; exit 1; }
echo "$out"
if grep -q '^not ok' <<<"$out"; then echo "FAIL: a check failed"; exit 1; fi
for how in options cut; do
  grep -q "^ok - distributed ($how): every pair owned by exactly one rank" <<<"$out" || { echo "FAIL: no passing ownership check for '$how'"; exit 1; }
  grep -q "^ok - distributed ($how): areas, normals, coordinates equal the serial values" <<<"$out" || { echo "FAIL: no passing geometry check for '$how'"; exit 1; }
done
grep -q "^ok - distributed (cut): the interface is cut by the partition" <<<"$out" || { echo "FAIL: the forced partition did not cut the interface"; exit 1; }
grep -q "^ok - no PETSc error" <<<"$out" || { echo "FAIL: PETSc error"; exit 1; }
echo "PASS"

#!/usr/bin/env bash
# DMPlexDistribute of a 40x20 box mesh over 2 ranks with -petscpartitioner_type metis, then a
# redistribution of the distributed mesh (graph spread over both ranks): every rank must own
# cells after each (checks inside test_partition_metis -distribute, printed by rank 0).
set -euo pipefail
BUILD=${BUILD:-build}
bin="$BUILD/tests/unit/test_partition_metis"
[ -x "$bin" ] || { echo "missing $bin: run make build-only"; exit 1; }
root_flag=""; [ "$(id -u)" = 0 ] && root_flag="--allow-run-as-root"
out=$(mpiexec --oversubscribe $root_flag -n 2 "$bin" -distribute -petscpartitioner_type metis 2>&1) || { echo "$out"; echo "FAIL: mpiexec exited non-zero"; exit 1; }
echo "$out"
if grep -q '^not ok' <<<"$out"; then echo "FAIL: a check failed"; exit 1; fi
for step in distribute redistribute; do
  grep -q "^ok - $step with metis: every rank owns cells" <<<"$out" || { echo "FAIL: no passing '$step' check"; exit 1; }
done
echo "PASS"

# The benchmarks must keep running (they are not run by make test otherwise): the smallest
# bulk-operator case, whose built-in check compares the element loop with an assembled AIJ
# matrix (they must agree to 1e-12 relative: the same element matrices summed in another
# order). Timings are printed, never asserted.
set -eu
. tests/tools/lib.sh
"$BUILD/bench/bench_bulk_operator" --case 2d_128 > "$WORK/bulk.txt"
cat "$WORK/bulk.txt"
$PY - "$WORK/bulk.txt" <<'PY'
import re, sys
diffs = [float(x) for x in re.findall(r"max relative difference ([0-9.eE+-]+)", open(sys.argv[1]).read())]
print("element loop vs AIJ:", diffs)
sys.exit(0 if diffs and max(diffs) <= 1e-12 else 1)
PY

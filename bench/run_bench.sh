#!/usr/bin/env bash
# Runs every benchmark binary build/bench/bench_* and every bench/cases/*.sh; each appends
# its rows to bench/results.csv (columns: benchmark,case,metric,value,unit).
set -u
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
out=bench/results.csv
echo "benchmark,case,metric,value,unit" > "$out"
for b in "$BUILD"/bench/bench_*; do
  [ -x "$b" ] || continue
  case "$b" in *.o|*.d) continue ;; esac
  echo "== $(basename "$b")"
  "$b" --csv "$out" || echo "benchmark $(basename "$b") failed"
done
for s in bench/cases/*.sh; do
  [ -f "$s" ] || continue
  echo "== $(basename "$s")"
  BENCH_CSV="$out" bash "$s" || echo "benchmark $(basename "$s") failed"
done
echo "results in $out"

# A footing's collapse load on a yielding soil on 0.25 and 0.125 m cells (B/h = 8 and 16):
# tests/cases/hysteretic_footing_collapse.sh with FOOTING_FINE=1, which adds the finer mesh
# (8 times the test's cost) to its checks (bounds and sources in its header: Prandtl's
# (2 + pi) k; the mean dilatation rests at 0.95 q_u and collapses at 1.1 q_u on B/h = 16,
# the Gauss points still hold 1.2 q_u: locking is not cured by refining). Rows to $BENCH_CSV:
# the outcome (1 = every check held) and the wall time.
set -u
cd "$(dirname "$0")/../.."
t0=$(date +%s)
FOOTING_FINE=1 bash tests/cases/hysteretic_footing_collapse.sh; rc=$?
if [ -n "${BENCH_CSV:-}" ]; then
  echo "hysteretic_footing_collapse,B/h=8+16,checks_held,$([ $rc -eq 0 ] && echo 1 || echo 0),-" >> "$BENCH_CSV"
  echo "hysteretic_footing_collapse,B/h=8+16,wall_time,$(( $(date +%s) - t0 )),s" >> "$BENCH_CSV"
fi
exit $rc

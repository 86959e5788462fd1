#!/usr/bin/env bash
# Runs every unit-test binary (each prints "ok - ..." / "not ok - ..." lines) and every
# scenario script tests/cases/*.sh (one test each: exit 0 = pass), then prints the
# closing line "N passed, N failed". Logs of the scripts go to build/tests/logs/.
set -u
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
logs="$BUILD/tests/logs"; mkdir -p "$logs"
# Open MPI start-up, for every process the suite launches: a program started without mpiexec
# (a singleton) forks a helper daemon, and the UCX transport probes the machine's network
# devices, 0.3 s of waiting per launch (errors_user_input.sh, 240 launches: 98 s, 17 s
# without). Neither is needed here: a singleton spawns no processes (ess_singleton_isolated:
# no daemon), and the ranks of an `mpiexec -n 2` share one machine, where Open MPI's own
# shared-memory path (pml ob1, btl vader) carries the messages. What is computed and sent is
# the same. A script run alone gets them only if you set them.
export OMPI_MCA_ess_singleton_isolated=${OMPI_MCA_ess_singleton_isolated:-1} OMPI_MCA_pml=${OMPI_MCA_pml:-ob1}
pass=0; fail=0; failed_names=()
start_all=$(date +%s)

for t in "$BUILD"/tests/unit/test_*; do
  [ -x "$t" ] || continue
  case "$t" in *.o|*.d) continue ;; esac
  name=$(basename "$t")
  out=$("$t" 2>&1); rc=$?
  p=$(grep -c '^ok - ' <<<"$out"); f=$(grep -c '^not ok - ' <<<"$out")
  grep '^not ok - ' <<<"$out" | sed "s/^/  $name: /"
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
    f=1; echo "  $name: exited $rc without a failing check:"; tail -5 <<<"$out" | sed 's/^/    /'
  fi
  pass=$((pass + p)); fail=$((fail + f))
  [ "$f" -gt 0 ] && failed_names+=("$name")
  printf '%-40s %4d ok %3d failed\n' "unit/$name" "$p" "$f"
done

for s in tests/cases/*.sh; do
  [ -f "$s" ] || continue
  name=$(basename "$s" .sh)
  t0=$(date +%s%N)
  bash "$s" >"$logs/$name.log" 2>&1; rc=$?
  ms=$(( ($(date +%s%N) - t0) / 1000000 )); dt="$((ms / 1000)).$(( (ms % 1000) / 100 ))"
  if [ "$rc" -eq 0 ]; then
    pass=$((pass + 1)); printf '%-40s ok      (%ss)\n' "cases/$name" "$dt"
  else
    fail=$((fail + 1)); failed_names+=("$name")
    printf '%-40s FAILED  (%ss, exit %d); last lines of %s:\n' "cases/$name" "$dt" "$rc" "$logs/$name.log"
    tail -15 "$logs/$name.log" | sed 's/^/    /'
  fi
done

echo "total time $(( $(date +%s) - start_all )) s"
[ ${#failed_names[@]} -gt 0 ] && echo "failed: ${failed_names[*]}"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]

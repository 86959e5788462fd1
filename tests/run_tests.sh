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

# The scenario scripts, SUITE_JOBS at a time (default 2, the cores of the machine the suite is
# sized for: many scripts run one process for much of their time, so one after another the
# suite left a core idle a quarter of the time). A script whose header has the line
# "# suite: alone" runs after the others, by itself (it times signals against the launcher).
# Each script gets its own Open MPI session directory (two singletons at once would share,
# and one remove, /tmp/ompi.HOST.UID/jf.0/1: tests/tools/together.sh), and a rank that waits
# for a message yields its core (a 2-rank run beside another script is oversubscribed, and a
# spinning rank would take the core its peer needs). Results print as the scripts end.
SUITE_JOBS=${SUITE_JOBS:-2}
export OMPI_MCA_mpi_yield_when_idle=${OMPI_MCA_mpi_yield_when_idle:-1}
results=$(mktemp -d); trap 'rm -rf "$results"' EXIT
running=()
case_start() { # case_start SCRIPT: in the background, its exit status and milliseconds to $results/NAME
  local s=$1 name
  name=$(basename "$s" .sh)
  (
    session=$(mktemp -d "${TMPDIR:-/tmp}/suite.XXXXXX")
    t0=$(date +%s%N)
    OMPI_MCA_orte_tmpdir_base=$session bash "$s" >"$logs/$name.log" 2>&1; rc=$?
    echo "$rc $(( ($(date +%s%N) - t0) / 1000000 ))" >"$results/$name"
    rm -rf "$session"
  ) &
  running+=("$!:$name")
}
case_report() { # case_report NAME: its line, and the tail of its log if it failed
  local name=$1 rc ms dt
  read -r rc ms <"$results/$name"
  dt="$((ms / 1000)).$(( (ms % 1000) / 100 ))"
  if [ "$rc" -eq 0 ]; then
    pass=$((pass + 1)); printf '%-40s ok      (%ss)\n' "cases/$name" "$dt"
  else
    fail=$((fail + 1)); failed_names+=("$name")
    printf '%-40s FAILED  (%ss, exit %d); last lines of %s:\n' "cases/$name" "$dt" "$rc" "$logs/$name.log"
    tail -15 "$logs/$name.log" | sed 's/^/    /'
  fi
}
cases_reap() { # cases_reap N: report the scripts that ended, until fewer than N run
  local entry alive
  while :; do
    alive=()
    for entry in "${running[@]}"; do
      if kill -0 "${entry%%:*}" 2>/dev/null; then alive+=("$entry"); else wait "${entry%%:*}"; case_report "${entry#*:}"; fi
    done
    running=(${alive[@]+"${alive[@]}"})
    [ ${#running[@]} -lt "$1" ] && return 0
    sleep 0.2
  done
}
alone=()
for s in tests/cases/*.sh; do
  [ -f "$s" ] || continue
  if grep -q '^# suite: alone' "$s"; then alone+=("$s"); continue; fi
  cases_reap "$SUITE_JOBS"
  case_start "$s"
done
cases_reap 1
for s in ${alone[@]+"${alone[@]}"}; do
  case_start "$s"
  cases_reap 1
done

echo "total time $(( $(date +%s) - start_all )) s"
[ ${#failed_names[@]} -gt 0 ] && echo "failed: ${failed_names[*]}"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]

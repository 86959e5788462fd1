#!/usr/bin/env bash
# Runs every unit-test binary (each prints "ok - ..." / "not ok - ..." lines) and every
# scenario script tests/cases/*.sh (one test each: exit 0 = pass), then prints the
# closing line "N passed, N failed". Logs of the scripts go to build/tests/logs/; their work
# folders (build/tests/work/<case>/) are removed once they pass unless KEEP_WORK=1.
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
# Two cases run side by side (below), so an MPI case's ranks share the cores with another
# case: ranks that yield while they wait for a message leave it its turn (two 2-core cases
# together, default_scene_ranks and foundation_impedance_strip: 104 s of wall busy-polling,
# 94 s yielding, 111 s one after the other). The arithmetic is the same.
export OMPI_MCA_mpi_yield_when_idle=${OMPI_MCA_mpi_yield_when_idle:-1}
pass=0; fail=0; failed_names=(); reran=()

# run_case SCRIPT LOG: the script in its own session, stdin closed (a launcher that reads a
# terminal would stop the suite), and a watchdog: past CASE_LIMIT seconds (about 9 times the
# slowest case) the stacks of every process of the session go to the log (gdb, where the
# machine lets it attach), then every process of the session is killed (an MPI launcher puts
# its ranks in process groups of their own); the status is then $timed_out.
CASE_LIMIT=${CASE_LIMIT:-900}; timed_out=200
run_case() {
  setsid bash "$1" >"$2" 2>&1 </dev/null & local pid=$!
  ( sleep "$CASE_LIMIT" & trap 'kill $! 2>/dev/null; exit 0' TERM; wait $!
    { echo "=== no end after $CASE_LIMIT s; the processes of the session:"; ps -o pid,etime,time,stat,args -s "$pid"
      for p in $(ps -o pid= -s "$pid"); do
        echo "=== stacks of $p"; timeout 60 gdb -p "$p" -batch -ex 'thread apply all bt' 2>&1 | grep -E '^(#|Thread)' | head -80
      done; } >>"$2.stacks" 2>&1
    kill -KILL $(ps -o pid= -s "$pid") 2>/dev/null ) & local watchdog=$!
  { wait "$pid"; } 2>/dev/null; local rc=$?
  kill "$watchdog" 2>/dev/null; wait "$watchdog" 2>/dev/null
  if [ -f "$2.stacks" ]; then cat "$2.stacks" >>"$2"; rm -f "$2.stacks"; return $timed_out; fi
  return $rc
}
start_all=$(date +%s)

for t in "$BUILD"/tests/unit/test_*; do
  [ -x "$t" ] || continue
  case "$t" in *.o|*.d) continue ;; esac
  name=$(basename "$t")
  # A unit binary takes seconds; one that hangs is stopped (exit 124) and fails.
  out=$(timeout -k 10 "$CASE_LIMIT" "$t" 2>&1 </dev/null); rc=$?
  p=$(grep -c '^ok - ' <<<"$out"); f=$(grep -c '^not ok - ' <<<"$out")
  grep '^not ok - ' <<<"$out" | sed "s/^/  $name: /"
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
    f=1; echo "  $name: exited $rc without a failing check:"; tail -5 <<<"$out" | sed 's/^/    /'
  fi
  pass=$((pass + p)); fail=$((fail + f))
  [ "$f" -gt 0 ] && failed_names+=("$name")
  printf '%-40s %4d ok %3d failed\n' "unit/$name" "$p" "$f"
done

# The scenario scripts run TEST_JOBS at a time (default 2, the machine's cores; 1: one after
# the other), each case with its work folders under build/tests/work/<case>/ (tests/tools/
# lib.sh takes TEST_WORK_ROOT), so a passed case's folders can go while another runs, and an
# Open MPI session directory of its own (singletons all take job id 1 and the same directory,
# which the first to end removes under the other: tests/tools/together.sh). Inside a case its
# independent runs then go one at a time (together.sh reads TEST_JOBS too), so the suite keeps
# about one process per core. Each case prints its line when it ends; the counts are read back
# from its status file.
TEST_JOBS=${TEST_JOBS:-2}
lanes=$TEST_JOBS
status="$BUILD/tests/status"; rm -rf "$status"; mkdir -p "$status"
run_one() {
  local s=$1 name; name=$(basename "$1" .sh)
  local root="$BUILD/tests/work/$name" t0 rc ms dt session
  rm -rf "$root"
  session=$(mktemp -d "${TMPDIR:-/tmp}/suite.XXXXXX")
  export TEST_WORK_ROOT="$root" OMPI_MCA_orte_tmpdir_base="$session"
  [ "$lanes" -gt 1 ] && export TEST_JOBS=1
  t0=$(date +%s%N)
  run_case "$s" "$logs/$name.log"; rc=$?
  if [ "$rc" -eq "$timed_out" ]; then
    # A hang is not an answer: say it, keep the stacks, run the script once more (its
    # verdict then counts, and the rerun is named in the summary).
    echo "cases/$name: no end after $CASE_LIMIT s; stacks in $logs/$name.hung.log; run again"
    mv "$logs/$name.log" "$logs/$name.hung.log"; touch "$status/$name.reran"
    run_case "$s" "$logs/$name.log"; rc=$?
  fi
  rm -rf "$session"
  ms=$(( ($(date +%s%N) - t0) / 1000000 )); dt="$((ms / 1000)).$(( (ms % 1000) / 100 ))"
  if [ "$rc" -eq 0 ]; then
    printf '%-40s ok      (%ss)\n' "cases/$name" "$dt"
    # A passed case's work folders go (the suite writes some 2 GB); a failed one's stay.
    [ -n "${KEEP_WORK:-}" ] || rm -rf "$root"
  else
    # One write, so the lines of a case running beside it do not cut into it.
    printf '%s\n' "$(printf '%-40s FAILED  (%ss, exit %d); last lines of %s:' "cases/$name" "$dt" "$rc" "$logs/$name.log"; tail -15 "$logs/$name.log" | sed 's/^/    /')"
  fi
  echo "$rc" >"$status/$name"
}
# A new case starts as soon as any running one has ended, found by polling (`wait -n` misses a
# case that ended before it is called, as tests/tools/together.sh says).
pids=()
for s in tests/cases/*.sh; do
  [ -f "$s" ] || continue
  while [ ${#pids[@]} -ge "$lanes" ]; do
    alive=()
    for pid in "${pids[@]}"; do kill -0 "$pid" 2>/dev/null && alive+=("$pid"); done
    pids=("${alive[@]}")
    [ ${#pids[@]} -ge "$lanes" ] && sleep 0.2
  done
  run_one "$s" & pids+=($!)
done
wait
for s in tests/cases/*.sh; do
  [ -f "$s" ] || continue
  name=$(basename "$s" .sh)
  [ -f "$status/$name.reran" ] && reran+=("$name")
  if [ "$(cat "$status/$name" 2>/dev/null)" = 0 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); failed_names+=("$name"); fi
done

echo "total time $(( $(date +%s) - start_all )) s"
[ ${#reran[@]} -gt 0 ] && echo "run again after no end in $CASE_LIMIT s: ${reran[*]}"
[ ${#failed_names[@]} -gt 0 ] && echo "failed: ${failed_names[*]}"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]

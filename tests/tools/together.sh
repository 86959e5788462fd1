# Independent runs of one test two at a time: the suite is sized for a 2-core machine, and a
# test's runs on one rank each leave a core idle when run one after another. Sourced by the
# tests that have such runs (after tests/tools/lib.sh). TEST_JOBS=1 runs them in sequence.
# `together COMMAND...` starts COMMAND in the background (redirections given to `together`
# apply to it, but not a here-document: a background command's stdin is /dev/null), first
# waiting for a run to end while TEST_JOBS are going; `together_wait`
# waits for the rest and fails if any run failed, so a failed run fails the test as it did
# in sequence. Runs on 2 ranks (mpiexec) stay outside: they use both cores themselves.
# Each run gets its own Open MPI session directory: the suite's singletons are isolated
# (tests/run_tests.sh), so they all take job id 1 and the same /tmp/ompi.HOST.UID/jf.0/1;
# the first to finish removed it under the other, which then exited 1 after a complete run
# (seen in CI, and 1 in 120 in a loop of three concurrent runs).
TEST_JOBS=${TEST_JOBS:-2}
together_pids=()
together_failed=0
# A new run starts as soon as any running one has ended (not the oldest: a short run started
# beside a long one would leave its core idle until the long one ends). The runs that ended
# are found by polling (kill -0: bash reaps its children as they end), then waited for, which
# gives their exit status (`wait -n` loses the status of a run that ended before it is called).
together_reap() {
  local pid alive
  while :; do
    alive=()
    for pid in "${together_pids[@]}"; do
      if kill -0 "$pid" 2> /dev/null; then alive+=("$pid"); else wait "$pid" || together_failed=1; fi
    done
    together_pids=("${alive[@]}")
    [ ${#together_pids[@]} -lt "$TEST_JOBS" ] && return 0
    sleep 0.1
  done
}
together() {
  [ ${#together_pids[@]} -lt "$TEST_JOBS" ] || together_reap
  local session
  session=$(mktemp -d "${TMPDIR:-/tmp}/together.XXXXXX")
  (
    rc=0
    OMPI_MCA_orte_tmpdir_base=$session "$@" || rc=$?
    rm -rf "$session"
    exit "$rc"
  ) &
  together_pids+=($!)
}
together_wait() {
  local pid
  for pid in "${together_pids[@]}"; do wait "$pid" || together_failed=1; done
  together_pids=()
  [ "$together_failed" = 0 ]
}

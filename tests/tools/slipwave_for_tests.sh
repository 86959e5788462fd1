#!/bin/bash
# The scenario tests' slipwave ($SW in tests/tools/lib.sh), as their checks were written
# against it: stations sampled every step (-station_interval 0: closed forms at every step,
# peaks, step counts) and the full setup report (-report_verbose: the lines they grep). A
# test's own options come later on the command line (or in its option file) and win; the
# tests of the defaults (run_answers.sh, report_compact.sh) run "$SLIPWAVE_BINARY" itself.
# SLIPWAVE_TEST_OPTIONS (tests/tools/lib.sh: CD_ORDER) go before them.
exec "$SLIPWAVE_BINARY" -station_interval 0 -report_verbose ${SLIPWAVE_TEST_OPTIONS:-} "$@"

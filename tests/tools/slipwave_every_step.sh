#!/bin/bash
# The scenario tests' slipwave ($SW in lib.sh): the stations sampled every step
# (-station_interval 0), the records their checks were written against (closed forms at
# every step, peaks, step counts). A test's own -station_interval comes later on the command
# line (or in its option file) and wins; tests of the default sampling set it so.
exec "$SLIPWAVE_BINARY" -station_interval 0 "$@"

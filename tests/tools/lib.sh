# Shared by the scenario tests: paths, the MPI launcher, and a runner that keeps the log.
BUILD=${BUILD:-build}
export SLIPWAVE_BINARY="$BUILD/slipwave"
# Stations every step and the verbose report unless a test says otherwise (tests/tools/slipwave_for_tests.sh).
SW=tests/tools/slipwave_for_tests.sh
PY=/usr/bin/python3
CHECK="$PY tests/tools/checks.py"
MPIEXEC="mpiexec --oversubscribe"
[ "$(id -u)" = 0 ] && MPIEXEC="$MPIEXEC --allow-run-as-root"
# Spectral-element degree of the scenario tests that take one (SEM_DEGREE=4 bash
# tests/cases/X.sh is how tests/cases/sem_*.sh rerun a p = 1 test at p = 4, issue 14):
# `elements N` turns the p = 1 test's N cells into ceil(N / p) elements of degree p, which
# keeps the GLL nodes per wavelength. SEM_DIM=3 asks a test that takes it for hexahedra.
# The work folder is per degree and dimension.
DEGREE=${SEM_DEGREE:-1}
elements() { echo $(( ($1 + DEGREE - 1) / DEGREE )); }
# CD_ORDER=4 bash tests/cases/X.sh reruns a test with the fourth-order integrator
# (-ts_cd_order 4 on every slipwave command line of $SW, before the test's own options;
# tests/cases/fourth_order_*.sh, issue 25).
[ -n "${CD_ORDER:-}" ] && export SLIPWAVE_TEST_OPTIONS="-ts_cd_order $CD_ORDER"
# The suite (tests/run_tests.sh) gives each case a root of its own, TEST_WORK_ROOT, so the
# folders of a case and of the scripts it runs go together.
WORK="${TEST_WORK_ROOT:-$BUILD/tests/work}/$(basename "$0" .sh)${SEM_DEGREE:+_p$SEM_DEGREE}${SEM_DIM:+_${SEM_DIM}d}${CD_ORDER:+_o$CD_ORDER}"
rm -rf "$WORK"; mkdir -p "$WORK"
# 1D column options: 100 m of soil, rho 2000, vp 400, vs 200, Ricker f0 = 5 Hz, peak 0.1 m/s.
COLUMN="-regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -bc_bottom_type absorbing -input_boundary bottom
 -input_stf ricker -input_f0 5 -input_t0 0.24 -input_amplitude 0.1 -ts_max_time 2.0 -output_fields 0 -progress_interval 100"

# newmark_pulse FILE: the base acceleration of the Newmark sliding-block tests
# (config/scenes/sliding_block.yaml): A = 0.4 g for tp = 0.2 s, then rest up to 2 s, as a
# record CSV (the step written as two points 1e-9 s apart).
newmark_pulse() {
  $PY - "$1" <<'PY'
import sys
A, g, tp = 0.4, 9.81, 0.2
with open(sys.argv[1], "w") as f:
    f.write("time,acceleration\n")
    for t, a in ((0.0, A * g), (tp, A * g), (tp + 1e-9, 0.0), (2.0, 0.0)):
        f.write(f"{t:.12e},{a:.12e}\n")
PY
}

# default_companion FILE: the default scene's 2 m companion mesh (config/scenes/default.geo at
# Gmsh's size factor 2: 1 m -> 2 m cells, the window's 0.125 m -> 0.25 m; the level make run's
# band runs beside the scene, scripts/convergence_check.py --geo), for the tests that check
# what the code does with the scene (answers, paths, restarts) rather than its resolution.
default_companion() {
  gmsh -2 config/scenes/default.geo -clscale 2 -format msh41 -o "$1" > "$1.log"
}

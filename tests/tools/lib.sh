# Shared by the scenario tests: paths, the MPI launcher, and a runner that keeps the log.
BUILD=${BUILD:-build}
SW="$BUILD/slipwave"
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
WORK="$BUILD/tests/work/$(basename "$0" .sh)${SEM_DEGREE:+_p$SEM_DEGREE}${SEM_DIM:+_${SEM_DIM}d}"
rm -rf "$WORK"; mkdir -p "$WORK"
# 1D column options: 100 m of soil, rho 2000, vp 400, vs 200, Ricker f0 = 5 Hz, peak 0.1 m/s.
COLUMN="-regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -bc_bottom_type absorbing -input_boundary bottom
 -input_stf ricker -input_f0 5 -input_t0 0.24 -input_amplitude 0.1 -ts_max_time 2.0 -output_fields 0 -progress_interval 100"

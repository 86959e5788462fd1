# 1 vs 2 ranks at spectral-element degree 4 (issue 14): tests/cases/mpi_ranks.sh (the layered
# site scene, two regions, Rayleigh damping, absorbing input, rollers; station records and
# energy ledgers equal to 1e-10 of their peaks: round-off of sums in another order) with
# 34 x 16 elements of degree 4. Measured (34 x 14, before the soil box had to fit the grid):
# stations 4.7e-14 (u, v), 3.8e-11 (a); energy ledgers equal digit for digit.
set -eu
SEM_DEGREE=4 bash tests/cases/mpi_ranks.sh

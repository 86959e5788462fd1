# Energy conservation of a closed undamped system at spectral-element degree 4 (issue 14:
# "conserved to 1e-9 over 10,000 steps at p = 4"): tests/cases/energy_closed.sh (the 2D
# two-material box and the 3D box, bottom fixed, uniform initial velocity, 10,000 steps; the
# ledger's shadow energy of central differences, exact up to round-off: bound 1e-9) with
# ceil(N / 4) elements of degree 4 per direction: 3 x 2 quadrilaterals (117 GLL nodes, the
# block one element) and one hexahedron (125 nodes). Measured at commit: 3.1e-15 and 5.3e-15.
set -eu
SEM_DEGREE=4 bash tests/cases/energy_closed.sh

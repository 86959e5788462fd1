# The hysteretic column (tests/cases/hysteretic_column.sh: its independent 1D Masing solution,
# its 3 % bound and the small-motion check) at spectral-element degree 4: 100 elements, the
# Iwan stress at every GLL node (medium/hysteresis.hpp). Measured at commit: L2 0.55 % (p = 1,
# 400 cells: 0.83 %).
set -eu
SEM_DEGREE=4 bash tests/cases/hysteretic_column.sh

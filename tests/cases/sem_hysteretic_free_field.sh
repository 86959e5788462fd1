# Free-field sides beside hysteretic soil (tests/cases/hysteretic_free_field.sh: the narrow
# model against the 1D column, SV and P, 1 and 2 ranks, its bounds) at element degree 2
# (2 m elements, the Iwan stress and the memory at the column's GLL points as at the 2D
# elements' GLL nodes).
set -eu
SEM_DEGREE=2 bash tests/cases/hysteretic_free_field.sh

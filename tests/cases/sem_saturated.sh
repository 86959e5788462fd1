# The saturated scenes' modules at spectral-element degree p > 1 (issue 24 part 4), against
# the expected values and bounds of their p = 1 tests: the water table and the geostatic
# stage (saturated_water_table.sh at p = 4: sigma'_v, p = p_h to round-off, at rest), free-field
# sides on a saturated site under SV (saturated_free_field.sh at p = 4: free-field as tied and
# with gravity as without to round-off, energy), free-field sides under P
# (saturated_free_field_p.sh at p = 2: the column's pore pressure at the GLL nodes; its own
# bounds, measured 1e-14 to 3e-12), and an interface whose gap drains
# (saturated_interface_gap.sh at p = 2, the degree whose elements keep the block on element
# faces: p = p_h on every open pair, energy on 1 and 2 ranks). Measured at commit: sigma'_v 1.0e-13
# of the largest, free-field as tied to 3.9e-13 of the peak, balance 2.2e-12. Checkpoint/restart and cavitation at
# p = 2 are docs/saturated-soil.md's (their scenes take minutes there).
set -eu
SEM_DEGREE=4 bash tests/cases/saturated_water_table.sh
SEM_DEGREE=4 bash tests/cases/saturated_free_field.sh
SEM_DEGREE=2 bash tests/cases/saturated_free_field_p.sh
SEM_DEGREE=2 bash tests/cases/saturated_interface_gap.sh

# Lamb's line load (tests/cases/lamb_line_load.sh: the frequency-wavenumber reference, surface
# velocities at 25 and 50 m within 3 % relative L2, 1 vs 2 ranks to 1e-10, energy balance
# 1e-9) at spectral-element degree 4 with ceil(207 / 4) = 52 elements per direction, 4x
# coarser than p = 1 (issue 14). The point force sits on the corner node (0, 150), on the
# surface at any degree. Measured at commit: 0.60-0.69 % (p = 1: 0.3-0.9 %); the stations
# at 25 and 50 m fall inside GLL sub-cells there (on element vertices with 54 elements the
# error is 0.04-0.08 %), so most of what is left is the stations' linear interpolation.
set -eu
SEM_DEGREE=4 bash tests/cases/lamb_line_load.sh

# Gravity with Rayleigh damping at element degree 4 (issue 14): gravity_column.sh (10 m column,
# rho 2000, vp 400, horizontal motion held, fixed base, gravity from rest, damping 0.3 at 5 and
# 20 Hz) with 5 elements of degree 4 instead of 20 cells (lib.sh elements). The static answer sigma_yy = -rho g
# (H - y) is quadratic in u and lies in the degree-4 space (GLL quadrature exact for it, see
# sem_geostatic.sh), so what is left at 1 s is the residual vibration, exp(-xi 2 pi f1 t) ~ 3e-7
# of the start: bound 1e-4 of rho g H at the sub-cell centres, as at p = 1. Rayleigh damping
# acts through the same element operator, and the energy ledger must close (balance error
# below 1e-9 of the largest energy; measured 1.7e-14).
SEM_DEGREE=4 exec bash tests/cases/gravity_column.sh

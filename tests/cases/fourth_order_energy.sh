# Energy of a closed undamped system with the fourth-order integrator (issue 25):
# tests/cases/energy_closed.sh (the two-material 2D box and the 3D box, base fixed, uniform
# initial velocity, 10,000 steps) at degree 4 with -ts_cd_order 4. The ledger books the work of
# the integrator's correction force M c (problem/energy_ledger.hpp), with which central
# differences' shadow-energy identity holds again: balance error bound 1e-9 relative, as for
# central differences. That the scheme conserves its modified energy W' = W - (h^2/24)
# (K u_{n+1})^T M^-1 K u_n to 1e-9 over 10,000 steps is checked in tests/unit/test_fourth_order.cpp.
set -eu
SEM_DEGREE=4 CD_ORDER=4 bash tests/cases/energy_closed.sh

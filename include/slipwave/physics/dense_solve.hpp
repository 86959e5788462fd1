// A small dense linear solve: the constant-Q least-squares fit (normal equations, n <= 8) and
// the central difference's coupled nodal damping blocks (n <= 3) both need one, too small for
// LAPACK's call overhead to pay.
#pragma once

namespace slipwave::physics {

// Solves A x = b by Gaussian elimination with partial pivoting. A is n x n, row-major; A and
// b are overwritten (the triangular factor and the permuted right-hand side). A must be
// non-singular: a zero pivot gives inf or nan in x, not a diagnosis.
void solveDense(int n, double *A, double *b, double *x);

} // namespace slipwave::physics

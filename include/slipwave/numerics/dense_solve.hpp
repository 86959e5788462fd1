// A small dense linear solve: the constant-Q least-squares fit (normal equations, n <= 8),
// the central difference's coupled nodal damping blocks (n <= 3) and the layered site's
// global plane-wave matrix (complex, banded) all need one, too small for LAPACK to pay.
#pragma once

#include <cmath>
#include <complex>
#include <utility>

namespace slipwave::numerics {

// Solves A x = b by Gaussian elimination with partial pivoting, for T = double or
// std::complex<double>. A is n x n, row-major; A and b are overwritten (the triangular factor
// and the permuted right-hand side); x may be b itself. Rows whose multiplier is zero are
// skipped (banded matrices). A must be non-singular: a zero pivot gives inf or nan in x.
template <typename T>
void solveDense(int n, T *A, T *b, T *x) {
  for (int c = 0; c < n; ++c) {
    int p = c;
    for (int i = c + 1; i < n; ++i)
      if (std::abs(A[i * n + c]) > std::abs(A[p * n + c])) p = i;
    if (p != c) {
      for (int j = 0; j < n; ++j) std::swap(A[c * n + j], A[p * n + j]);
      std::swap(b[c], b[p]);
    }
    for (int i = c + 1; i < n; ++i) {
      const T f = A[i * n + c] / A[c * n + c];
      if (f == T(0)) continue;
      for (int j = c; j < n; ++j) A[i * n + j] -= f * A[c * n + j];
      b[i] -= f * b[c];
    }
  }
  for (int i = n - 1; i >= 0; --i) {
    T s = b[i];
    for (int j = i + 1; j < n; ++j) s -= A[i * n + j] * x[j];
    x[i] = s / A[i * n + i];
  }
}

} // namespace slipwave::numerics

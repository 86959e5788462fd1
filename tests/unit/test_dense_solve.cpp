// The small dense solve of numerics/dense_solve against systems whose solutions are known by
// construction: b = A x_true for a chosen x_true, including a matrix whose first pivot is 0
// (it needs the row exchange) and the constant-Q fit's size (8, a Hilbert-like matrix).
#include "slipwave/numerics/dense_solve.hpp"

#include "unit_check.hpp"

#include <vector>

using slipwave::numerics::solveDense;

namespace {

// Solves A x = A x_true and returns the largest |x - x_true|.
double solveError(int n, std::vector<double> A, const std::vector<double> &x_true) {
  std::vector<double> b(n, 0.0), x(n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) b[i] += A[i * n + j] * x_true[j];
  solveDense(n, A.data(), b.data(), x.data());
  double worst = 0;
  for (int i = 0; i < n; ++i) worst = std::fmax(worst, std::fabs(x[i] - x_true[i]));
  return worst;
}

} // namespace

int main() {
  // 1x1: x = b / a.
  unit::near(solveError(1, {4.0}, {-2.5}), 0, 0, 1e-15, "1x1 system");
  // 3x3 with a zero (0,0) entry: without the row exchange the first pivot divides by zero.
  unit::near(solveError(3, {0, 2, 1, 1, 1, 1, 2, 1, 3}, {1, -2, 3}), 0, 0, 1e-14, "3x3 with a zero first pivot (row exchange)");
  // A damped node block (I + s D) as the central difference builds it: s = 1e-4, D a dashpot
  // block with off-diagonal coupling.
  unit::near(solveError(3, {1 + 2e-1, 5e-2, 0, 5e-2, 1 + 3e-1, 1e-2, 0, 1e-2, 1 + 1e-1}, {0.3, -0.7, 1.1}), 0, 0, 1e-15,
             "3x3 damping block I + s D");
  // 8x8 Hilbert matrix (condition ~1.5e10): the fit's size; error bounded by cond * eps.
  std::vector<double> H(64);
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) H[i * 8 + j] = 1.0 / (i + j + 1);
  unit::near(solveError(8, H, {1, 1, 1, 1, 1, 1, 1, 1}), 0, 0, 1.5e10 * 2.2e-16 * 10, "8x8 Hilbert matrix within cond x eps");
  return unit::failures();
}

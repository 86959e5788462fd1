#include "slipwave/numerics/gll_basis.hpp"

#include <cmath>

namespace slipwave::numerics {
namespace {

// P_n(x) and P_n'(x) by the three-term recurrence.
void legendre(int n, double x, double *P, double *dP) {
  double p0 = 1, p1 = x, d0 = 0, d1 = 1;
  if (n == 0) {
    *P  = 1;
    *dP = 0;
    return;
  }
  for (int k = 2; k <= n; ++k) {
    const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
    const double d2 = d0 + (2 * k - 1) * p1; // P_k' = P_{k-2}' + (2k-1) P_{k-1}
    p0 = p1, p1 = p2, d0 = d1, d1 = d2;
  }
  *P  = p1;
  *dP = d1;
}

} // namespace

void gllPointsWeights(int p, double *x, double *w) {
  x[0] = -1;
  x[p] = 1;
  // Interior points: roots of P_p'. Newton on q = (1 - x^2) P_p', whose roots are all the
  // GLL points, from Chebyshev-Gauss-Lobatto guesses (they interlace with the GLL points).
  // (1 - x^2) P_p'' = 2x P_p' - p(p+1) P_p gives q' = -p(p+1) P_p.
  for (int i = 1; i < (p + 1) / 2; ++i) {
    double xi = -std::cos(M_PI * i / p);
    for (int it = 0; it < 100; ++it) {
      double P, dP;
      legendre(p, xi, &P, &dP);
      const double step = (1 - xi * xi) * dP / (-p * (p + 1.0) * P);
      xi -= step;
      if (std::fabs(step) < 1e-16) break;
    }
    x[i]     = xi;
    x[p - i] = -xi; // exact antisymmetry: mirrored elements see mirrored nodes
  }
  if (p % 2 == 0) x[p / 2] = 0;
  for (int i = 0; i <= p; ++i) {
    double P, dP;
    legendre(p, x[i], &P, &dP);
    w[i] = 2.0 / (p * (p + 1.0) * P * P);
  }
  for (int i = 0; i < (p + 1) / 2; ++i) w[p - i] = w[i]; // symmetric to the bit, like the points
}

void lagrangeValues(int p, const double *x, double xi, double *l) {
  for (int j = 0; j <= p; ++j) {
    double v = 1;
    for (int k = 0; k <= p; ++k)
      if (k != j) v *= (xi - x[k]) / (x[j] - x[k]);
    l[j] = v;
  }
}

void lagrangeDerivativeMatrix(int p, const double *x, double *D) {
  // Barycentric weights c_j = prod_{k != j} (x_j - x_k); off-diagonal l_j'(x_i) =
  // (c_i / c_j) / (x_i - x_j); the diagonal makes each row sum to zero.
  double c[kMaxSpectralDegree + 1];
  for (int j = 0; j <= p; ++j) {
    c[j] = 1;
    for (int k = 0; k <= p; ++k)
      if (k != j) c[j] *= x[j] - x[k];
  }
  for (int i = 0; i <= p; ++i) {
    double diag = 0;
    for (int j = 0; j <= p; ++j) {
      if (j == i) continue;
      D[i * (p + 1) + j] = (c[i] / c[j]) / (x[i] - x[j]);
      diag -= D[i * (p + 1) + j];
    }
    D[i * (p + 1) + i] = diag;
  }
}

double gllEndNodeStiffness(int p) {
  double x[kMaxSpectralDegree + 1], w[kMaxSpectralDegree + 1], D[(kMaxSpectralDegree + 1) * (kMaxSpectralDegree + 1)];
  gllPointsWeights(p, x, w);
  lagrangeDerivativeMatrix(p, x, D);
  double integral = 0; // int l_0'^2, exact by the GLL rule (degree 2p - 2)
  for (int q = 0; q <= p; ++q) integral += w[q] * D[q * (p + 1)] * D[q * (p + 1)];
  return 2 * integral;
}

} // namespace slipwave::numerics

#include "slipwave/numerics/spectral_dispersion.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "slipwave/numerics/dense_solve.hpp"
#include "slipwave/numerics/gll_basis.hpp"

namespace slipwave::numerics {

double spectralPhaseSpeedError(int p, double theta) {
  constexpr int n_max = kMaxSpectralDegree + 1;
  double        x[n_max], w[n_max], D[n_max * n_max];
  gllPointsWeights(p, x, w);
  lagrangeDerivativeMatrix(p, x, D);
  // The element [-1, 1] of a medium with c = 1 and unit density: K_ij = int l_i' l_j' (the
  // GLL rule is exact for the degree 2p - 2 integrand), M = diag(w); theta = 2 k, Omega = k.
  const int    n      = p + 1;
  const double omega2 = 0.25 * theta * theta;
  double       S[n_max * n_max] = {};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double k = 0;
      for (int q = 0; q < n; ++q) k += w[q] * D[q * n + i] * D[q * n + j];
      S[i * n + j] = k - (i == j ? omega2 * w[i] : 0.0);
    }
  // Condensed onto the ends: a = S_00 - S_0I S_II^-1 S_I0, b = S_0p - S_0I S_II^-1 S_Ip.
  double a = S[0], b = S[p];
  if (p > 1) {
    const int m = p - 1;
    double    A[n_max * n_max], r0[n_max], rp[n_max], y0[n_max], yp[n_max];
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < m; ++j) A[i * m + j] = S[(i + 1) * n + (j + 1)];
      r0[i] = S[(i + 1) * n], rp[i] = S[(i + 1) * n + p];
    }
    double B[n_max * n_max];
    std::copy(A, A + m * m, B);
    solveDense(m, A, r0, y0); // y0 = S_II^-1 S_I0
    solveDense(m, B, rp, yp); // yp = S_II^-1 S_Ip
    for (int i = 0; i < m; ++i) {
      a -= S[i + 1] * y0[i];
      b -= S[i + 1] * yp[i];
    }
  }
  const double cos_h   = std::clamp(-a / b, -1.0, 1.0);
  const double theta_0 = std::acos(cos_h);
  // Unfolded: 2 pi j +- theta_0, the one nearest theta.
  double best = theta_0;
  for (int j = 0; j <= p + 1; ++j)
    for (double cand : {2 * M_PI * j + theta_0, 2 * M_PI * j - theta_0})
      if (std::fabs(cand - theta) < std::fabs(best - theta)) best = cand;
  return theta / best - 1;
}

double spectralDispersionBound(int p, double nodes_per_wavelength) {
  constexpr int samples   = 256;
  const double  theta_max = 2 * M_PI * p / nodes_per_wavelength;
  double        worst     = 0;
  for (int s = 1; s <= samples; ++s) worst = std::max(worst, std::fabs(spectralPhaseSpeedError(p, theta_max * s / samples)));
  return worst;
}

} // namespace slipwave::numerics

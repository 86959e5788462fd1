// GLL points, weights, Lagrange basis and derivative matrix against closed forms and the
// exactness properties that define them.
#include "slipwave/numerics/gll_basis.hpp"

#include "unit_check.hpp"

#include <cmath>
#include <string>

using namespace slipwave::numerics;

int main() {
  constexpr int N = kMaxSpectralDegree + 1;
  double        x[N], w[N], D[N * N], l[N];
  // Closed forms (e.g. Abramowitz & Stegun 25.4.32; Canuto et al., Spectral Methods, 2.3):
  // p = 2: 0, weights 1/3, 4/3; p = 3: +-1/sqrt(5), weights 1/6, 5/6;
  // p = 4: 0, +-sqrt(3/7), weights 1/10, 49/90, 32/45.
  gllPointsWeights(2, x, w);
  unit::near(x[1], 0, 0, 0, "p=2 middle point");
  unit::near(w[0], 1.0 / 3, 0, 1e-15, "p=2 end weight 1/3");
  unit::near(w[1], 4.0 / 3, 0, 1e-15, "p=2 middle weight 4/3");
  gllPointsWeights(3, x, w);
  unit::near(x[2], 1 / std::sqrt(5.0), 0, 1e-15, "p=3 point 1/sqrt(5)");
  unit::near(w[1], 5.0 / 6, 0, 1e-15, "p=3 weight 5/6");
  gllPointsWeights(4, x, w);
  unit::near(x[3], std::sqrt(3.0 / 7), 0, 1e-15, "p=4 point sqrt(3/7)");
  unit::near(w[0], 0.1, 0, 1e-15, "p=4 end weight 1/10");
  unit::near(w[1], 49.0 / 90, 0, 1e-15, "p=4 weight 49/90");
  unit::near(w[2], 32.0 / 45, 0, 1e-15, "p=4 middle weight 32/45");

  for (int p = 1; p <= kMaxSpectralDegree; ++p) {
    gllPointsWeights(p, x, w);
    const std::string tag = "p=" + std::to_string(p) + " ";
    bool ascending = true, mirrored = true;
    for (int i = 0; i < p; ++i) ascending = ascending && x[i] < x[i + 1];
    for (int i = 0; i <= p; ++i) mirrored = mirrored && x[p - i] == -x[i] && w[p - i] == w[i];
    unit::check(ascending && x[0] == -1 && x[p] == 1, tag + "points ascending from -1 to 1");
    unit::check(mirrored, tag + "points and weights exactly symmetric");
    // The rule is exact for degree 2p-1: integral of x^k over [-1,1] = 2/(k+1) for even k.
    double worst = 0;
    for (int k = 0; k <= 2 * p - 1; ++k) {
      double q = 0;
      for (int i = 0; i <= p; ++i) q += w[i] * std::pow(x[i], k);
      worst = std::fmax(worst, std::fabs(q - (k % 2 == 0 ? 2.0 / (k + 1) : 0.0)));
    }
    unit::near(worst, 0, 0, 1e-14, tag + "quadrature exact to degree 2p-1");
    // D differentiates x^k exactly for k <= p; the basis reproduces x^p at an off-node point.
    lagrangeDerivativeMatrix(p, x, D);
    worst = 0;
    for (int k = 0; k <= p; ++k)
      for (int i = 0; i <= p; ++i) {
        double d = 0;
        for (int j = 0; j <= p; ++j) d += D[i * (p + 1) + j] * std::pow(x[j], k);
        worst = std::fmax(worst, std::fabs(d - (k == 0 ? 0.0 : k * std::pow(x[i], k - 1))));
      }
    unit::near(worst, 0, 0, 1e-12, tag + "derivative matrix exact on x^k, k <= p");
    lagrangeValues(p, x, 0.3141, l);
    double one = 0, xp = 0;
    for (int j = 0; j <= p; ++j) one += l[j], xp += l[j] * std::pow(x[j], p);
    unit::near(one, 1, 0, 1e-14, tag + "basis sums to one");
    unit::near(xp, std::pow(0.3141, p), 0, 1e-14, tag + "basis reproduces x^p");
    // The end node's stiffness factor against the closed form (p^2 + p + 1)/3 (gll_basis.hpp).
    unit::near(gllEndNodeStiffness(p), (p * p + p + 1) / 3.0, 1e-12, 0, tag + "end-node stiffness (p^2 + p + 1)/3");
  }
  return unit::failures();
}

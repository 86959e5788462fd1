// The u-p element operators of degree p (fem/spectral_biot.hpp) against what holds exactly:
// the coupling's nodal divergence of translations (0) and of u = x (dim w|J| at each node, on
// curved elements too: x is in the isoparametric space); the transpose kernel against the
// dense Q; a constant pressure's nodal forces summing to zero; H symmetric, positive
// semi-definite, with the constants in its null space; on a rectangle H against its tensor
// form K_x (x) M_y + M_x (x) K_y built here from the 1D GLL rule; the storage sums to the
// element's volume; and Q^T S^{-1} Q against the elastic element with lambda = alpha^2 M,
// mu = 0 (what the undrained step bound of porous/pore_pressure.cpp relies on).
#include "slipwave/fem/spectral_biot.hpp"

#include "slipwave/fem/spectral_kernels.hpp"
#include "slipwave/numerics/gll_basis.hpp"
#include "unit_check.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace slipwave::fem;
using namespace slipwave::numerics;

namespace {

// GLL nodes of degree p mapped by x = F(xi): a box of sides L scaled into [0, L], skewed by
// `skew` and bent by `bend` (a quadratic term, so the map is curved at p >= 2).
std::vector<double> mappedNodes(int dim, int p, const double *L, double skew, double bend) {
  double x[9], w[9];
  gllPointsWeights(p, x, w);
  const int           n1 = p + 1, nz = dim == 3 ? n1 : 1;
  std::vector<double> c((size_t)spectralNodeCount(dim, p) * dim);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < n1; ++j)
      for (int i = 0; i < n1; ++i) {
        const double s[3] = {x[i], x[j], dim == 3 ? x[k] : 0.0};
        double      *X    = &c[(size_t)(i + n1 * (j + n1 * k)) * dim];
        for (int d = 0; d < dim; ++d) X[d] = 0.5 * L[d] * (1 + s[d]);
        X[0] += skew * s[1] + bend * s[1] * s[1];
        X[1] += 0.5 * skew * s[0] - bend * s[0] * s[0];
      }
  return c;
}

double maxAbs(const std::vector<double> &v) {
  double m = 0;
  for (double a : v) m = std::max(m, std::fabs(a));
  return m;
}

std::vector<double> derivative1D(int p) {
  double              x[9], w[9];
  std::vector<double> D((size_t)(p + 1) * (p + 1));
  gllPointsWeights(p, x, w);
  lagrangeDerivativeMatrix(p, x, D.data());
  return D;
}

// H of the rectangle [0, a] x [0, b] from the 1D GLL matrices: K1_ij = (2/L) sum_q w_q D_qi D_qj,
// M1 = (L/2) diag(w); node (i, j) is i + (p+1) j.
std::vector<double> rectangleDiffusion(int p, double a, double b) {
  double x[9], w[9];
  gllPointsWeights(p, x, w);
  const std::vector<double> D  = derivative1D(p);
  const int                 n1 = p + 1, nq = n1 * n1;
  auto                      K1 = [&](double L, int i, int j) {
    double s = 0;
    for (int q = 0; q < n1; ++q) s += w[q] * D[q * n1 + i] * D[q * n1 + j];
    return 2 / L * s;
  };
  std::vector<double> H((size_t)nq * nq, 0.0);
  for (int j1 = 0; j1 < n1; ++j1)
    for (int i1 = 0; i1 < n1; ++i1)
      for (int j2 = 0; j2 < n1; ++j2)
        for (int i2 = 0; i2 < n1; ++i2) {
          double h = 0;
          if (j1 == j2) h += K1(a, i1, i2) * 0.5 * b * w[j1];
          if (i1 == i2) h += 0.5 * a * w[i1] * K1(b, j1, j2);
          H[(size_t)(i1 + n1 * j1) * nq + i2 + n1 * j2] = h;
        }
  return H;
}

} // namespace

int main() {
  const double L[3] = {2.0, 1.5, 1.2};
  for (int dim = 2; dim <= 3; ++dim)
    for (int p = 1; p <= 6; ++p)
      for (int curved = 0; curved <= 1; ++curved) {
        const std::string tag = std::to_string(dim) + "D p=" + std::to_string(p) + (curved ? " curved: " : " parallelogram: ");
        const int         nq = spectralNodeCount(dim, p), n = dim * nq;
        const auto        coords = mappedNodes(dim, p, L, 0.2, curved && p > 1 ? 0.08 : 0.0);
        std::vector<double> wdet(nq), jinv((size_t)nq * dim * dim), Q((size_t)nq * n), H((size_t)nq * nq), ue(n), fe(n), pe(nq), out(nq);
        unit::check(spectralGeometry(dim, p, coords.data(), wdet.data(), jinv.data()), tag + "element accepted");
        const std::vector<double> D = derivative1D(p);
        spectralCouplingMatrix(dim, p, wdet.data(), jinv.data(), Q.data());
        spectralDiffusionMatrix(dim, p, wdet.data(), jinv.data(), H.data());
        const double qscale = maxAbs(Q), hscale = maxAbs(H);

        // Translations have no divergence: every row of Q sums to 0 per component.
        double worst = 0;
        for (int a = 0; a < nq; ++a)
          for (int j = 0; j < dim; ++j) {
            double s = 0;
            for (int b = 0; b < nq; ++b) s += Q[(size_t)a * n + b * dim + j];
            worst = std::max(worst, std::fabs(s));
          }
        unit::near(worst / qscale, 0, 0, 1e-13, tag + "Q of a translation is 0");
        // u = x: div u = dim at every node, so (Q u)_a = dim w_a |J_a|.
        for (int a = 0; a < nq; ++a)
          for (int j = 0; j < dim; ++j) ue[a * dim + j] = coords[a * dim + j];
        spectralDivergence(dim, p, D.data(), wdet.data(), jinv.data(), ue.data(), out.data());
        worst = 0;
        for (int a = 0; a < nq; ++a) worst = std::max(worst, std::fabs(out[a] - dim * wdet[a]) / wdet[a]);
        unit::near(worst, 0, 0, 1e-12, tag + "Q of u = x is dim w|J| at every node (patch test)");

        // The transpose kernel is the transpose of the divergence kernel.
        for (int a = 0; a < nq; ++a) pe[a] = std::sin(1.3 * a + 0.4) + 0.2 * (a % 3);
        spectralDivergenceTranspose(dim, p, D.data(), wdet.data(), jinv.data(), pe.data(), fe.data());
        worst = 0;
        for (int c = 0; c < n; ++c) {
          double s = 0;
          for (int a = 0; a < nq; ++a) s += Q[(size_t)a * n + c] * pe[a];
          worst = std::max(worst, std::fabs(fe[c] - s));
        }
        unit::near(worst / (qscale * maxAbs(pe)), 0, 0, 1e-13, tag + "Q^T p kernel = transpose of Q");
        // A constant pressure is in equilibrium with itself: its nodal forces sum to 0.
        std::fill(pe.begin(), pe.end(), 1.0);
        spectralDivergenceTranspose(dim, p, D.data(), wdet.data(), jinv.data(), pe.data(), fe.data());
        worst = 0;
        for (int j = 0; j < dim; ++j) {
          double s = 0;
          for (int b = 0; b < nq; ++b) s += fe[b * dim + j];
          worst = std::max(worst, std::fabs(s));
        }
        unit::near(worst / qscale, 0, 0, 1e-13, tag + "Q^T of a constant pressure sums to 0");

        // H: symmetric, H 1 = 0, p^T H p >= 0, and the kernel applies the dense matrix.
        double asym = 0, null = 0;
        for (int a = 0; a < nq; ++a) {
          double s = 0;
          for (int b = 0; b < nq; ++b) {
            s += H[(size_t)a * nq + b];
            asym = std::max(asym, std::fabs(H[(size_t)a * nq + b] - H[(size_t)b * nq + a]));
          }
          null = std::max(null, std::fabs(s));
        }
        unit::near(asym / hscale, 0, 0, 1e-13, tag + "H symmetric");
        unit::near(null / hscale, 0, 0, 1e-13, tag + "H of a constant is 0");
        double energy = 0, norm = 0;
        for (int a = 0; a < nq; ++a) pe[a] = std::cos(2.1 * a + 0.7) * (a % 2 ? 1 : -1);
        spectralDiffusion(dim, p, D.data(), wdet.data(), jinv.data(), pe.data(), out.data());
        worst = 0;
        for (int a = 0; a < nq; ++a) {
          double s = 0;
          for (int b = 0; b < nq; ++b) s += H[(size_t)a * nq + b] * pe[b];
          worst = std::max(worst, std::fabs(out[a] - s));
          energy += pe[a] * out[a];
          norm += pe[a] * pe[a];
        }
        unit::near(worst / (hscale * maxAbs(pe)), 0, 0, 1e-13, tag + "H p kernel = dense H");
        unit::check(energy > 0 && energy >= 1e-6 * hscale * norm, tag + "p^T H p > 0 for a non-constant p");

        // Storage w|J| / M: the element's volume over M. The parallelogram's constant
        // det J = (L0 L1 / 4 - skew^2 / 2) (L2 / 2 in 3D) times the reference volume 2^dim.
        double volume = 0;
        for (int a = 0; a < nq; ++a) volume += wdet[a];
        const double exact = (L[0] * L[1] - 2 * 0.2 * 0.2) * (dim == 3 ? L[2] : 1.0);
        if (!curved) unit::near(volume, exact, 1e-13, 0, tag + "storage sums to the volume");

        // Q^T S^-1 Q (S = w|J| / M, alpha = 1) = the elastic element with lambda = M, mu = 0.
        const double        M = 2.5e9;
        std::vector<double> A((size_t)n * n, 0.0), K((size_t)n * n);
        for (int a = 0; a < nq; ++a)
          for (int r = 0; r < n; ++r)
            for (int c = 0; c < n; ++c) A[(size_t)r * n + c] += Q[(size_t)a * n + r] * M / wdet[a] * Q[(size_t)a * n + c];
        spectralElementStiffness(dim, p, wdet.data(), jinv.data(), LameParameters{M, 0.0}, K.data());
        worst = 0;
        for (size_t r = 0; r < A.size(); ++r) worst = std::max(worst, std::fabs(A[r] - K[r]));
        unit::near(worst / maxAbs(K), 0, 0, 1e-12, tag + "Q^T S^-1 Q = elastic element with lambda = alpha^2 M, mu = 0");
      }

  // H on rectangles against the tensor form (independent of the kernel's J^{-1} route).
  for (int p = 1; p <= 8; ++p) {
    const double a = 2.0, b = 0.7, sides[3] = {a, b, 1.0};
    const int    nq = spectralNodeCount(2, p);
    const auto   coords = mappedNodes(2, p, sides, 0.0, 0.0);
    std::vector<double> wdet(nq), jinv((size_t)nq * 4), H((size_t)nq * nq);
    spectralGeometry(2, p, coords.data(), wdet.data(), jinv.data());
    spectralDiffusionMatrix(2, p, wdet.data(), jinv.data(), H.data());
    const auto ref = rectangleDiffusion(p, a, b);
    double     worst = 0;
    for (size_t r = 0; r < H.size(); ++r) worst = std::max(worst, std::fabs(H[r] - ref[r]));
    unit::near(worst / maxAbs(ref), 0, 0, 1e-13, "2D p=" + std::to_string(p) + " rectangle: H = K_x (x) M_y + M_x (x) K_y");
  }
  return unit::failures();
}

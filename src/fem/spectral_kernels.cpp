#include "slipwave/fem/spectral_kernels.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "slipwave/fem/spectral_force_kernel.hpp"
#include "slipwave/numerics/gll_basis.hpp"

namespace slipwave::fem {
namespace {

// The 1D ingredients of degree p.
struct Gll1D {
  double x[kMaxSpectralNodes1D], w[kMaxSpectralNodes1D], D[kMaxSpectralNodes1D * kMaxSpectralNodes1D];
  explicit Gll1D(int p) {
    numerics::gllPointsWeights(p, x, w);
    numerics::lagrangeDerivativeMatrix(p, x, D);
  }
};

// Inverse and determinant of the dim x dim matrix J (row-major); inv row-major.
double invert(int dim, const double *J, double *inv) {
  if (dim == 2) {
    const double det = J[0] * J[3] - J[1] * J[2];
    inv[0] = J[3] / det, inv[1] = -J[1] / det, inv[2] = -J[2] / det, inv[3] = J[0] / det;
    return det;
  }
  const double c00 = J[4] * J[8] - J[5] * J[7], c01 = J[5] * J[6] - J[3] * J[8], c02 = J[3] * J[7] - J[4] * J[6];
  const double det = J[0] * c00 + J[1] * c01 + J[2] * c02;
  inv[0] = c00 / det, inv[1] = (J[2] * J[7] - J[1] * J[8]) / det, inv[2] = (J[1] * J[5] - J[2] * J[4]) / det;
  inv[3] = c01 / det, inv[4] = (J[0] * J[8] - J[2] * J[6]) / det, inv[5] = (J[2] * J[3] - J[0] * J[5]) / det;
  inv[6] = c02 / det, inv[7] = (J[1] * J[6] - J[0] * J[7]) / det, inv[8] = (J[0] * J[4] - J[1] * J[3]) / det;
  return det;
}

// l_j'(xi) of the Lagrange basis on the nodes x: sum over m != j of the product rule term.
void lagrangeDerivatives(int p, const double *x, double xi, double *dl) {
  for (int j = 0; j <= p; ++j) {
    double s = 0;
    for (int m = 0; m <= p; ++m) {
      if (m == j) continue;
      double v = 1 / (x[j] - x[m]);
      for (int k = 0; k <= p; ++k)
        if (k != j && k != m) v *= (xi - x[k]) / (x[j] - x[k]);
      s += v;
    }
    dl[j] = s;
  }
}

template <int P, int DIM>
void forceNodeMajor(const double *D, const double *wdet, const double *jinv, const LameParameters &m, const double *ue, double *fe) {
  constexpr int NQ = SpectralShape<P, DIM>::NQ;
  double        u[DIM * NQ], f[DIM * NQ];
  for (int q = 0; q < NQ; ++q)
    for (int c = 0; c < DIM; ++c) u[c * NQ + q] = ue[q * DIM + c];
  spectralForce<P, DIM, double>(D, wdet, jinv, m.lambda, m.mu, u, f);
  for (int q = 0; q < NQ; ++q)
    for (int c = 0; c < DIM; ++c) fe[q * DIM + c] = f[c * NQ + q];
}

using ForceFn = void (*)(const double *, const double *, const double *, const LameParameters &, const double *, double *);

template <int DIM>
ForceFn forceOfDegree(int p) {
  switch (p) {
  case 1: return forceNodeMajor<1, DIM>;
  case 2: return forceNodeMajor<2, DIM>;
  case 3: return forceNodeMajor<3, DIM>;
  case 4: return forceNodeMajor<4, DIM>;
  case 5: return forceNodeMajor<5, DIM>;
  case 6: return forceNodeMajor<6, DIM>;
  case 7: return forceNodeMajor<7, DIM>;
  case 8: return forceNodeMajor<8, DIM>;
  default: return nullptr;
  }
}

} // namespace

int spectralNodeCount(int dim, int p) { return dim == 2 ? (p + 1) * (p + 1) : (p + 1) * (p + 1) * (p + 1); }

bool spectralGeometry(int dim, int p, const double *coords, double *wdet, double *jinv) {
  const Gll1D g(p);
  const int   n1 = p + 1, nz = dim == 3 ? n1 : 1;
  const int   stride[3] = {1, n1, n1 * n1};
  double      sign = 0;
  for (int i2 = 0; i2 < nz; ++i2)
    for (int i1 = 0; i1 < n1; ++i1)
      for (int i0 = 0; i0 < n1; ++i0) {
        const int q = i0 + n1 * (i1 + n1 * i2), idx[3] = {i0, i1, i2};
        double    J[9]; // J[i * dim + k] = d x_i / d xi_k
        for (int k = 0; k < dim; ++k) {
          const int base = q - idx[k] * stride[k];
          for (int i = 0; i < dim; ++i) {
            double s = 0;
            for (int m = 0; m < n1; ++m) s += g.D[idx[k] * n1 + m] * coords[(base + m * stride[k]) * dim + i];
            J[i * dim + k] = s;
          }
        }
        const double det = invert(dim, J, jinv + q * dim * dim);
        if (!(det != 0) || !std::isfinite(det)) return false;
        if (sign == 0) sign = det > 0 ? 1 : -1;
        if (det * sign <= 0) return false;
        wdet[q] = g.w[i0] * g.w[i1] * (dim == 3 ? g.w[i2] : 1.0) * std::fabs(det);
      }
  return true;
}

void spectralLumpedMass(int dim, int p, const double *wdet, double rho, double *mass) {
  const int nq = spectralNodeCount(dim, p);
  for (int q = 0; q < nq; ++q) mass[q] = rho * wdet[q];
}

void spectralElementForce(int dim, int p, const double *wdet, const double *jinv, const LameParameters &m, const double *ue, double *fe) {
  const Gll1D g(p);
  spectralElementForce(dim, p, g.D, wdet, jinv, m, ue, fe);
}

void spectralElementForce(int dim, int p, const double *D, const double *wdet, const double *jinv, const LameParameters &m, const double *ue, double *fe) {
  const ForceFn f = dim == 2 ? forceOfDegree<2>(p) : forceOfDegree<3>(p);
  f(D, wdet, jinv, m, ue, fe);
}

namespace {

// K column by column: cols[j * n + r] = (K e_j)_r (each column written contiguously).
std::vector<double> stiffnessColumns(int dim, int p, const double *wdet, const double *jinv, const LameParameters &m) {
  const Gll1D         g(p);
  const ForceFn       f = dim == 2 ? forceOfDegree<2>(p) : forceOfDegree<3>(p);
  const int           n = dim * spectralNodeCount(dim, p);
  std::vector<double> cols((size_t)n * n), e(n, 0.0);
  for (int j = 0; j < n; ++j) {
    e[j] = 1;
    f(g.D, wdet, jinv, m, e.data(), &cols[(size_t)j * n]);
    e[j] = 0;
  }
  return cols;
}

// Collatz-Wielandt bound of A = diag(1/mass) |K| from `iterations` power steps.
double collatzWielandt(int n, const std::vector<double> &cols, const double *mass, int iterations) {
  std::vector<double> d(n, 1.0), y(n);
  double              best = HUGE_VAL;
  for (int it = 0; it <= iterations; ++it) {
    std::fill(y.begin(), y.end(), 0.0);
    for (int j = 0; j < n; ++j)
      for (int r = 0; r < n; ++r) y[r] += std::fabs(cols[(size_t)j * n + r]) * d[j];
    double bound = 0, ymax = 0;
    for (int r = 0; r < n; ++r) {
      y[r] /= mass[r];
      bound = std::max(bound, y[r] / d[r]);
      ymax  = std::max(ymax, y[r]);
    }
    best = std::min(best, bound);
    // |K| has a positive diagonal, so y > 0 whenever d > 0: every d stays positive.
    for (int r = 0; r < n; ++r) d[r] = y[r] / ymax;
  }
  return best;
}

// The largest eigenvalue of the symmetric tridiagonal matrix (diagonal a, off-diagonal b)
// by bisection on its Sturm sequence (the count of eigenvalues below x), to round-off.
double tridiagonalLargest(const std::vector<double> &a, const std::vector<double> &b) {
  const int m  = (int)a.size();
  double    lo = HUGE_VAL, hi = -HUGE_VAL;
  for (int i = 0; i < m; ++i) {
    const double radius = (i > 0 ? std::fabs(b[i - 1]) : 0.0) + (i + 1 < m ? std::fabs(b[i]) : 0.0);
    lo = std::min(lo, a[i] - radius), hi = std::max(hi, a[i] + radius);
  }
  const auto below = [&](double x) {
    int    count = 0;
    double d     = 1;
    for (int i = 0; i < m; ++i) {
      d = a[i] - x - (i > 0 ? b[i - 1] * b[i - 1] / d : 0.0);
      if (d == 0) d = -1e-300;
      count += d < 0;
    }
    return count;
  };
  while (hi - lo > 4 * 0x1p-53 * std::max(std::fabs(lo), std::fabs(hi))) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (below(mid) == m ? hi : lo) = mid;
  }
  return lo;
}

// The largest Ritz value of S = diag(s) K diag(s) (K by columns): Lanczos with full
// re-orthogonalisation, up to kLanczosSteps steps. A Ritz value never exceeds the largest
// eigenvalue; for the elements here it reaches it to round-off, whatever the start, so the
// same cell gives the same value in any orientation (another rank's) up to round-off. (A
// power iteration of 300 steps was 0.2 % short at p = 3, by an amount that depended on the
// orientation, so the step on the partition.) The start is a fixed scrambled vector: a
// symmetric one (a constant: a rigid translation; a checkerboard) keeps the Krylov space in
// one symmetry class of a symmetric element, which need not hold the highest mode.
double largestRitzValue(int n, const std::vector<double> &cols, const std::vector<double> &s) {
  constexpr int       kLanczosSteps = 120;
  const int           steps         = std::min(n, kLanczosSteps);
  std::vector<double> basis, v(n), w(n), a, b;
  for (int r = 0; r < n; ++r) v[r] = 0.5 + std::fmod(0.6180339887498949 * (r + 1), 1.0);
  double norm = 0;
  for (double x : v) norm += x * x;
  for (double &x : v) x /= std::sqrt(norm);
  double lambda = 0;
  for (int j = 0; j < steps; ++j) {
    basis.insert(basis.end(), v.begin(), v.end());
    std::fill(w.begin(), w.end(), 0.0);
    for (int c = 0; c < n; ++c)
      for (int r = 0; r < n; ++r) w[r] += cols[(size_t)c * n + r] * s[c] * v[c];
    double alpha = 0;
    for (int r = 0; r < n; ++r) w[r] *= s[r], alpha += w[r] * v[r];
    a.push_back(alpha);
    // Two passes of Gram-Schmidt against every basis vector keep the basis orthogonal.
    for (int pass = 0; pass < 2; ++pass)
      for (int k = 0; k <= j; ++k) {
        const double *q   = &basis[(size_t)k * n];
        double        dot = 0;
        for (int r = 0; r < n; ++r) dot += w[r] * q[r];
        for (int r = 0; r < n; ++r) w[r] -= dot * q[r];
      }
    lambda      = tridiagonalLargest(a, b);
    double beta = 0;
    for (double x : w) beta += x * x;
    beta = std::sqrt(beta);
    if (!(beta > 1e-13 * std::fabs(lambda))) break; // an invariant subspace: its Ritz values are exact
    b.push_back(beta);
    for (int r = 0; r < n; ++r) v[r] = w[r] / beta;
  }
  return lambda;
}

// True when sigma I - S (S = diag(s) K diag(s), s = mass^{-1/2}) is proven positive definite:
// floating-point Cholesky of B - alpha I succeeds, alpha covering the factorisation's
// round-off (Rump 2006: gamma_{n+1} / (1 - gamma_{n+1}) trace(B), doubled) and the rounding
// and asymmetry of B as formed here (n times its largest entry error).
bool provenAbove(int n, const std::vector<double> &cols, const std::vector<double> &s, double sigma) {
  const double        eps = 0x1p-53, gamma = (n + 1) * eps / (1 - (n + 1) * eps);
  std::vector<double> B((size_t)n * n);
  double              trace = 0, entry_error = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j) {
      const double kij = cols[(size_t)j * n + i], kji = cols[(size_t)i * n + j];
      B[(size_t)i * n + j] = (i == j ? sigma : 0.0) - kij * s[i] * s[j];
      entry_error          = std::max(entry_error, std::fabs(kij - kji) * s[i] * s[j] + 4 * eps * (std::fabs(B[(size_t)i * n + j]) + (i == j ? sigma : 0.0)));
      if (i == j) trace += B[(size_t)i * n + i];
    }
  if (!(trace > 0)) return false;
  const double alpha = 2 * gamma / (1 - gamma) * trace + n * entry_error;
  for (int i = 0; i < n; ++i) B[(size_t)i * n + i] -= alpha;
  for (int j = 0; j < n; ++j) {
    double *Lj = &B[(size_t)j * n];
    double  d  = Lj[j];
    for (int k = 0; k < j; ++k) d -= Lj[k] * Lj[k];
    if (!(d > 0)) return false;
    Lj[j] = std::sqrt(d);
    for (int i = j + 1; i < n; ++i) {
      double *Li = &B[(size_t)i * n];
      double  v  = Li[j];
      for (int k = 0; k < j; ++k) v -= Li[k] * Lj[k];
      Li[j] = v / Lj[j];
    }
  }
  return true;
}

} // namespace

void spectralElementStiffness(int dim, int p, const double *wdet, const double *jinv, const LameParameters &m, double *K) {
  const Gll1D         g(p);
  const ForceFn       f = dim == 2 ? forceOfDegree<2>(p) : forceOfDegree<3>(p);
  const int           n = dim * spectralNodeCount(dim, p);
  std::vector<double> e(n, 0.0), col(n);
  for (int j = 0; j < n; ++j) {
    e[j] = 1;
    f(g.D, wdet, jinv, m, e.data(), col.data());
    e[j] = 0;
    for (int r = 0; r < n; ++r) K[r * n + j] = col[r];
  }
}

void spectralElementRowAbsSums(int dim, int p, const double *wdet, const double *jinv, const LameParameters &m, double *rowabs) {
  const int  n    = dim * spectralNodeCount(dim, p);
  const auto cols = stiffnessColumns(dim, p, wdet, jinv, m);
  std::fill(rowabs, rowabs + n, 0.0);
  for (int j = 0; j < n; ++j)
    for (int r = 0; r < n; ++r) rowabs[r] += std::fabs(cols[(size_t)j * n + r]);
}

double spectralElementEigenBound(int dim, int p, const double *wdet, const double *jinv, const LameParameters &m, double rho, EigenBoundKind kind) {
  const int           nq = spectralNodeCount(dim, p), n = dim * nq;
  const auto          cols = stiffnessColumns(dim, p, wdet, jinv, m);
  std::vector<double> mass(n);
  for (int r = 0; r < n; ++r) mass[r] = rho * wdet[r / dim];
  if (kind == EigenBoundKind::Gershgorin) return collatzWielandt(n, cols, mass.data(), 0);
  const double cw = collatzWielandt(n, cols, mass.data(), 30);
  if (kind == EigenBoundKind::CollatzWielandt) return cw;
  // lambda~: the largest Ritz value of S = M^{-1/2} K M^{-1/2} (a lower bound).
  std::vector<double> s(n);
  for (int r = 0; r < n; ++r) s[r] = 1 / std::sqrt(mass[r]);
  const double lambda = largestRitzValue(n, cols, s);
  for (int k = 0; k < 5; ++k) {
    const double sigma = lambda * (1 + 0.005 * std::pow(3.0, k));
    if (sigma >= cw) break;
    if (provenAbove(n, cols, s, sigma)) return sigma;
  }
  return cw;
}

void spectralBasisValues(int dim, int p, const double *xi, double *N) {
  const Gll1D g(p);
  double      l[3][kMaxSpectralNodes1D];
  for (int k = 0; k < dim; ++k) numerics::lagrangeValues(p, g.x, xi[k], l[k]);
  const int n1 = p + 1, nz = dim == 3 ? n1 : 1;
  for (int i2 = 0; i2 < nz; ++i2)
    for (int i1 = 0; i1 < n1; ++i1)
      for (int i0 = 0; i0 < n1; ++i0) N[i0 + n1 * (i1 + n1 * i2)] = l[0][i0] * l[1][i1] * (dim == 3 ? l[2][i2] : 1.0);
}

bool spectralStress(int dim, int p, const double *coords, const LameParameters &m, const double *ue, const double *xi, double *sigma) {
  const Gll1D g(p);
  double      l[3][kMaxSpectralNodes1D], dl[3][kMaxSpectralNodes1D];
  for (int k = 0; k < dim; ++k) {
    numerics::lagrangeValues(p, g.x, xi[k], l[k]);
    lagrangeDerivatives(p, g.x, xi[k], dl[k]);
  }
  const int n1 = p + 1, nz = dim == 3 ? n1 : 1;
  double    J[9] = {0}, G[9] = {0}; // J[i][k] = d x_i / d xi_k, G[c][k] = d u_c / d xi_k
  for (int i2 = 0; i2 < nz; ++i2)
    for (int i1 = 0; i1 < n1; ++i1)
      for (int i0 = 0; i0 < n1; ++i0) {
        const int a = i0 + n1 * (i1 + n1 * i2), idx[3] = {i0, i1, i2};
        for (int k = 0; k < dim; ++k) {
          double dN = 1;
          for (int s = 0; s < dim; ++s) dN *= s == k ? dl[s][idx[s]] : l[s][idx[s]];
          for (int i = 0; i < dim; ++i) {
            J[i * dim + k] += coords[a * dim + i] * dN;
            G[i * dim + k] += ue[a * dim + i] * dN;
          }
        }
      }
  double    Jinv[9];
  const double det = invert(dim, J, Jinv);
  if (!(det != 0) || !std::isfinite(det)) return false;
  double H[3][3] = {{0}}; // H[c][i] = d u_c / d x_i
  for (int c = 0; c < dim; ++c)
    for (int i = 0; i < dim; ++i)
      for (int k = 0; k < dim; ++k) H[c][i] += G[c * dim + k] * Jinv[k * dim + i];
  const double tr = H[0][0] + H[1][1] + H[2][2];
  sigma[0] = m.lambda * tr + 2 * m.mu * H[0][0];
  sigma[1] = m.lambda * tr + 2 * m.mu * H[1][1];
  sigma[2] = m.lambda * tr + 2 * m.mu * H[2][2];
  sigma[3] = m.mu * (H[0][1] + H[1][0]);
  sigma[4] = m.mu * (H[1][2] + H[2][1]);
  sigma[5] = m.mu * (H[0][2] + H[2][0]);
  return true;
}

} // namespace slipwave::fem

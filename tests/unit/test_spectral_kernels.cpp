// Spectral-element kernels of degree p against an element matrix built here by brute force
// (basis derivatives by the product rule, J and its inverse by cofactors, the Voigt B and C
// matrices, K = sum_q B^T C B w_q |det J_q| over the tensor GLL rule the elements use), and
// against the properties that hold exactly: rigid-body modes in the null space, symmetry,
// the patch test, the mass of the whole element, a partition of unity.
#include "slipwave/fem/spectral_kernels.hpp"

#include "slipwave/numerics/gll_basis.hpp"
#include "unit_check.hpp"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <string>
#include <vector>

using namespace slipwave::fem;
using namespace slipwave::numerics;

namespace {

const LameParameters kLame{2.0e9, 1.1e9};

// Node coordinates of the degree-p element on the Q1 map of `corners` (Quad4 / Hex8
// reference order of element_kernels.hpp), plus `curve` times a smooth bump so that the
// map is genuinely of degree p (the kernels take any node positions).
std::vector<double> elementNodes(int dim, int p, const double *corners, double curve) {
  double x[9], w[9];
  gllPointsWeights(p, x, w);
  const int           n1 = p + 1, nz = dim == 3 ? n1 : 1, nq = spectralNodeCount(dim, p);
  std::vector<double> c(nq * dim);
  // Q1 corner (a, b, g) in {0,1}^3 -> Quad4 / Hex8 node.
  const int corner_of[2][2][2] = {{{0, 4}, {3, 7}}, {{1, 5}, {2, 6}}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < n1; ++j)
      for (int i = 0; i < n1; ++i) {
        const double s[3] = {x[i], x[j], dim == 3 ? x[k] : -1.0};
        double      *X    = &c[(i + n1 * (j + n1 * k)) * dim];
        for (int d = 0; d < dim; ++d) X[d] = 0;
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b)
            for (int g = 0; g < (dim == 3 ? 2 : 1); ++g) {
              const double N = (a ? 1 + s[0] : 1 - s[0]) * (b ? 1 + s[1] : 1 - s[1]) * (dim == 3 ? (g ? 1 + s[2] : 1 - s[2]) / 8 : 0.25);
              for (int d = 0; d < dim; ++d) X[d] += N * corners[corner_of[a][b][g] * dim + d];
            }
        const double bump = (1 - s[0] * s[0]) * (1 - s[1] * s[1]) * (dim == 3 ? 1 - s[2] * s[2] : 1.0);
        X[0] += curve * bump;
        X[1] += 0.5 * curve * bump * s[0];
      }
  return c;
}

const double kQuad[] = {0.0, 0.0, 2.1, 0.3, 2.4, 1.9, -0.2, 1.5};
// The box meshes' elements: a square and a cube (side 5).
const double kSquare[] = {0.0, 0.0, 5.0, 0.0, 5.0, 5.0, 0.0, 5.0};
const double kCube[]   = {0, 0, 0, 5, 0, 0, 5, 5, 0, 0, 5, 0, 0, 0, 5, 5, 0, 5, 5, 5, 5, 0, 5, 5};
const double kHex[]  = {0.0, 0.0, 0.0, 1.8, 0.2, 0.1, 2.0, 1.7, -0.1, 0.1, 1.5, 0.2, 0.2, -0.1, 1.6, 2.1, 0.3, 1.9, 1.9, 1.8, 1.4, -0.1, 1.4, 1.8};

// dl[j] = l_j'(t) by the product rule.
void derivative1D(int p, const double *x, double t, double *dl) {
  for (int j = 0; j <= p; ++j) {
    dl[j] = 0;
    for (int m = 0; m <= p; ++m) {
      if (m == j) continue;
      double v = 1 / (x[j] - x[m]);
      for (int k = 0; k <= p; ++k)
        if (k != j && k != m) v *= (t - x[k]) / (x[j] - x[k]);
      dl[j] += v;
    }
  }
}

// The element matrix by the textbook route (Hughes, The Finite Element Method, 2.8 and 3.10).
std::vector<double> bruteForceStiffness(int dim, int p, const double *coords) {
  double x[9], w[9];
  gllPointsWeights(p, x, w);
  const int           n1 = p + 1, nq = spectralNodeCount(dim, p), n = dim * nq, nz = dim == 3 ? n1 : 1, nv = dim == 3 ? 6 : 3;
  std::vector<double> K(n * n, 0.0), B(nv * n), dN(nq * dim);
  // Voigt C: 2D plane strain (xx, yy, xy), 3D (xx, yy, zz, yz, xz, xy), engineering shear.
  double C[6][6] = {{0}};
  for (int a = 0; a < dim; ++a) {
    for (int b = 0; b < dim; ++b) C[a][b] = kLame.lambda;
    C[a][a] += 2 * kLame.mu;
  }
  for (int a = dim; a < nv; ++a) C[a][a] = kLame.mu;
  for (int qk = 0; qk < nz; ++qk)
    for (int qj = 0; qj < n1; ++qj)
      for (int qi = 0; qi < n1; ++qi) {
        const double t[3] = {x[qi], x[qj], dim == 3 ? x[qk] : 0.0};
        double       l[3][9], dl[3][9];
        for (int d = 0; d < dim; ++d) {
          lagrangeValues(p, x, t[d], l[d]);
          derivative1D(p, x, t[d], dl[d]);
        }
        double J[3][3] = {{0}};
        for (int k = 0; k < nz; ++k)
          for (int j = 0; j < n1; ++j)
            for (int i = 0; i < n1; ++i) {
              const int a = i + n1 * (j + n1 * k), id[3] = {i, j, k};
              for (int d = 0; d < dim; ++d) {
                double v = 1;
                for (int s = 0; s < dim; ++s) v *= s == d ? dl[s][id[s]] : l[s][id[s]];
                dN[a * dim + d] = v;
                for (int r = 0; r < dim; ++r) J[r][d] += coords[a * dim + r] * v;
              }
            }
        if (dim == 2) J[2][2] = 1;
        const double det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                           J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
        double Ji[3][3]; // inverse by cofactors: Ji[d][r] = d xi_d / d x_r
        for (int r = 0; r < 3; ++r)
          for (int d = 0; d < 3; ++d)
            Ji[d][r] = (J[(r + 1) % 3][(d + 1) % 3] * J[(r + 2) % 3][(d + 2) % 3] - J[(r + 1) % 3][(d + 2) % 3] * J[(r + 2) % 3][(d + 1) % 3]) / det;
        std::fill(B.begin(), B.end(), 0.0);
        for (int a = 0; a < nq; ++a) {
          double g[3] = {0, 0, 0}; // dN_a / dx_r
          for (int r = 0; r < dim; ++r)
            for (int d = 0; d < dim; ++d) g[r] += dN[a * dim + d] * Ji[d][r];
          for (int r = 0; r < dim; ++r) B[r * n + a * dim + r] = g[r];
          if (dim == 2) {
            B[2 * n + a * 2 + 0] = g[1], B[2 * n + a * 2 + 1] = g[0];
          } else {
            B[3 * n + a * 3 + 1] = g[2], B[3 * n + a * 3 + 2] = g[1];
            B[4 * n + a * 3 + 0] = g[2], B[4 * n + a * 3 + 2] = g[0];
            B[5 * n + a * 3 + 0] = g[1], B[5 * n + a * 3 + 1] = g[0];
          }
        }
        const double wq = w[qi] * w[qj] * (dim == 3 ? w[qk] : 1.0) * std::fabs(det);
        for (int r = 0; r < n; ++r)
          for (int v = 0; v < nv; ++v) {
            double cb = 0; // (C B)_{v, r} contracted below with B_{u, c}
            for (int u = 0; u < nv; ++u) cb += C[v][u] * B[u * n + r];
            if (cb == 0) continue;
            for (int c = 0; c < n; ++c) K[r * n + c] += wq * B[v * n + c] * cb;
          }
      }
  return K;
}

double maxAbs(const std::vector<double> &v) {
  double m = 0;
  for (double a : v) m = std::max(m, std::fabs(a));
  return m;
}

} // namespace

int main() {
  for (int dim = 2; dim <= 3; ++dim)
    for (int p = 1; p <= 6; ++p) {
      const std::string   tag = std::to_string(dim) + "D p=" + std::to_string(p) + " ";
      const int           nq = spectralNodeCount(dim, p), n = dim * nq;
      const auto          coords = elementNodes(dim, p, dim == 2 ? kQuad : kHex, p > 1 ? 0.08 : 0.0);
      std::vector<double> wdet(nq), jinv(nq * dim * dim), K(n * n), ue(n), fe(n), ref(n);
      unit::check(spectralGeometry(dim, p, coords.data(), wdet.data(), jinv.data()), tag + "distorted element accepted");
      const auto Kbf = bruteForceStiffness(dim, p, coords.data());
      spectralElementStiffness(dim, p, wdet.data(), jinv.data(), kLame, K.data());
      // A deterministic, non-smooth displacement so every mode takes part.
      for (int r = 0; r < n; ++r) ue[r] = std::sin(1.7 * r + 0.3) + 0.1 * (r % 5);
      spectralElementForce(dim, p, wdet.data(), jinv.data(), kLame, ue.data(), fe.data());
      for (int r = 0; r < n; ++r) {
        ref[r] = 0;
        for (int c = 0; c < n; ++c) ref[r] += Kbf[r * n + c] * ue[c];
      }
      double ferr = 0, kerr = 0, asym = 0;
      for (int r = 0; r < n; ++r) ferr = std::max(ferr, std::fabs(fe[r] - ref[r]));
      for (int r = 0; r < n * n; ++r) kerr = std::max(kerr, std::fabs(K[r] - Kbf[r]));
      for (int r = 0; r < n; ++r)
        for (int c = 0; c < r; ++c) asym = std::max(asym, std::fabs(K[r * n + c] - K[c * n + r]));
      // Brute force and sum factorisation are the same sum in another order: round-off only.
      unit::near(ferr / maxAbs(ref), 0, 0, 1e-12, tag + "sum-factorised K u = brute-force K u (max error / max |K u|)");
      unit::near(kerr / maxAbs(Kbf), 0, 0, 1e-12, tag + "element matrix = brute-force matrix (max error / max |K|)");
      unit::near(asym / maxAbs(K), 0, 0, 1e-13, tag + "element matrix symmetric");

      // Rigid-body modes (translations, infinitesimal rotations) carry no strain: K r = 0.
      const int nrigid = dim == 2 ? 3 : 6;
      double    worst  = 0;
      for (int mode = 0; mode < nrigid; ++mode) {
        for (int a = 0; a < nq; ++a) {
          const double *X = &coords[a * dim];
          double        r[3] = {0, 0, 0};
          if (mode < dim) r[mode] = 1;
          else if (dim == 2) r[0] = -X[1], r[1] = X[0];
          else {
            const int i = (mode - 3 + 1) % 3, j = (mode - 3 + 2) % 3; // rotation about axis mode-3
            r[i] = -X[j], r[j] = X[i];
          }
          for (int d = 0; d < dim; ++d) ue[a * dim + d] = r[d];
        }
        spectralElementForce(dim, p, wdet.data(), jinv.data(), kLame, ue.data(), fe.data());
        worst = std::max(worst, maxAbs(fe) / (maxAbs(K) * maxAbs(ue)));
      }
      unit::near(worst, 0, 0, 1e-12, tag + "rigid-body modes give zero force (max |K r| / (max |K| max |r|))");

      // Patch test: u = A x + b is in the isoparametric space, so its strain, hence the stress
      // sigma = lambda tr(eps) I + 2 mu eps, is reproduced exactly at every point.
      const double A[3][3] = {{1e-3, 2e-4, -3e-4}, {-5e-4, 7e-4, 1e-4}, {3e-4, -2e-4, -6e-4}};
      for (int a = 0; a < nq; ++a)
        for (int i = 0; i < dim; ++i) {
          ue[a * dim + i] = 0.01 * (i + 1);
          for (int j = 0; j < dim; ++j) ue[a * dim + i] += A[i][j] * coords[a * dim + j];
        }
      double eps[3][3], want[6];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) eps[i][j] = i < dim && j < dim ? 0.5 * (A[i][j] + A[j][i]) : 0.0;
      const double tr = eps[0][0] + eps[1][1] + eps[2][2];
      for (int i = 0; i < 3; ++i) want[i] = kLame.lambda * tr + 2 * kLame.mu * eps[i][i];
      want[3] = 2 * kLame.mu * eps[0][1], want[4] = 2 * kLame.mu * eps[1][2], want[5] = 2 * kLame.mu * eps[0][2];
      double perr = 0;
      const double points[3][3] = {{0.3, -0.7, 0.1}, {-1, 1, -1}, {0.91, 0.05, -0.44}};
      for (const auto &xi : points) {
        double sigma[6];
        unit::check(spectralStress(dim, p, coords.data(), kLame, ue.data(), xi, sigma), tag + "stress map regular");
        for (int k = 0; k < 6; ++k) perr = std::max(perr, std::fabs(sigma[k] - want[k]));
      }
      unit::near(perr / std::fabs(kLame.lambda * tr + 2 * kLame.mu * 1e-3), 0, 0, 1e-12, tag + "patch test: linear field gives its constant stress");

      // Eigenvalue bounds of one element, against lambda_max(M_e^{-1} K_e) from below (the
      // Rayleigh quotient of power steps: a bound under it would be wrong).
      if (dim == 2 || p <= 4) {
        const double rho = 2100;
        std::vector<double> v(n, 1.0), y(n);
        double              rq = 0;
        for (int it = 0; it < 3000; ++it) {
          double vKv = 0, vMv = 0, norm = 0;
          for (int r = 0; r < n; ++r) {
            y[r] = 0;
            for (int c = 0; c < n; ++c) y[r] += K[r * n + c] * v[c];
            vKv += v[r] * y[r], vMv += v[r] * rho * wdet[r / dim] * v[r];
          }
          rq = vKv / vMv;
          for (int r = 0; r < n; ++r) v[r] = y[r] / (rho * wdet[r / dim]), norm = std::max(norm, std::fabs(v[r]));
          for (int r = 0; r < n; ++r) v[r] /= norm;
        }
        const double gersh = spectralElementEigenBound(dim, p, wdet.data(), jinv.data(), kLame, rho, EigenBoundKind::Gershgorin);
        const double cw    = spectralElementEigenBound(dim, p, wdet.data(), jinv.data(), kLame, rho, EigenBoundKind::CollatzWielandt);
        const double cert  = spectralElementEigenBound(dim, p, wdet.data(), jinv.data(), kLame, rho, EigenBoundKind::Certified);
        unit::check(rq <= cert && cert <= cw && cw <= gersh, tag + "element bounds ordered: lambda <= certified <= Collatz-Wielandt <= Gershgorin");
        std::printf("# %selement bound / lambda_max: Gershgorin %.3f Collatz-Wielandt %.3f certified %.4f\n", tag.c_str(), gersh / rq, cw / rq, cert / rq);
        // A square (cube) element with its nodes in another order (the reference frame turned
        // by 90 degrees about its third axis: node (i0, i1, i2) is the old (i1, p - i0, i2)),
        // as another rank may lay the cell out: the same bound to round-off, so the step does
        // not depend on the partition. (A power iteration from a fixed start missed the
        // nearly equal top eigenvalues of a square by 0.2 % at p = 3, by an amount that
        // depended on the node order.)
        const auto          square = elementNodes(dim, p, dim == 2 ? kSquare : kCube, 0.0);
        std::vector<double> turned(square.size()), wdet_s(nq), jinv_s(nq * dim * dim), wdet_t(nq), jinv_t(nq * dim * dim);
        const int           n1 = p + 1;
        for (int a = 0; a < nq; ++a) {
          const int i0 = a % n1, i1 = (a / n1) % n1, i2 = a / (n1 * n1), old = i1 + n1 * ((p - i0) + n1 * i2);
          for (int d = 0; d < dim; ++d) turned[a * dim + d] = square[old * dim + d];
        }
        unit::check(spectralGeometry(dim, p, square.data(), wdet_s.data(), jinv_s.data()) && spectralGeometry(dim, p, turned.data(), wdet_t.data(), jinv_t.data()),
                    tag + "square and turned square accepted");
        const double cert_s = spectralElementEigenBound(dim, p, wdet_s.data(), jinv_s.data(), kLame, rho, EigenBoundKind::Certified);
        const double cert_t = spectralElementEigenBound(dim, p, wdet_t.data(), jinv_t.data(), kLame, rho, EigenBoundKind::Certified);
        unit::near(cert_t / cert_s, 1, 0, 1e-12, tag + "certified bound of a square independent of its node order");
      }

      // Partition of unity and interpolation (N_a(x_b) = delta_ab) of the tensor basis.
      std::vector<double> N(nq);
      const double        xi[3] = {0.37, -0.81, 0.6};
      spectralBasisValues(dim, p, xi, N.data());
      double sum = 0;
      for (double v : N) sum += v;
      unit::near(sum, 1, 0, 1e-13, tag + "basis sums to one");
    }

  // Mass: sum_q w_q |det J_q| = the element's volume. Quad on its Q1 map: the polygon area
  // (shoelace, 2 x area = sum of x_i y_{i+1} - x_{i+1} y_i); det J is bilinear, integrated
  // exactly by GLL at every p >= 1.
  double shoelace = 0;
  for (int i = 0; i < 4; ++i) shoelace += kQuad[2 * i] * kQuad[2 * ((i + 1) % 4) + 1] - kQuad[2 * ((i + 1) % 4)] * kQuad[2 * i + 1];
  const double area = 0.5 * std::fabs(shoelace), rho = 2100;
  // Hex on its Q1 map: det J has degree 2 per direction, integrated exactly by the 2-point
  // Gauss rule (degree 3), taken here from the p = 1 brute-force route with Gauss points.
  double volume = 0;
  {
    const auto   nodes = elementNodes(3, 1, kHex, 0.0);
    const double g     = 1 / std::sqrt(3.0), gx[2] = {-g, g}, xl[2] = {-1, 1};
    for (double a : gx)
      for (double b : gx)
        for (double c : gx) {
          double J[3][3] = {{0}}, l[3][2], dl[3][2];
          const double t[3] = {a, b, c};
          for (int d = 0; d < 3; ++d) {
            lagrangeValues(1, xl, t[d], l[d]);
            derivative1D(1, xl, t[d], dl[d]);
          }
          for (int n = 0; n < 8; ++n) {
            const int id[3] = {n & 1, (n >> 1) & 1, n >> 2};
            for (int d = 0; d < 3; ++d) {
              double v = 1;
              for (int s = 0; s < 3; ++s) v *= s == d ? dl[s][id[s]] : l[s][id[s]];
              for (int r = 0; r < 3; ++r) J[r][d] += nodes[n * 3 + r] * v;
            }
          }
          volume += std::fabs(J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                              J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]));
        }
  }
  for (int dim = 2; dim <= 3; ++dim)
    for (int p = dim == 2 ? 1 : 2; p <= kMaxSpectralDegree; ++p) {
      const int           nq = spectralNodeCount(dim, p);
      const auto          coords = elementNodes(dim, p, dim == 2 ? kQuad : kHex, 0.0);
      std::vector<double> wdet(nq), jinv(nq * dim * dim), mass(nq);
      spectralGeometry(dim, p, coords.data(), wdet.data(), jinv.data());
      spectralLumpedMass(dim, p, wdet.data(), rho, mass.data());
      double total = 0;
      bool   positive = true;
      for (double m : mass) total += m, positive = positive && m > 0;
      const std::string tag = std::to_string(dim) + "D p=" + std::to_string(p) + " ";
      unit::near(total, rho * (dim == 2 ? area : volume), 1e-13, 0, tag + "lumped mass sums to rho x volume");
      unit::check(positive, tag + "every lumped mass positive");
    }

  // A folded quad (two corners swapped: the bow-tie) is reported, not used.
  const double bowtie[] = {0, 0, 1, 0, 0, 1, 1, 1};
  for (int p = 1; p <= 4; p += 3) {
    const auto          coords = elementNodes(2, p, bowtie, 0.0);
    std::vector<double> wdet(spectralNodeCount(2, p)), jinv(4 * spectralNodeCount(2, p));
    unit::check(!spectralGeometry(2, p, coords.data(), wdet.data(), jinv.data()), "p=" + std::to_string(p) + " folded quad reported");
  }
  return unit::failures();
}

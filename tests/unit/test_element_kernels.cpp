// Element kernels: rigid modes, rank, patch tests, exact energies, volumes, masses,
// inverse map, faces and node-order invariance, on distorted cells of every shape.
#include "slipwave/fem/element_kernels.hpp"

#include "unit_check.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace slipwave::fem;
using namespace slipwave::numerics;

namespace {

struct Cell {
  CellShape shape;
  const char *name;
  std::vector<double> coords;
};

const LameParameters kLame{2.0e9, 1.3e9};

std::vector<Cell> distortedCells() {
  return {
      {CellShape::Tri3, "Tri3", {0.1, 0.2, 1.3, 0.1, 0.4, 1.1}},
      {CellShape::Quad4, "Quad4", {0.0, 0.0, 2.0, 0.2, 1.8, 1.5, 0.3, 1.2}},
      {CellShape::Tet4, "Tet4", {0.0, 0.0, 0.0, 1.2, 0.1, 0.2, 0.3, 1.1, -0.1, 0.2, 0.3, 0.9}},
      {CellShape::Hex8,
       "Hex8",
       {0.0, 0.0, 0.0, 2.1, 0.1, -0.1, 2.0, 1.6, 0.2, -0.2, 1.4, 0.0,  //
        0.1, -0.1, 1.2, 1.9, 0.0, 1.0, 2.2, 1.5, 1.3, 0.0, 1.7, 1.1}},
  };
}

int dofs(CellShape s) { return cellNodeCount(s) * cellDimension(s); }

std::vector<double> stiffness(CellShape s, const std::vector<double> &x, const LameParameters &m = kLame, Dilatation d = Dilatation::Gauss) {
  std::vector<double> K(dofs(s) * dofs(s));
  elementStiffness(s, x.data(), m, K.data(), d);
  return K;
}

std::vector<double> multiply(const std::vector<double> &K, const std::vector<double> &u) {
  const size_t n = u.size();
  std::vector<double> f(n, 0.0);
  for (size_t r = 0; r < n; ++r)
    for (size_t c = 0; c < n; ++c) f[r] += K[r * n + c] * u[c];
  return f;
}

double maxAbs(const std::vector<double> &v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

// u(x) = A x + b at the nodes; A is dim x dim row-major.
std::vector<double> linearField(const std::vector<double> &x, int dim, const double *A, const double *b) {
  std::vector<double> u(x.size());
  for (size_t a = 0; a < x.size() / dim; ++a)
    for (int i = 0; i < dim; ++i) {
      u[a * dim + i] = b[i];
      for (int j = 0; j < dim; ++j) u[a * dim + i] += A[i * dim + j] * x[a * dim + j];
    }
  return u;
}

// Eigenvalues of a symmetric matrix by cyclic Jacobi rotations (Golub & Van Loan §8.5).
std::vector<double> symmetricEigenvalues(std::vector<double> A, int n) {
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) off += A[p * n + q] * A[p * n + q];
    if (off < 1e-30 * maxAbs(A) * maxAbs(A)) break;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) {
        if (A[p * n + q] == 0) continue;
        const double theta = (A[q * n + q] - A[p * n + p]) / (2 * A[p * n + q]);
        const double t = (theta >= 0 ? 1 : -1) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < n; ++k) {  // A <- A G
          const double akp = A[k * n + p], akq = A[k * n + q];
          A[k * n + p] = c * akp - s * akq;
          A[k * n + q] = s * akp + c * akq;
        }
        for (int k = 0; k < n; ++k) {  // A <- G^T A
          const double apk = A[p * n + k], aqk = A[q * n + k];
          A[p * n + k] = c * apk - s * aqk;
          A[q * n + k] = s * apk + c * aqk;
        }
      }
  }
  std::vector<double> ev(n);
  for (int i = 0; i < n; ++i) ev[i] = A[i * n + i];
  return ev;
}

void testRigidModesAndRank(const Cell &c) {
  const int dim = cellDimension(c.shape), nd = dofs(c.shape);
  const std::vector<double> K = stiffness(c.shape, c.coords);
  const double kmax = maxAbs(K);
  // Rigid modes: translations e_i and infinitesimal rotations u = W x with W skew.
  std::vector<std::vector<double>> modes;
  for (int i = 0; i < dim; ++i) {
    double A[9] = {}, b[3] = {};
    b[i] = 1;
    modes.push_back(linearField(c.coords, dim, A, b));
  }
  const int rotations = dim == 2 ? 1 : 3;
  for (int r = 0; r < rotations; ++r) {
    double A[9] = {}, b[3] = {};
    const int p = dim == 2 ? 0 : r, q = dim == 2 ? 1 : (r + 1) % 3;
    A[p * dim + q] = -1, A[q * dim + p] = 1;
    modes.push_back(linearField(c.coords, dim, A, b));
  }
  for (size_t k = 0; k < modes.size(); ++k)
    unit::near(maxAbs(multiply(K, modes[k])) / (kmax * maxAbs(modes[k])), 0, 0, 1e-14,
               std::string(c.name) + ": rigid mode " + std::to_string(k) + " gives zero force (round-off)");

  // Symmetric and positive semi-definite with exactly the rigid modes in the kernel
  // (3 in 2D, 6 in 3D): full integration has no hourglass modes.
  double asym = 0;
  for (int r = 0; r < nd; ++r)
    for (int s = 0; s < nd; ++s) asym = std::max(asym, std::fabs(K[r * nd + s] - K[s * nd + r]));
  unit::near(asym / kmax, 0, 0, 1e-15, std::string(c.name) + ": K symmetric");
  const std::vector<double> ev = symmetricEigenvalues(K, nd);
  const double evmax = *std::max_element(ev.begin(), ev.end());
  int zeros = 0;
  double most_negative = 0;
  for (double e : ev) {
    if (std::fabs(e) < 1e-10 * evmax) ++zeros;
    most_negative = std::min(most_negative, e);
  }
  unit::check(zeros == (dim == 2 ? 3 : 6),
              std::string(c.name) + ": zero eigenvalues = rigid modes (got " + std::to_string(zeros) + ")");
  unit::near(most_negative / evmax, 0, 0, 1e-12, std::string(c.name) + ": K positive semi-definite");

  // Gershgorin: every row sum of |K| bounds its diagonal and the largest eigenvalue.
  std::vector<double> rowabs(nd);
  elementStiffnessRowAbsSum(c.shape, c.coords.data(), kLame, rowabs.data());
  bool dominates = true;
  for (int r = 0; r < nd; ++r) dominates = dominates && rowabs[r] >= std::fabs(K[r * nd + r]);
  unit::check(dominates, std::string(c.name) + ": Gershgorin row sums >= |diagonal|");
  unit::check(*std::max_element(rowabs.begin(), rowabs.end()) >= evmax,
              std::string(c.name) + ": max Gershgorin row sum >= largest eigenvalue");
  double r0 = 0;
  for (int col = 0; col < nd; ++col) r0 += std::fabs(K[col]);
  unit::near(rowabs[0], r0, 1e-15, 0, std::string(c.name) + ": row-abs sum of row 0 by definition");
}

// Constant strain u = A x + b: centroid stress is Hooke's law exactly, and
// 1/2 u^T K u = 1/2 (lambda tr(eps)^2 + 2 mu eps:eps) V (the strain energy density of a
// constant field times the volume; the antisymmetric part of A is a rotation, energy-free).
void testConstantStrain(const Cell &c) {
  const int dim = cellDimension(c.shape), nd = dofs(c.shape);
  const double A3[9] = {1.0e-3, 4.0e-4, -2.0e-4, -1.0e-4, -7.0e-4, 3.0e-4, 5.0e-4, 2.0e-4, 6.0e-4};
  const double b[3] = {0.3, -0.1, 0.2};
  double A[9] = {};
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) A[i * dim + j] = A3[i * 3 + j];
  const std::vector<double> u = linearField(c.coords, dim, A, b);
  double eps[3][3] = {};
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) eps[i][j] = 0.5 * (A[i * dim + j] + A[j * dim + i]);
  const double tr = eps[0][0] + eps[1][1] + eps[2][2];
  double hooke[3][3], eps_eps = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      hooke[i][j] = (i == j ? kLame.lambda * tr : 0.0) + 2 * kLame.mu * eps[i][j];
      eps_eps += eps[i][j] * eps[i][j];
    }
  std::vector<double> S(kStressComponents * nd);
  elementStressOperator(c.shape, c.coords.data(), kLame, S.data());
  const int ri[6] = {0, 1, 2, 0, 1, 0}, rj[6] = {0, 1, 2, 1, 2, 2};
  const double scale = 2 * kLame.mu * 1e-3;
  for (int row = 0; row < kStressComponents; ++row) {
    double sigma = 0;
    for (int k = 0; k < nd; ++k) sigma += S[row * nd + k] * u[k];
    // Plane strain: hooke[2][2] = lambda (exx + eyy) since ezz = 0; yz = xz = 0.
    unit::near(sigma, hooke[ri[row]][rj[row]], 1e-12, 1e-12 * scale,
               std::string(c.name) + ": patch-test stress row " + std::to_string(row) + " = Hooke");
  }
  // The energy uses the field without the translation b: u^T K u with a translation
  // cancels to round-off relative to |b|^2 |K| (the translation is checked on its own in
  // testRigidModesAndRank), which would hide the quantity under test.
  const double no_translation[3] = {0, 0, 0};
  const std::vector<double> us = linearField(c.coords, dim, A, no_translation);
  const std::vector<double> f = multiply(stiffness(c.shape, c.coords), us);
  double energy = 0;
  for (int k = 0; k < nd; ++k) energy += 0.5 * us[k] * f[k];
  const double V = cellVolume(c.shape, c.coords.data());
  unit::near(energy, 0.5 * (kLame.lambda * tr * tr + 2 * kLame.mu * eps_eps) * V, 1e-12, 0,
             std::string(c.name) + ": 1/2 u^T K u = 1/2 eps:C:eps V for constant strain");
}

double quadratic(const std::vector<double> &K, const std::vector<double> &u) {
  const std::vector<double> f = multiply(K, u);
  double e = 0;
  for (size_t k = 0; k < u.size(); ++k) e += u[k] * f[k];
  return e;
}

// The mean-dilatation (B-bar) element, Dilatation::Mean (Hughes 1980): the volumetric energy
// kappa V (mean div u)^2 in place of kappa int (div u)^2, the deviatoric part as before.
void testMeanDilatation(const Cell &c) {
  const int dim = cellDimension(c.shape), nd = dofs(c.shape);
  const std::string name = std::string(c.name) + " mean dilatation: ";
  const std::vector<double> Kg = stiffness(c.shape, c.coords), Km = stiffness(c.shape, c.coords, kLame, Dilatation::Mean);
  const double kmax = maxAbs(Kg);
  // A uniform strain has the same div u at every point: the same forces and stress.
  const double A3[9] = {1.0e-3, 4.0e-4, -2.0e-4, -1.0e-4, -7.0e-4, 3.0e-4, 5.0e-4, 2.0e-4, 6.0e-4}, b[3] = {0.3, -0.1, 0.2};
  double A[9] = {};
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) A[i * dim + j] = A3[i * 3 + j];
  const std::vector<double> u = linearField(c.coords, dim, A, b), fg = multiply(Kg, u), fm = multiply(Km, u);
  double diff = 0;
  for (int k = 0; k < nd; ++k) diff = std::max(diff, std::fabs(fg[k] - fm[k]));
  unit::near(diff / maxAbs(fg), 0, 0, 1e-12, name + "uniform strain: the Gauss element's forces");
  std::vector<double> Sg(kStressComponents * nd), Sm(kStressComponents * nd);
  elementStressOperator(c.shape, c.coords.data(), kLame, Sg.data());
  elementStressOperator(c.shape, c.coords.data(), kLame, Sm.data(), Dilatation::Mean);
  for (int row = 0; row < kStressComponents; ++row) {
    double sg = 0, sm = 0;
    for (int k = 0; k < nd; ++k) sg += Sg[row * nd + k] * u[k], sm += Sm[row * nd + k] * u[k];
    unit::near(sm, sg, 0, 1e-12 * 2 * kLame.mu * 1e-3, name + "uniform strain: stress row " + std::to_string(row) + " as the Gauss element's");
  }
  // Symmetric, positive semi-definite, and below the Gauss element: Kg - Km = kappa (int div div -
  // V mean div mean div) >= 0 by Jensen's inequality; the rigid modes stay its only kernel
  // (the deviatoric part alone holds every non-rigid mode of these cells).
  double asym = 0;
  for (int r = 0; r < nd; ++r)
    for (int q = 0; q < nd; ++q) asym = std::max(asym, std::fabs(Km[r * nd + q] - Km[q * nd + r]));
  unit::near(asym / kmax, 0, 0, 1e-15, name + "symmetric");
  std::vector<double> gap(nd * nd);
  for (int k = 0; k < nd * nd; ++k) gap[k] = Kg[k] - Km[k];
  const std::vector<double> ev_gap = symmetricEigenvalues(gap, nd), ev = symmetricEigenvalues(Km, nd);
  unit::near(std::min(0.0, *std::min_element(ev_gap.begin(), ev_gap.end())) / kmax, 0, 0, 1e-12, name + "K_gauss - K_mean positive semi-definite");
  const double evmax = *std::max_element(ev.begin(), ev.end());
  int zeros = 0;
  for (double e : ev) zeros += std::fabs(e) < 1e-10 * evmax;
  unit::check(zeros == (dim == 2 ? 3 : 6), name + "zero eigenvalues = rigid modes (got " + std::to_string(zeros) + ")");
  // lambda enters only through kappa V (mean div u)^2: raising lambda by d raises u^T K u by
  // d V (mean div u)^2 (d int div^2 with Gauss points). In 2D the mean comes independently from
  // the boundary, V mean div u = sum over edges of the edge's mean u . (dy, -dx) (u is linear
  // along a straight edge; nodes counterclockwise).
  std::vector<double> w(nd);
  unsigned seed = 12345;
  for (double &x : w) x = ((seed = seed * 1103515245u + 12345u) >> 8) / double(1u << 24) - 0.5;
  const double d = 1e3 * kLame.lambda;
  const LameParameters stiffer{kLame.lambda + d, kLame.mu};
  const double rise_m = quadratic(stiffness(c.shape, c.coords, stiffer, Dilatation::Mean), w) - quadratic(Km, w);
  if (dim == 2) {
    const int n = cellNodeCount(c.shape);
    double flux = 0;
    for (int a = 0; a < n; ++a) {
      const int e = (a + 1) % n;
      const double dx = c.coords[2 * e] - c.coords[2 * a], dy = c.coords[2 * e + 1] - c.coords[2 * a + 1];
      flux += 0.5 * ((w[2 * a] + w[2 * e]) * dy - (w[2 * a + 1] + w[2 * e + 1]) * dx);
    }
    const double V = cellVolume(c.shape, c.coords.data());
    unit::near(rise_m, d * flux * flux / V, 1e-9, 0, name + "d(u^T K u)/d lambda = V (mean div u)^2, the mean from the boundary flux");
  }
  if (c.shape == CellShape::Tri3 || c.shape == CellShape::Tet4) {
    unit::near(maxAbs(gap) / kmax, 0, 0, 1e-14, name + "one Gauss point: the same element");
    return;
  }
  // The locking the mean removes: the random mode less its mean dilatation (G = dK_mean/dlambda =
  // V dbar dbar^T, so w - (w.Gw / |Gw|^2) Gw has dbar.w = 0) still has div u varying inside
  // the cell; its lambda energy is d int (div u)^2 > 0 with Gauss points (a nearly
  // incompressible solid cannot take it: the element locks) and zero with the mean.
  std::vector<double> G(nd * nd);
  const std::vector<double> Km_stiffer = stiffness(c.shape, c.coords, stiffer, Dilatation::Mean);
  for (int k = 0; k < nd * nd; ++k) G[k] = (Km_stiffer[k] - Km[k]) / d;
  const std::vector<double> Gw = multiply(G, w);
  double wGw = 0, GwGw = 0;
  for (int k = 0; k < nd; ++k) wGw += w[k] * Gw[k], GwGw += Gw[k] * Gw[k];
  std::vector<double> v(nd);
  for (int k = 0; k < nd; ++k) v[k] = w[k] - wGw / GwGw * Gw[k];
  const double vm = quadratic(Km_stiffer, v) - quadratic(Km, v), vg = quadratic(stiffness(c.shape, c.coords, stiffer), v) - quadratic(Kg, v);
  unit::near(vm / vg, 0, 0, 1e-9, name + "no lambda energy in a mode of zero mean dilatation (Gauss points: " + std::to_string(vg / quadratic(Kg, v)) + " x its energy at lambda)");
  unit::check(vg > 0.1 * quadratic(Kg, v), name + "the Gauss element's lambda energy in that mode is not small (it locks)");
}

void testMassSumsToRhoVolume(const Cell &c) {
  const double rho = 1850.0;
  std::vector<double> m(cellNodeCount(c.shape));
  elementLumpedMass(c.shape, c.coords.data(), rho, m.data());
  double sum = 0;
  for (double v : m) sum += v;
  unit::near(sum, rho * cellVolume(c.shape, c.coords.data()), 1e-14, 0,
             std::string(c.name) + ": lumped mass sums to rho V");
}

void testReferenceCoordinates(const Cell &c) {
  const int n = cellNodeCount(c.shape), dim = cellDimension(c.shape);
  const bool simplex = c.shape == CellShape::Tri3 || c.shape == CellShape::Tet4;
  unsigned seed = 12345;
  auto uniform = [&seed]() {  // LCG: deterministic and portable
    seed = seed * 1103515245u + 12345u;
    return ((seed >> 8) & 0xffff) / 65536.0;
  };
  double worst = 0;
  bool all_found = true;
  for (int trial = 0; trial < 50; ++trial) {
    double xi[3] = {}, N[8], x[3] = {}, back[3];
    double sum = 0;
    for (int i = 0; i < dim; ++i) {
      xi[i] = simplex ? uniform() * (1 - sum) * 0.95 : 1.9 * uniform() - 0.95;
      sum += xi[i];
    }
    shapeFunctions(c.shape, xi, N);
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < dim; ++i) x[i] += N[a] * c.coords[a * dim + i];
    all_found = all_found && referenceCoordinates(c.shape, c.coords.data(), x, back);
    for (int i = 0; i < dim; ++i) worst = std::max(worst, std::fabs(back[i] - xi[i]));
  }
  unit::check(all_found, std::string(c.name) + ": interior points found inside");
  unit::near(worst, 0, 0, 1e-12, std::string(c.name) + ": referenceCoordinates inverts the map");
  // Reference point (1.3, 0.1, 0.1) is outside every reference cell (beyond xi = 1).
  const double outside_xi[3] = {1.3, 0.1, 0.1};
  double N[8], x[3] = {}, back[3];
  shapeFunctions(c.shape, outside_xi, N);
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < dim; ++i) x[i] += N[a] * c.coords[a * dim + i];
  unit::check(!referenceCoordinates(c.shape, c.coords.data(), x, back),
              std::string(c.name) + ": point outside reported outside");
}

void testVolumesOfKnownShapes() {
  // Right triangle legs 2 and 3: area 3.
  const double tri[] = {0, 0, 2, 0, 0, 3};
  unit::near(cellVolume(CellShape::Tri3, tri), 3.0, 1e-15, 0, "Tri3 area of right triangle = 3");
  // Trapezoid, parallel sides 4 and 2 at distance 1.5, clockwise: area (4+2)/2*1.5 = 4.5.
  const double quad[] = {0, 0, 1, 1.5, 3, 1.5, 4, 0};
  unit::near(cellVolume(CellShape::Quad4, quad), 4.5, 1e-15, 0, "Quad4 area of trapezoid = 4.5 (clockwise)");
  // Tet with edges 1, 2, 3 along the axes: 1*2*3/6 = 1.
  const double tet[] = {0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 3};
  unit::near(cellVolume(CellShape::Tet4, tet), 1.0, 1e-15, 0, "Tet4 volume 1*2*3/6 = 1");
  // Parallelepiped on edges (2,0,0), (0.5,1,0), (0.2,0.3,1.5): det = 2*1*1.5 = 3.
  const double e[3][3] = {{2, 0, 0}, {0.5, 1, 0}, {0.2, 0.3, 1.5}};
  std::vector<double> hex;
  const int corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int z = 0; z < 2; ++z)
    for (const auto &c : corner)
      for (int i = 0; i < 3; ++i) hex.push_back(c[0] * e[0][i] + c[1] * e[1][i] + z * e[2][i]);
  unit::near(cellVolume(CellShape::Hex8, hex.data()), 3.0, 1e-14, 0, "Hex8 parallelepiped volume = det = 3");
  // Trapezoidal prism: the trapezoid above extruded 2 in z: 4.5*2 = 9.
  std::vector<double> prism;
  for (int z = 0; z < 2; ++z)
    for (int a = 0; a < 4; ++a) prism.insert(prism.end(), {quad[2 * a], quad[2 * a + 1], 2.0 * z});
  unit::near(cellVolume(CellShape::Hex8, prism.data()), 9.0, 1e-14, 0, "Hex8 trapezoidal prism volume = 9");
  // Parallelogram: det J is constant, so each N_a integrates to V/4 by symmetry.
  const double para[] = {0, 0, 2, 0, 2.5, 1, 0.5, 1};
  double m[4];
  elementLumpedMass(CellShape::Quad4, para, 1.0, m);
  for (int a = 0; a < 4; ++a)
    unit::near(m[a], 0.5, 1e-15, 0, "Quad4 parallelogram lumped mass node " + std::to_string(a) + " = V/4");
  double mt[4];
  elementLumpedMass(CellShape::Tet4, tet, 2.0, mt);
  unit::near(mt[2], 0.5, 1e-15, 0, "Tet4 lumped mass = rho V/4");
  // Trapezoid: the same hand integrals as the Quad4 face weights in testFaces.
  elementLumpedMass(CellShape::Quad4, quad, 2.0, m);
  const double trapezoid_mass[4] = {2.5, 2.0, 2.0, 2.5};
  for (int a = 0; a < 4; ++a)
    unit::near(m[a], trapezoid_mass[a], 1e-14, 0, "Quad4 trapezoid lumped mass node " + std::to_string(a));
}

// Assembled internal force at the interior node of a patch under a linear displacement
// field is zero (the patch test): the element forces of the neighbours cancel there.
struct Patch {
  CellShape shape;
  const char *name;
  std::vector<double> x;                // nodes x dim
  std::vector<std::vector<int>> cells;  // connectivity
  int interior;
};

std::vector<double> gridNodes(int dim) {
  // 3^dim nodes on [0,2]^dim, each node shifted by a fixed pseudo-random offset so no
  // cell is affine.
  std::vector<double> x;
  const int n = dim == 2 ? 9 : 27;
  for (int k = 0; k < n; ++k) {
    const int ijk[3] = {k % 3, (k / 3) % 3, k / 9};
    for (int i = 0; i < dim; ++i) x.push_back(ijk[i] + 0.2 * std::sin(1.7 * k + 2.3 * i));
  }
  return x;
}

std::vector<Patch> patches() {
  std::vector<Patch> p;
  auto id2 = [](int i, int j) { return i + 3 * j; };
  auto id3 = [](int i, int j, int k) { return i + 3 * j + 9 * k; };
  Patch quad{CellShape::Quad4, "Quad4", gridNodes(2), {}, id2(1, 1)};
  Patch tri{CellShape::Tri3, "Tri3", gridNodes(2), {}, id2(1, 1)};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int c[4] = {id2(i, j), id2(i + 1, j), id2(i + 1, j + 1), id2(i, j + 1)};
      quad.cells.push_back({c[0], c[1], c[2], c[3]});
      tri.cells.push_back({c[0], c[1], c[2]});
      tri.cells.push_back({c[0], c[2], c[3]});
    }
  Patch hex{CellShape::Hex8, "Hex8", gridNodes(3), {}, id3(1, 1, 1)};
  Patch tet{CellShape::Tet4, "Tet4", gridNodes(3), {}, id3(1, 1, 1)};
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        hex.cells.push_back({id3(i, j, k), id3(i + 1, j, k), id3(i + 1, j + 1, k), id3(i, j + 1, k),
                             id3(i, j, k + 1), id3(i + 1, j, k + 1), id3(i + 1, j + 1, k + 1),
                             id3(i, j + 1, k + 1)});
        // Kuhn split into 6 tets along the (0,0,0)-(1,1,1) diagonal: conforming across cells.
        const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
        for (const auto &pm : perms) {
          int o[3] = {i, j, k};
          std::vector<int> t{id3(o[0], o[1], o[2])};
          for (int step = 0; step < 3; ++step) {
            ++o[pm[step]];
            t.push_back(id3(o[0], o[1], o[2]));
          }
          tet.cells.push_back(t);
        }
      }
  p.push_back(tri), p.push_back(quad), p.push_back(tet), p.push_back(hex);
  return p;
}

void testPatchInteriorForce(const Patch &p) {
  const int dim = cellDimension(p.shape), n = cellNodeCount(p.shape), nd = n * dim;
  const double A[9] = {1e-3, 4e-4, -2e-4, -1e-4, -7e-4, 3e-4, 5e-4, 2e-4, 6e-4};
  double Ad[9];
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) Ad[i * dim + j] = A[i * 3 + j];
  const double b[3] = {0.1, 0.2, 0.3};
  const std::vector<double> u = linearField(p.x, dim, Ad, b);
  double force[3] = {}, scale = 0;
  for (const auto &cell : p.cells) {
    std::vector<double> xe(nd), ue(nd);
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < dim; ++i) xe[a * dim + i] = p.x[cell[a] * dim + i], ue[a * dim + i] = u[cell[a] * dim + i];
    const std::vector<double> Ke = stiffness(p.shape, xe);
    const std::vector<double> fe = multiply(Ke, ue);
    // Round-off in K u is relative to the terms summed, |K| |u|, not to |K u|.
    scale = std::max(scale, maxAbs(Ke) * maxAbs(ue));
    for (int a = 0; a < n; ++a)
      if (cell[a] == p.interior)
        for (int i = 0; i < dim; ++i) force[i] += fe[a * dim + i];
  }
  double worst = 0;
  for (int i = 0; i < dim; ++i) worst = std::max(worst, std::fabs(force[i]));
  unit::near(worst / scale, 0, 0, 1e-13,
             std::string(p.name) + ": patch of " + std::to_string(p.cells.size()) +
                 " cells, zero internal force at the interior node");
}

// Renumbering the nodes consistently must permute K and nothing else.
void testNodeOrderInvariance(const Cell &c, const std::vector<int> &perm, const std::string &what) {
  const int dim = cellDimension(c.shape), nd = dofs(c.shape), n = cellNodeCount(c.shape);
  std::vector<double> y(c.coords.size());
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < dim; ++i) y[a * dim + i] = c.coords[perm[a] * dim + i];
  const std::vector<double> K = stiffness(c.shape, c.coords), Kp = stiffness(c.shape, y);
  double worst = 0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j)
          worst = std::max(worst, std::fabs(Kp[(a * dim + i) * nd + b * dim + j] -
                                            K[(perm[a] * dim + i) * nd + perm[b] * dim + j]));
  unit::near(worst / maxAbs(K), 0, 0, 1e-14, std::string(c.name) + ": K invariant under " + what);
  std::vector<double> m(n), mp(n);
  elementLumpedMass(c.shape, c.coords.data(), 1.0, m.data());
  elementLumpedMass(c.shape, y.data(), 1.0, mp.data());
  double mworst = 0;
  for (int a = 0; a < n; ++a) mworst = std::max(mworst, std::fabs(mp[a] - m[perm[a]]));
  unit::near(mworst / maxAbs(m), 0, 0, 1e-14, std::string(c.name) + ": lumped mass invariant under " + what);
}

void testFaces() {
  // Seg2 (1,1) -> (4,5): length 5; right-hand normal (dy, -dx)/L = (4, -3)/5.
  const double seg[] = {1, 1, 4, 5};
  double w[4], nrm[3];
  faceLumpedWeights(FaceShape::Seg2, 2, seg, w);
  unit::near(w[0] + w[1], 5.0, 1e-15, 0, "Seg2 weights sum to length 5");
  unit::near(w[0], 2.5, 1e-15, 0, "Seg2 weight = L/2");
  faceNormal(FaceShape::Seg2, 2, seg, nrm);
  unit::near(nrm[0], 0.8, 1e-15, 0, "Seg2 normal x = dy/L");
  unit::near(nrm[1], -0.6, 1e-15, 0, "Seg2 normal y = -dx/L");
  // Tri3 in the plane x + y + z = 1 through the axis points: area sqrt(3)/2, normal (1,1,1)/sqrt(3).
  const double tri[] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  faceLumpedWeights(FaceShape::Tri3, 3, tri, w);
  unit::near(w[0] + w[1] + w[2], std::sqrt(3.0) / 2, 1e-15, 0, "Tri3 face weights sum to area sqrt(3)/2");
  faceNormal(FaceShape::Tri3, 3, tri, nrm);
  for (int i = 0; i < 3; ++i)
    unit::near(nrm[i], 1 / std::sqrt(3.0), 1e-15, 0, "Tri3 face normal component " + std::to_string(i));
  // The trapezoid above placed in the plane y = -2 ((x, y) -> (x, -2, y)). Its diagonals
  // (3,0,1.5) x (3,0,-1.5) = (0,9,0): normal +y.
  // Weights by hand: the bilinear map has det J = 0.375 (3 - xi) (xi along the edge 0-1,
  // eta along the long side 0-3), so w_0 = 1/4 * 0.375 * int(1-eta) * int(1-xi)(3-xi)
  // = 1/4 * 0.375 * 2 * 20/3 = 1.25 and w_1 = 1/4 * 0.375 * 2 * 16/3 = 1.0.
  const double q2[] = {0, 0, 1, 1.5, 3, 1.5, 4, 0};
  double quad[12];
  for (int a = 0; a < 4; ++a) quad[3 * a] = q2[2 * a], quad[3 * a + 1] = -2.0, quad[3 * a + 2] = q2[2 * a + 1];
  faceLumpedWeights(FaceShape::Quad4, 3, quad, w);
  unit::near(w[0] + w[1] + w[2] + w[3], 4.5, 1e-14, 0, "Quad4 face weights sum to trapezoid area 4.5");
  const double want[4] = {1.25, 1.0, 1.0, 1.25};
  for (int a = 0; a < 4; ++a)
    unit::near(w[a], want[a], 1e-14, 0, "Quad4 trapezoid face weight node " + std::to_string(a) + " (hand integral)");
  faceNormal(FaceShape::Quad4, 3, quad, nrm);
  unit::near(nrm[0], 0, 0, 1e-15, "Quad4 face normal x");
  unit::near(nrm[1], 1, 1e-15, 0, "Quad4 face normal y (right-hand rule)");
  unit::near(nrm[2], 0, 0, 1e-15, "Quad4 face normal z");
  // Consistent face mass: rows sum to the lumped weights; Seg2 L/6 [[2, 1], [1, 2]], Tri3
  // A/12 (1 + delta_ab); a rectangle a x b: ab/36 times 4 (self), 2 (along an edge), 1 (across).
  double M[16];
  faceConsistentMass(FaceShape::Quad4, 3, quad, M);
  for (int a = 0; a < 4; ++a)
    unit::near(M[4 * a] + M[4 * a + 1] + M[4 * a + 2] + M[4 * a + 3], want[a], 1e-14, 0, "Quad4 trapezoid consistent mass row " + std::to_string(a) + " sums to its weight");
  faceConsistentMass(FaceShape::Seg2, 2, seg, M);
  unit::near(M[0], 5.0 / 3, 1e-15, 0, "Seg2 consistent mass diagonal L/3");
  unit::near(M[1], 5.0 / 6, 1e-15, 0, "Seg2 consistent mass off-diagonal L/6");
  faceConsistentMass(FaceShape::Tri3, 3, tri, M);
  unit::near(M[0], std::sqrt(3.0) / 2 / 6, 1e-15, 0, "Tri3 consistent mass diagonal A/6");
  unit::near(M[1], std::sqrt(3.0) / 2 / 12, 1e-15, 0, "Tri3 consistent mass off-diagonal A/12");
  const double rect[] = {0, 0, 0, 0, 2, 0, 0, 2, 3, 0, 0, 3};
  faceConsistentMass(FaceShape::Quad4, 3, rect, M);
  const double rect_want[4] = {4.0 / 6, 2.0 / 6, 1.0 / 6, 2.0 / 6};
  for (int b = 0; b < 4; ++b) unit::near(M[b], rect_want[b], 1e-14, 0, "2 x 3 rectangle consistent mass entry 0," + std::to_string(b));
}

} // namespace

int main() {
  const std::vector<Cell> cells = distortedCells();
  for (const Cell &c : cells) {
    unit::check(static_cast<int>(c.coords.size()) == dofs(c.shape), std::string(c.name) + ": test cell size");
    testRigidModesAndRank(c);
    testConstantStrain(c);
    testMeanDilatation(c);
    testMassSumsToRhoVolume(c);
    testReferenceCoordinates(c);
  }
  testVolumesOfKnownShapes();
  for (const Patch &p : patches()) testPatchInteriorForce(p);

  testNodeOrderInvariance(cells[0], {2, 0, 1}, "cyclic renumbering");
  testNodeOrderInvariance(cells[0], {0, 2, 1}, "orientation reversal");
  testNodeOrderInvariance(cells[1], {1, 2, 3, 0}, "cyclic shift");
  testNodeOrderInvariance(cells[1], {0, 3, 2, 1}, "clockwise order");
  testNodeOrderInvariance(cells[2], {3, 1, 0, 2}, "renumbering");
  testNodeOrderInvariance(cells[3], {1, 2, 3, 0, 5, 6, 7, 4}, "cyclic shift of both faces");
  testNodeOrderInvariance(cells[3], {4, 5, 6, 7, 0, 1, 2, 3}, "swapping the two faces");
  testNodeOrderInvariance(cells[3], {0, 3, 2, 1, 4, 7, 6, 5}, "reversing the face orientation");
  testNodeOrderInvariance(cells[3], {0, 1, 5, 4, 3, 2, 6, 7}, "choosing another face pair");
  testFaces();
  return unit::failures();
}

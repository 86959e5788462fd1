// The spectral-element operator over a block of elements: its batched loop (elements
// sharing geometry, one SIMD lane each) and its per-element loop against the element
// kernel applied element by element; the assembled mass against rho x volume; and the
// stable-step bounds against the largest eigenvalue of the assembled M^{-1} K (from below
// by the Rayleigh quotient of a converged power iteration: if a bound fell below it, the
// bound would be wrong). Prints how far each bound lies above that eigenvalue.
#include "slipwave/fem/spectral_operator.hpp"

#include "petsc_test_main.hpp"
#include "spectral_box_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace slipwave;
using fem::SpectralOperator;
using numerics::kMaxSpectralDegree;

namespace {

const std::vector<fem::RegionMaterial> kMaterials{{2100.0, {2.0e9, 1.1e9}}};

// f = sum over the elements in `elements` of the element kernel's force, node-major gathered.
std::vector<double> elementByElement(const unit::SpectralBoxMesh &m, const std::vector<PetscInt> &elements, const std::vector<double> &u) {
  const int           nq = fem::spectralNodeCount(m.dim, m.p);
  std::vector<double> f(m.ndof, 0.0), wdet(nq), jinv(nq * m.dim * m.dim), ue(nq * m.dim), fe(nq * m.dim);
  for (PetscInt e : elements) {
    fem::spectralGeometry(m.dim, m.p, &m.coords[(size_t)e * nq * m.dim], wdet.data(), jinv.data());
    for (int a = 0; a < nq; ++a)
      for (int c = 0; c < m.dim; ++c) ue[a * m.dim + c] = u[m.node_offset[e * nq + a] + c];
    fem::spectralElementForce(m.dim, m.p, wdet.data(), jinv.data(), kMaterials[0].lame, ue.data(), fe.data());
    for (int a = 0; a < nq; ++a)
      for (int c = 0; c < m.dim; ++c) f[m.node_offset[e * nq + a] + c] += fe[a * m.dim + c];
  }
  return f;
}

// max |a - b| over the round-off scale of K u, max_i sum_j |K_ij| x max |u| (K u itself
// cancels: it is much smaller than its terms).
double roundoffDifference(const std::vector<double> &a, const std::vector<double> &b, const std::vector<double> &rowabs, const std::vector<double> &u) {
  double d = 0, k = 0, umax = 0;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, std::fabs(a[i] - b[i])), k = std::max(k, rowabs[i]), umax = std::max(umax, std::fabs(u[i]));
  return d / (k * umax);
}

void warpNodes(double *X) { // a smooth map with a positive Jacobian: every element distinct
  const double x = X[0], y = X[1], z = X[2];
  X[0] += 0.06 * std::sin(1.3 * y + 0.4 * z);
  X[1] += 0.05 * std::sin(1.1 * x + 0.2);
  X[2] += 0.04 * std::sin(0.9 * x + 0.7 * y);
}

PetscErrorCode checkForce(int dim, int p, bool warped) {
  PetscFunctionBeginUser;
  const int  ne[3] = {4, 3, dim == 3 ? 2 : 1}; // 12 (2D) / 24 (3D) elements: full batches and a remainder
  const auto m     = unit::spectralBoxMesh(dim, p, ne, 1.0, warped ? warpNodes : std::function<void(double *)>());
  SpectralOperator op;
  PetscCall(op.Setup(dim, p, m.nelem, m.coords.data(), m.node_offset.data(), m.region.data(), kMaterials));
  const std::string tag = std::to_string(dim) + "D p=" + std::to_string(p) + (warped ? " warped " : " box ");
  unit::check(op.distinctGeometries() == (warped ? m.nelem : 1), tag + "geometry records shared exactly when the elements are congruent");
  std::vector<double> u(m.ndof), f(m.ndof, 0.0), rowabs(m.ndof, 0.0);
  for (PetscInt i = 0; i < m.ndof; ++i) u[i] = std::sin(0.37 * i) + 0.2 * std::cos(1.9 * i);
  op.addStiffnessRowAbsSums(rowabs.data());
  op.addStiffnessTimes(u.data(), f.data());
  std::vector<PetscInt> all(m.nelem), some;
  for (PetscInt e = 0; e < m.nelem; ++e) all[e] = e;
  // The same kernel; the vector and scalar code differ only in where the compiler contracts
  // a multiply and an add into an FMA: round-off, a few eps of the scale of the terms.
  unit::near(roundoffDifference(f, elementByElement(m, all, u), rowabs, u), 0, 0, 1e-14, tag + "operator K u = element-by-element K u");
  for (PetscInt e = 0; e < m.nelem; ++e)
    if (e % 3 != 1) some.push_back(e);
  std::fill(f.begin(), f.end(), 0.0);
  op.addStiffnessTimes(op.subset(some), u.data(), f.data());
  unit::near(roundoffDifference(f, elementByElement(m, some, u), rowabs, u), 0, 0, 1e-14, tag + "subset K u = element-by-element K u on the subset");
  // The element matrix of the last element times its u = the operator on that element alone.
  {
    const PetscInt      e = m.nelem - 1, n = op.nodesPerElement() * dim;
    std::vector<double> K((size_t)n * n), fe(m.ndof, 0.0), want(m.ndof, 0.0);
    op.elementStiffness(e, K.data());
    for (PetscInt r = 0; r < n; ++r)
      for (PetscInt c = 0; c < n; ++c) want[op.elementNodeOffset(e, r / dim) + r % dim] += K[r * n + c] * u[op.elementNodeOffset(e, c / dim) + c % dim];
    op.addStiffnessTimes(op.subset({e}), u.data(), fe.data());
    unit::near(roundoffDifference(fe, want, rowabs, u), 0, 0, 1e-14, tag + "elementStiffness x u = the operator on that element");
    // elementForce on the element's own vector (node-major), scattered like the operator.
    std::vector<double> ue(n), ke(n);
    for (PetscInt r = 0; r < n; ++r) ue[r] = u[op.elementNodeOffset(e, r / dim) + r % dim];
    op.elementForce(e, ue.data(), ke.data());
    std::fill(fe.begin(), fe.end(), 0.0);
    for (PetscInt r = 0; r < n; ++r) fe[op.elementNodeOffset(e, r / dim) + r % dim] += ke[r];
    unit::near(roundoffDifference(fe, want, rowabs, u), 0, 0, 1e-14, tag + "elementForce(u_e) = elementStiffness x u_e");
  }
  // Mass of the block: rho x its volume per component (box: 4 x 3 (x 2) unit cubes).
  std::vector<double> mass(m.ndof, 0.0);
  op.addLumpedMass(mass.data());
  double total = 0;
  for (double v : mass) total += v;
  if (!warped) unit::near(total, dim * kMaterials[0].rho * (dim == 3 ? 24.0 : 12.0), 1e-13, 0, tag + "assembled mass = dim x rho x volume");
  // Patch test through the operator's node offsets: u = A x gives sigma = lambda tr(A) I +
  // mu (A + A^T) in every element at any point (A symmetric here, so eps = A).
  const double A[3][3] = {{1e-3, 2e-4, -1e-4}, {2e-4, -5e-4, 3e-4}, {-1e-4, 3e-4, 4e-4}};
  for (PetscInt e = 0; e < m.nelem; ++e)
    for (PetscInt a = 0; a < op.nodesPerElement(); ++a)
      for (int i = 0; i < dim; ++i) {
        double v = 0;
        for (int j = 0; j < dim; ++j) v += A[i][j] * op.elementCoordinates(e)[a * dim + j];
        u[op.elementNodeOffset(e, a) + i] = v;
      }
  const fem::LameParameters &l = kMaterials[0].lame;
  const double tr = A[0][0] + A[1][1] + (dim == 3 ? A[2][2] : 0.0);
  const double want[6] = {l.lambda * tr + 2 * l.mu * A[0][0], l.lambda * tr + 2 * l.mu * A[1][1], l.lambda * tr + (dim == 3 ? 2 * l.mu * A[2][2] : 0.0),
                          2 * l.mu * A[0][1], dim == 3 ? 2 * l.mu * A[1][2] : 0.0, dim == 3 ? 2 * l.mu * A[0][2] : 0.0};
  double worst = 0;
  const double xi[3] = {0.21, -0.63, 0.48};
  for (PetscInt e = 0; e < m.nelem; ++e) {
    double sigma[6];
    op.stressAt(e, xi, u.data(), sigma);
    for (int k = 0; k < 6; ++k) worst = std::max(worst, std::fabs(sigma[k] - want[k]));
  }
  unit::near(worst / (l.lambda * 1e-3), 0, 0, 1e-12, tag + "stressAt: linear field gives its constant stress in every element");
  PetscFunctionReturn(0);
}

// lambda_max(M^{-1} K) from below: the Rayleigh quotient u^T K u / u^T M u of a power
// iteration on M^{-1} K (any Rayleigh quotient is <= lambda_max).
double rayleighLowerBound(const SpectralOperator &op, const std::vector<double> &mass, int iterations) {
  const size_t        n = mass.size();
  std::vector<double> u(n), f(n);
  for (size_t i = 0; i < n; ++i) u[i] = 1 + 0.5 * std::sin(2.3 * i);
  double rq = 0;
  for (int it = 0; it < iterations; ++it) {
    std::fill(f.begin(), f.end(), 0.0);
    op.addStiffnessTimes(u.data(), f.data());
    double uKu = 0, uMu = 0, norm = 0;
    for (size_t i = 0; i < n; ++i) uKu += u[i] * f[i], uMu += u[i] * mass[i] * u[i];
    rq = uKu / uMu;
    for (size_t i = 0; i < n; ++i) u[i] = f[i] / mass[i], norm = std::max(norm, std::fabs(u[i]));
    for (size_t i = 0; i < n; ++i) u[i] /= norm;
  }
  return rq;
}

PetscErrorCode checkBounds(int dim, int p) {
  PetscFunctionBeginUser;
  const int  ne[3] = {3, 3, 2};
  const auto m     = unit::spectralBoxMesh(dim, p, ne, 1.0, warpNodes);
  SpectralOperator op;
  PetscCall(op.Setup(dim, p, m.nelem, m.coords.data(), m.node_offset.data(), m.region.data(), kMaterials));
  std::vector<double> mass(m.ndof, 0.0), rowabs(m.ndof, 0.0);
  op.addLumpedMass(mass.data());
  op.addStiffnessRowAbsSums(rowabs.data());
  double gershgorin = 0;
  for (PetscInt i = 0; i < m.ndof; ++i) gershgorin = std::max(gershgorin, rowabs[i] / mass[i]);
  const double element_gershgorin = op.maxElementEigenBound(fem::EigenBoundKind::Gershgorin);
  const double element_cw         = op.maxElementEigenBound(fem::EigenBoundKind::CollatzWielandt);
  const double element_certified  = op.maxElementEigenBound(fem::EigenBoundKind::Certified);
  const double lambda             = rayleighLowerBound(op, mass, 4000);
  const std::string tag = std::to_string(dim) + "D p=" + std::to_string(p) + " warped ";
  unit::check(gershgorin >= lambda, tag + "global Gershgorin bound >= lambda_max(M^-1 K)");
  unit::check(element_gershgorin >= lambda, tag + "element Gershgorin bound >= lambda_max(M^-1 K)");
  unit::check(element_cw >= lambda, tag + "element Collatz-Wielandt bound >= lambda_max(M^-1 K)");
  unit::check(element_certified >= lambda, tag + "element certified bound >= lambda_max(M^-1 K)");
  unit::check(element_cw <= element_gershgorin, tag + "Collatz-Wielandt iterations tighten the element Gershgorin bound");
  unit::check(element_certified <= element_cw, tag + "the certified bound is no looser than Collatz-Wielandt");
  std::printf("# %s bound / lambda_max: global Gershgorin %.3f, element Gershgorin %.3f, element Collatz-Wielandt %.3f, "
              "element certified %.3f (stable dt ratio = 1/sqrt of these: %.3f %.3f %.3f %.3f)\n",
              tag.c_str(), gershgorin / lambda, element_gershgorin / lambda, element_cw / lambda, element_certified / lambda, 1 / std::sqrt(gershgorin / lambda),
              1 / std::sqrt(element_gershgorin / lambda), 1 / std::sqrt(element_cw / lambda), 1 / std::sqrt(element_certified / lambda));
  PetscFunctionReturn(0);
}

// A folded element (the block mirrored in x at one node column) stops Setup with an error.
PetscErrorCode checkFoldedElementRejected() {
  PetscFunctionBeginUser;
  const int ne[3] = {2, 1, 1};
  auto      m     = unit::spectralBoxMesh(2, 2, ne, 1.0);
  m.coords[0]     = 1.5; // node 0 of element 0 pushed past its neighbours: det J < 0 there
  SpectralOperator op;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  const PetscErrorCode ierr = op.Setup(2, 2, m.nelem, m.coords.data(), m.node_offset.data(), m.region.data(), kMaterials);
  PetscCall(PetscPopErrorHandler());
  unit::check(ierr == PETSC_ERR_USER_INPUT, "folded element stops Setup with PETSC_ERR_USER_INPUT");
  PetscFunctionReturn(0);
}

PetscErrorCode run(bool) {
  PetscFunctionBeginUser;
  PetscCall(checkFoldedElementRejected());
  for (int dim = 2; dim <= 3; ++dim)
    for (int p = 1; p <= kMaxSpectralDegree; ++p) {
      PetscCall(checkForce(dim, p, false));
      PetscCall(checkForce(dim, p, true));
    }
  for (int dim = 2; dim <= 3; ++dim)
    for (int p = 1; p <= (dim == 2 ? 8 : 4); ++p) PetscCall(checkBounds(dim, p));
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char **argv) { return unit::runPetscTest(argc, argv, run); }

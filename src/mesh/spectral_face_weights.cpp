#include "slipwave/mesh/spectral_face_weights.hpp"

#include "slipwave/numerics/gll_basis.hpp"

#include <cmath>

namespace slipwave::mesh {

double gllFaceNodeWeight(int dim, int p, const double *X, int I, int J) {
  double xi[numerics::kMaxSpectralDegree + 1], wq[numerics::kMaxSpectralDegree + 1];
  numerics::gllPointsWeights(p, xi, wq);
  const auto share = [p](int i) { return (i == 0 || i == p) ? 1.0 : 2.0; };
  if (dim == 2) { // straight side: |dx/dxi| = L/2
    const double dx = X[2] - X[0], dy = X[3] - X[1];
    return wq[I] * 0.5 * std::sqrt(dx * dx + dy * dy) / share(I);
  }
  // Bilinear side on [-1,1]^2: the tangents at (xi_I, xi_J), their cross product.
  const double s = xi[I], t = xi[J];
  double       a[3], b[3], n[3];
  for (int d = 0; d < 3; ++d) {
    a[d] = 0.25 * ((1 - t) * (X[3 + d] - X[d]) + (1 + t) * (X[9 + d] - X[6 + d]));
    b[d] = 0.25 * ((1 - s) * (X[6 + d] - X[d]) + (1 + s) * (X[9 + d] - X[3 + d]));
  }
  n[0] = a[1] * b[2] - a[2] * b[1], n[1] = a[2] * b[0] - a[0] * b[2], n[2] = a[0] * b[1] - a[1] * b[0];
  return wq[I] * wq[J] * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) / (share(I) * share(J));
}

PetscErrorCode SpectralFaceWeights(const SpectralLayout &L, const VertexCoordinates &coords, PetscInt cell_local, PetscInt nfv, const PetscInt *fverts, double *w) {
  const PetscInt p = L.degree, dim = L.dim, np1 = p + 1;
  PetscFunctionBeginUser;
  const PetscInt  e     = L.cell_element[cell_local];
  const PetscInt  nnode = SpectralCount(np1, dim);
  const PetscInt *nodes = &L.element_nodes[(size_t)e * nnode];
  // The face's vertices as GLL indices of the element.
  PetscInt idx[4][3] = {{0}};
  for (PetscInt a = 0; a < nfv; ++a) {
    PetscInt n = -1;
    for (PetscInt k = 0; k < nnode && n < 0; ++k)
      if (nodes[k] == fverts[a]) n = k;
    PetscCheck(n >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "SpectralFaceWeights: vertex %" PetscInt_FMT " is not a node of element %" PetscInt_FMT, fverts[a], L.element_id[e]);
    idx[a][0] = n % np1, idx[a][1] = (n / np1) % np1, idx[a][2] = n / (np1 * np1);
  }
  // The element side it lies on: the dimension where every vertex has the index 0, or p.
  PetscInt fixed = -1;
  for (PetscInt d = 0; d < dim && fixed < 0; ++d) {
    bool same = idx[0][d] == 0 || idx[0][d] == p;
    for (PetscInt a = 1; a < nfv; ++a) same = same && idx[a][d] == idx[0][d];
    if (same) fixed = d;
  }
  PetscCheck(fixed >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "SpectralFaceWeights: the face lies inside element %" PetscInt_FMT, L.element_id[e]);
  PetscInt t1 = -1, t2 = -1;
  for (PetscInt d = 0; d < dim; ++d)
    if (d != fixed) (t1 < 0 ? t1 : t2) = d;
  double corners[4 * 3];
  for (PetscInt k = 0; k < (dim == 2 ? 2 : 4); ++k) {
    PetscInt c[3] = {0, 0, 0};
    c[fixed]      = idx[0][fixed];
    c[t1]         = (k & 1) * p;
    if (t2 >= 0) c[t2] = ((k >> 1) & 1) * p;
    PetscCall(coords.Get(nodes[c[0] + np1 * (c[1] + np1 * c[2])], &corners[k * dim]));
  }
  for (PetscInt a = 0; a < nfv; ++a) w[a] = gllFaceNodeWeight((int)dim, (int)p, corners, (int)idx[a][t1], t2 >= 0 ? (int)idx[a][t2] : 0);
  PetscFunctionReturn(0);
}

} // namespace slipwave::mesh

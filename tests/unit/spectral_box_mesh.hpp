// A structured block of ne[0] x ne[1] (x ne[2]) spectral elements of degree p and size h for
// the operator tests and benchmarks, in the arrays SpectralOperator::Setup takes: the global
// GLL node grid numbered lexicographically (dof offset = node * dim), elements in
// lexicographic order, every element in region 0. warp (may be empty) moves every node, so
// that each element gets its own geometry.
#pragma once
#include <petscsys.h>

#include <functional>
#include <vector>

#include "slipwave/fem/spectral_kernels.hpp"
#include "slipwave/numerics/gll_basis.hpp"

namespace unit {

struct SpectralBoxMesh {
  int                   dim = 0, p = 0;
  PetscInt              nelem = 0, ndof = 0;
  std::vector<double>   coords;      // nelem * (p+1)^dim * dim
  std::vector<PetscInt> node_offset; // nelem * (p+1)^dim
  std::vector<PetscInt> region;      // nelem zeros
};

inline SpectralBoxMesh spectralBoxMesh(int dim, int p, const int *ne, double h, const std::function<void(double *)> &warp = {}) {
  SpectralBoxMesh m;
  m.dim = dim, m.p = p;
  double x[slipwave::fem::kMaxSpectralNodes1D], w[slipwave::fem::kMaxSpectralNodes1D];
  slipwave::numerics::gllPointsWeights(p, x, w);
  const int n1 = p + 1, nz = dim == 3 ? n1 : 1, ez = dim == 3 ? ne[2] : 1;
  const PetscInt gx = (PetscInt)ne[0] * p + 1, gy = (PetscInt)ne[1] * p + 1, gz = dim == 3 ? (PetscInt)ne[2] * p + 1 : 1;
  m.nelem = (PetscInt)ne[0] * ne[1] * ez;
  m.ndof  = gx * gy * gz * dim;
  for (int ek = 0; ek < ez; ++ek)
    for (int ej = 0; ej < ne[1]; ++ej)
      for (int ei = 0; ei < ne[0]; ++ei)
        for (int k = 0; k < nz; ++k)
          for (int j = 0; j < n1; ++j)
            for (int i = 0; i < n1; ++i) {
              const PetscInt node = (ei * p + i) + gx * ((ej * p + j) + gy * (PetscInt)(ek * p + k));
              m.node_offset.push_back(node * dim);
              double X[3] = {h * (ei + 0.5 * (x[i] + 1)), h * (ej + 0.5 * (x[j] + 1)), h * (ek + 0.5 * (x[k] + 1))};
              if (warp) warp(X);
              for (int d = 0; d < dim; ++d) m.coords.push_back(X[d]);
            }
  m.region.assign(m.nelem, 0);
  return m;
}

} // namespace unit

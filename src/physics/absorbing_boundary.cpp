#include "slipwave/physics/absorbing_boundary.hpp"

namespace slipwave::physics {

void lysmerDashpot(int dim, const double *n, double area, const ElasticMaterial &m, double *C) {
  const double zp = m.rho * m.vp, zs = m.rho * m.vs;
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) C[i * dim + j] = area * ((zp - zs) * n[i] * n[j] + (i == j ? zs : 0.0));
}

void incidentWaveTraction(int dim, const double *d, double rho, double c, double v_in, double *t) {
  for (int i = 0; i < dim; ++i) t[i] = 2 * rho * c * v_in * d[i];
}

} // namespace slipwave::physics

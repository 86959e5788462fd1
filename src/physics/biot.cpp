#include "slipwave/physics/biot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace slipwave::physics {

double biotCoefficient(const BiotMaterial &b, double K_drained) { return b.grain_bulk_modulus > 0 ? 1.0 - K_drained / b.grain_bulk_modulus : 1.0; }

double biotModulus(const BiotMaterial &b, double K_drained) {
  const double alpha     = biotCoefficient(b, K_drained);
  const double inverse_M = b.porosity / b.fluid_bulk_modulus + (b.grain_bulk_modulus > 0 ? (alpha - b.porosity) / b.grain_bulk_modulus : 0.0);
  return 1.0 / inverse_M;
}

double mobility(const BiotMaterial &b) { return b.hydraulic_conductivity / (b.fluid_density * b.gravity); }

double undrainedBulkModulus(double K_drained, double alpha, double M) { return K_drained + alpha * alpha * M; }

double skemptonB(double K_drained, double alpha, double M) { return alpha * M / undrainedBulkModulus(K_drained, alpha, M); }

double loadingEfficiency(double K_drained, double G, double alpha, double M) { return alpha * M / (K_drained + 4.0 * G / 3.0 + alpha * alpha * M); }

double undrainedPWaveSpeed(double K_drained, double G, double alpha, double M, double rho) {
  return std::sqrt((K_drained + 4.0 * G / 3.0 + alpha * alpha * M) / rho);
}

double undrainedPlaneWavePressure(double sigma_zz, double eps_xx, double lambda_undrained, double mu, double alpha, double M) {
  const double eps_zz = (sigma_zz - lambda_undrained * eps_xx) / (lambda_undrained + 2.0 * mu);
  return -alpha * M * (eps_xx + eps_zz);
}

double consolidationCoefficient(double K_drained, double G, double alpha, double M, double kappa) {
  return kappa / (1.0 / M + alpha * alpha / (K_drained + 4.0 * G / 3.0));
}

double explicitDiffusionStepOfRow(double storage, double diffusion_row_abs_sum) {
  return diffusion_row_abs_sum > 0 ? 2.0 * storage / diffusion_row_abs_sum : 1e300;
}

int diffusionSubsteps(double h, double dt_diffusion, bool subcycle) { return subcycle && h > 0 ? std::max(1, (int)std::ceil(h / (0.9 * dt_diffusion))) : 1; }

std::string biotMaterialProblem(const BiotMaterial &b, double K_drained) {
  char buf[200];
  if (!(b.porosity > 0 && b.porosity < 1)) std::snprintf(buf, sizeof buf, "porosity = %g; allowed: 0 < n < 1", b.porosity);
  else if (!(b.fluid_bulk_modulus > 0)) std::snprintf(buf, sizeof buf, "fluid bulk modulus = %g Pa; allowed: > 0", b.fluid_bulk_modulus);
  else if (!(b.grain_bulk_modulus == 0 || b.grain_bulk_modulus > K_drained))
    std::snprintf(buf, sizeof buf, "grain bulk modulus = %g Pa; allowed: 0 (incompressible grains) or above the drained bulk modulus %g Pa", b.grain_bulk_modulus,
                  K_drained);
  else if (!(b.hydraulic_conductivity >= 0)) std::snprintf(buf, sizeof buf, "hydraulic conductivity = %g m/s; allowed: >= 0", b.hydraulic_conductivity);
  else if (!(b.fluid_density > 0)) std::snprintf(buf, sizeof buf, "fluid density = %g kg/m^3; allowed: > 0", b.fluid_density);
  else if (!(b.gravity > 0)) std::snprintf(buf, sizeof buf, "gravity = %g m/s^2; allowed: > 0", b.gravity);
  else return "";
  return buf;
}

} // namespace slipwave::physics

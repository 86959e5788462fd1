#include "slipwave/physics/damped_medium.hpp"

#include <cmath>

namespace slipwave::physics {

DampedMedium dampedMedium(const ElasticMaterial &m, const MediumDamping &d, double w) {
  const LameParameters lm     = lame(m);
  std::complex<double> factor = std::complex<double>(1.0, w * d.rayleigh.beta);
  if (!d.constant_q.omega.empty()) factor *= d.unrelaxed_factor * constantQModulusRatio(d.constant_q, w / (2 * M_PI));
  const std::complex<double> rho = w > 0 ? m.rho * std::complex<double>(1.0, -d.rayleigh.alpha / w) : std::complex<double>(m.rho);
  return {rho, factor * lm.lambda, factor * lm.mu};
}

} // namespace slipwave::physics

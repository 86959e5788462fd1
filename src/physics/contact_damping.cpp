#include "slipwave/physics/contact_damping.hpp"

#include <algorithm>
#include <cmath>

namespace slipwave::physics {

double contactDashpotCoefficient(double zeta, double k, double m1, double m2) {
  const double m_eff = m1 * m2 / (m1 + m2);
  return 2.0 * zeta * std::sqrt(k * m_eff);
}

double contactDampingTraction(double c_per_area, double w_dot, double sigma_N) {
  const double viscous = c_per_area * w_dot;
  if (viscous <= 0) return viscous; // closing: resists
  return std::min(viscous, std::max(-sigma_N, 0.0));
}

} // namespace slipwave::physics

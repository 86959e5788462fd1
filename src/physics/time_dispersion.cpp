#include "slipwave/physics/time_dispersion.hpp"

#include <cmath>

namespace slipwave::physics {

double integratorPhaseSpeedError(int order, double omega_dt) {
  // omega~ h = 2 asin(sqrt((1 - cos)/2)), without the cancellation of acos near 1: 1 - cos is
  // W^2/2 at order 2 and (W^2/2)(1 - W^2/12) at order 4.
  const double W = omega_dt;
  const double half_chord = order == 2 ? 0.5 * W : 0.5 * W * std::sqrt(1 - W * W / 12);
  return 2 * std::asin(half_chord) / W - 1;
}

double integratorStepForError(int order, double omega, double error) {
  const double w_max = order == 2 ? 2.0 : std::sqrt(12.0);
  double       lo = 0, hi = w_max;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (std::fabs(integratorPhaseSpeedError(order, mid)) <= error) lo = mid;
    else hi = mid;
  }
  return lo / omega;
}

} // namespace slipwave::physics

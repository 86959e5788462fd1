#include "slipwave/physics/stable_time_step.hpp"

#include <cmath>

namespace slipwave::physics {

// Belytschko, Liu & Moran, Nonlinear Finite Elements for Continua and Structures (2000),
// §6.3. One mode u'' + 2 xi w u' + w^2 u = 0 with xi = beta w / 2 (the modal ratio of
// c = beta k), stepped by
//   v_{n+1/2} = v_{n-1/2} + h (-w^2 u_n - 2 xi w v_{n-1/2}),  u_{n+1} = u_n + h v_{n+1/2}.
// Eliminating v gives u_{n+1} + (W^2 + 2 xi W - 2) u_n + (1 - 2 xi W) u_{n-1} = 0 with
// W = w h. Both roots of z^2 + a1 z + a0 lie in the unit disc iff |a0| <= 1,
// 1 + a1 + a0 >= 0 and 1 - a1 + a0 >= 0 (Jury). The first two hold; the third is
// 4 - 4 xi W - W^2 >= 0, i.e. W <= 2 (sqrt(1 + xi^2) - xi).
double centralDifferenceStableStep(double omega_max, double beta_stiffness_damping) {
  const double xi = 0.5 * beta_stiffness_damping * omega_max;
  // Rewritten as 2 / (omega (sqrt(1 + xi^2) + xi)) so large xi does not cancel.
  return 2.0 / (omega_max * (std::sqrt(1 + xi * xi) + xi));
}

double centralDifferenceStableStepOfRow(double omega2, double rate) {
  // Root of (omega2/4) h^2 + (rate/2) h - 1 = 0, written without cancellation.
  return 2.0 / (std::sqrt(omega2 + 0.25 * rate * rate) + 0.5 * rate);
}

double massForStableStep(double stiffness_row, double damping_row, double dt) { return 0.25 * dt * dt * stiffness_row + 0.5 * dt * damping_row; }

double fourthOrderStableStep(double omega_max, double beta_stiffness_damping) {
  const double xi = 0.5 * beta_stiffness_damping * omega_max, w_end = std::sqrt(12.0);
  // The condition fails where xi >= Xi(W) = (1/(1 - W^2/12) - W^2/4) / W, a function that falls
  // from +inf at W = 0 to its minimum 0.2007 at W = 2.364 and rises to +inf at sqrt(12)
  // (unimodal: tests/unit/test_stable_time_step.cpp). Below the minimum every W < sqrt(12)
  // passes; above it the limit is where the falling branch meets xi.
  const auto big_xi = [](double W) { return (1 / (1 - W * W / 12) - W * W / 4) / W; };
  double lo = 0, hi = w_end;
  for (int it = 0; it < 200; ++it) { // golden-section search for the minimum of Xi
    const double a = lo + 0.381966 * (hi - lo), b = hi - 0.381966 * (hi - lo);
    if (big_xi(a) < big_xi(b)) hi = b;
    else lo = a;
  }
  const double w_min = 0.5 * (lo + hi);
  if (xi < big_xi(w_min)) return w_end / omega_max;
  lo = 0, hi = w_min;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (big_xi(mid) > xi) lo = mid;
    else hi = mid;
  }
  return lo / omega_max;
}

} // namespace slipwave::physics

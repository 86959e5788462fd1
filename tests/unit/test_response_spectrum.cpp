// The response-spectrum oscillators (numerics/response_spectrum.hpp) against the closed-form
// response of the damped oscillator, at rest at t = 0, to inputs that are linear between the
// samples, where the Nigam-Jennings step is exact: a step a(t) = a0 and a ramp a(t) = r t.
#include "slipwave/numerics/response_spectrum.hpp"

#include "unit_check.hpp"

#include <cmath>
#include <string>

using namespace slipwave::numerics;

int main() {
  const double zeta = 0.05, dt = 0.004, a0 = 2.0, r = 3.0;
  const std::vector<double> periods = {0.05, 0.3, 1.0};
  ResponseSpectrum          step(periods, zeta), ramp(periods, zeta);
  std::vector<double>       peak_step(periods.size(), 0.0), peak_ramp(periods.size(), 0.0);
  const int                 n = 1000; // 4 s
  for (int i = 0; i <= n; ++i) {
    const double t = i * dt;
    step.add(t, a0);
    ramp.add(t, r * t);
    for (size_t k = 0; k < periods.size(); ++k) {
      const double w = 2 * M_PI / periods[k], root = std::sqrt(1 - zeta * zeta), wd = w * root, e = std::exp(-zeta * w * t);
      // Step: u = -(a0 / w^2) (1 - e^{-zeta w t} (cos wd t + zeta / root sin wd t)).
      const double us = -(a0 / (w * w)) * (1 - e * (std::cos(wd * t) + zeta / root * std::sin(wd * t)));
      // Ramp: the quasi-static u_p = -(r / w^2)(t - 2 zeta / w) plus the free vibration that
      // starts the oscillator at rest: C1 = -u_p(0), C2 = (r / w^2 + zeta w C1) / wd.
      const double up = -(r / (w * w)) * (t - 2 * zeta / w), c1 = -(2 * zeta * r / (w * w * w)), c2 = (r / (w * w) + zeta * w * c1) / wd;
      const double ur = up + e * (c1 * std::cos(wd * t) + c2 * std::sin(wd * t));
      peak_step[k]    = std::fmax(peak_step[k], std::fabs(us));
      peak_ramp[k]    = std::fmax(peak_ramp[k], std::fabs(ur));
    }
  }
  for (size_t k = 0; k < periods.size(); ++k) {
    const std::string T = std::to_string(periods[k]);
    // Round-off of 1000 recursion steps only: the input is exactly linear between samples.
    unit::near(step.peakDisplacement(k), peak_step[k], 1e-10, 0, "step input, T = " + T + " s: peak |u| equals the closed form's at the samples");
    unit::near(ramp.peakDisplacement(k), peak_ramp[k], 1e-10, 0, "ramp input, T = " + T + " s: peak |u| equals the closed form's at the samples");
    const double w = 2 * M_PI / periods[k];
    unit::near(step.pseudoAcceleration(k), w * w * peak_step[k], 1e-10, 0, "PSA = omega^2 max |u|, T = " + T + " s");
  }
  // A step's peak is near the undamped 2 a0 / w^2 times 1 + e^{-zeta pi / root} (the first
  // overshoot): the closed form itself, checked against the textbook overshoot.
  const double w = 2 * M_PI / periods[1];
  unit::near(step.peakDisplacement(1), a0 / (w * w) * (1 + std::exp(-zeta * M_PI / std::sqrt(1 - zeta * zeta))), 2e-3, 0,
             "step input, T = 0.3 s: peak = (a0 / w^2)(1 + exp(-zeta pi / sqrt(1 - zeta^2))) to the sampling of the overshoot");
  return unit::failures();
}

// Numerical dispersion of the elements (numerics/spectral_dispersion) and of the integrators
// (physics/time_dispersion), the inputs of the accuracy step (problem/integrator_step):
//  - degree 1 against the closed form of the lumped linear chain, Omega = (2c/h) sin(k_h h/2);
//  - degree 2..4: the phase error of GLL spectral elements falls like (k h)^(2p) (Ainsworth &
//    Wajid 2009): the observed rate between 10 and 12 nodes per wavelength is 2p +- 0.3;
//  - the bound over all longer wavelengths is at least the error at n and never rises with n;
//  - the integrators: omega~ from their characteristic equations (cos(omega~ h) = 1 - W^2/2 and
//    1 - W^2/2 + W^4/24) to round-off, their leading terms W^2/24 and -W^4/720, and
//    integratorStepForError as the inverse of the error within the stable range.
#include "slipwave/numerics/spectral_dispersion.hpp"
#include "slipwave/physics/time_dispersion.hpp"

#include "unit_check.hpp"

#include <cmath>
#include <string>

using namespace slipwave;

int main() {
  // Degree 1: the chain of lumped linear elements of length 2 (c = 1) carries Omega = sin(theta_h / 2)
  // at frequency Omega = theta / 2, so theta_h = 2 asin(theta / 2).
  for (double theta : {0.3, 1.0, 1.6}) {
    const double want = theta / (2 * std::asin(theta / 2)) - 1;
    unit::near(numerics::spectralPhaseSpeedError(1, theta), want, 1e-10, 1e-14, "p = 1, theta = " + std::to_string(theta).substr(0, 3) + ": the lumped chain's closed form");
  }
  // Degrees 2..4: the rate of the phase error in the nodes per wavelength n (theta = 2 pi p / n).
  for (int p : {2, 3, 4}) {
    const double e10 = std::fabs(numerics::spectralPhaseSpeedError(p, 2 * M_PI * p / 10)), e12 = std::fabs(numerics::spectralPhaseSpeedError(p, 2 * M_PI * p / 12));
    const double rate = std::log(e10 / e12) / std::log(1.2);
    unit::check(std::fabs(rate - 2 * p) <= 0.3 && numerics::spectralPhaseSpeedError(p, 2 * M_PI * p / 10) < 0,
                "p = " + std::to_string(p) + ": GLL elements are slow, error rate in n " + std::to_string(rate).substr(0, 5) + " (2p = " + std::to_string(2 * p) + " +- 0.3)");
  }
  // The bound: at least the error at n, and non-increasing in n.
  for (int p : {2, 4, 6}) {
    bool   ok = true;
    double previous = HUGE_VAL;
    for (double n = 4; n <= 16; n += 0.5) {
      const double bound = numerics::spectralDispersionBound(p, n);
      ok = ok && bound >= std::fabs(numerics::spectralPhaseSpeedError(p, 2 * M_PI * p / n)) && bound <= previous * (1 + 1e-12);
      previous = bound;
    }
    unit::check(ok, "p = " + std::to_string(p) + ": the bound is at least the error at n and never rises with n (n = 4 .. 16)");
  }
  // The integrators.
  for (double W : {0.1, 0.7, 1.5}) {
    const double e2 = physics::integratorPhaseSpeedError(2, W), e4 = physics::integratorPhaseSpeedError(4, W);
    const double x = W * W;
    unit::near(std::cos((1 + e2) * W), 1 - x / 2, 1e-13, 1e-15, "order 2, W = " + std::to_string(W).substr(0, 3) + ": cos(omega~ h) = 1 - W^2/2");
    unit::near(std::cos((1 + e4) * W), 1 - x / 2 + x * x / 24, 1e-13, 1e-15, "order 4, W = " + std::to_string(W).substr(0, 3) + ": cos(omega~ h) = 1 - W^2/2 + W^4/24");
  }
  unit::near(physics::integratorPhaseSpeedError(2, 0.02), 0.02 * 0.02 / 24, 1e-3, 0, "order 2: W^2/24 for small W");
  unit::near(physics::integratorPhaseSpeedError(4, 0.05), -std::pow(0.05, 4) / 720, 2e-3, 0, "order 4: -W^4/720 for small W");
  for (int order : {2, 4})
    for (double error : {1e-6, 1e-3}) {
      const double omega = 100, h = physics::integratorStepForError(order, omega, error);
      unit::near(std::fabs(physics::integratorPhaseSpeedError(order, omega * h)), error, 1e-9, 0,
                 "order " + std::to_string(order) + ": the step for an error of " + std::to_string(error) + " has that error");
    }
  return unit::failures();
}

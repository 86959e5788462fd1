#include "slipwave/numerics/response_spectrum.hpp"

#include <cmath>

namespace slipwave::numerics {

OscillatorStep oscillatorStep(double omega, double zeta, double dt) {
  const double root = std::sqrt(1.0 - zeta * zeta), wd = omega * root, e = std::exp(-zeta * omega * dt);
  const double s = std::sin(wd * dt), c = std::cos(wd * dt);
  OscillatorStep step;
  step.A[0] = e * (c + zeta / root * s);
  step.A[1] = e * s / wd;
  step.A[2] = -e * omega / root * s;
  step.A[3] = e * (c - zeta / root * s);
  // For a = a0 + da tau the particular solution is quasi-static, u_p = p + q tau with
  // q = -da / omega^2 and p = -(a0 - 2 zeta da / omega) / omega^2; the free vibration carries
  // the rest of the initial state: x(dt) = x_p(dt) + A (x(0) - x_p(0)). Column j of B is
  // x_p(dt) - A x_p(0) for a unit a_i (j = 0) or a unit a_{i+1} (j = 1).
  const double k = 1.0 / (omega * omega);
  for (int j = 0; j < 2; ++j) {
    const double a0 = j == 0 ? 1.0 : 0.0, a1 = 1.0 - a0, da = (a1 - a0) / dt;
    const double vp = -k * da, u0 = -k * (a0 - 2 * zeta / omega * da), u1 = -k * (a1 - 2 * zeta / omega * da);
    step.B[j]     = u1 - (step.A[0] * u0 + step.A[1] * vp);
    step.B[2 + j] = vp - (step.A[2] * u0 + step.A[3] * vp);
  }
  return step;
}

ResponseSpectrum::ResponseSpectrum(const std::vector<double> &periods, double zeta)
    : periods_(periods), zeta_(zeta), steps_(periods.size()), state_(2 * periods.size(), 0.0), peak_(periods.size(), 0.0) {}

void ResponseSpectrum::add(double t, double a) {
  if (!started_) {
    started_ = true;
    t_       = t;
    a_       = a;
    return;
  }
  const double dt = t - t_;
  // A step of another length (the run's last, shortened to end on -ts_max_time) gets its own
  // matrices; equal lengths to round-off reuse them.
  if (std::fabs(dt - dt_) > 1e-12 * dt) {
    dt_ = dt;
    for (size_t k = 0; k < periods_.size(); ++k) steps_[k] = oscillatorStep(2 * M_PI / periods_[k], zeta_, dt);
  }
  for (size_t k = 0; k < periods_.size(); ++k) {
    const OscillatorStep &s = steps_[k];
    double               *x = &state_[2 * k];
    const double          u = s.A[0] * x[0] + s.A[1] * x[1] + s.B[0] * a_ + s.B[1] * a;
    const double          v = s.A[2] * x[0] + s.A[3] * x[1] + s.B[2] * a_ + s.B[3] * a;
    x[0]                    = u;
    x[1]                    = v;
    peak_[k]                = std::fmax(peak_[k], std::fabs(u));
  }
  t_ = t;
  a_ = a;
}

double ResponseSpectrum::pseudoAcceleration(size_t k) const {
  const double omega = 2 * M_PI / periods_[k];
  return omega * omega * peak_[k];
}

} // namespace slipwave::numerics

#include "slipwave/physics/source_time_function.hpp"

#include <algorithm>
#include <cmath>

namespace slipwave::physics {

double velocity(const RickerWavelet &w, double t) {
  const double a = M_PI * M_PI * w.frequency * w.frequency, tau = t - w.delay;
  return w.amplitude * (1 - 2 * a * tau * tau) * std::exp(-a * tau * tau);
}

double displacement(const RickerWavelet &w, double t) {
  const double a = M_PI * M_PI * w.frequency * w.frequency, tau = t - w.delay;
  return w.amplitude * tau * std::exp(-a * tau * tau);
}

double acceleration(const RickerWavelet &w, double t) {
  const double a = M_PI * M_PI * w.frequency * w.frequency, tau = t - w.delay;
  return w.amplitude * 2 * a * tau * (2 * a * tau * tau - 3) * std::exp(-a * tau * tau);
}

double topFrequency(const RickerWavelet &w) { return kRickerTopFrequencyRatio * w.frequency; }

double velocity(const GaborWavelet &w, double t) {
  const double tau = t - w.delay, k = 2 * M_PI * w.frequency / w.gamma;
  return w.amplitude * std::exp(-k * k * tau * tau) * std::cos(2 * M_PI * w.frequency * tau + w.phase);
}

double acceleration(const GaborWavelet &w, double t) {
  const double tau = t - w.delay, k = 2 * M_PI * w.frequency / w.gamma, om = 2 * M_PI * w.frequency;
  return w.amplitude * std::exp(-k * k * tau * tau) *
         (-2 * k * k * tau * std::cos(om * tau + w.phase) - om * std::sin(om * tau + w.phase));
}

double topFrequency(const GaborWavelet &w) { return w.frequency * (1 + 2 * std::sqrt(std::log(100.0)) / w.gamma); }

double velocity(const HarmonicWave &w, double t) {
  return t < w.delay ? 0.0 : w.amplitude * std::sin(2 * M_PI * w.frequency * (t - w.delay));
}

double acceleration(const HarmonicWave &w, double t) {
  const double om = 2 * M_PI * w.frequency;
  return t < w.delay ? 0.0 : w.amplitude * om * std::cos(om * (t - w.delay));
}

double topFrequency(const HarmonicWave &w) { return 2 * w.frequency; }

double velocity(const TabulatedHistory &h, double t) {
  if (h.times.empty() || t < h.times.front()) return 0;
  if (t >= h.times.back()) return h.values.back();
  const size_t k = std::upper_bound(h.times.begin(), h.times.end(), t) - h.times.begin();  // t in [t_{k-1}, t_k)
  const double s = (t - h.times[k - 1]) / (h.times[k] - h.times[k - 1]);
  return (1 - s) * h.values[k - 1] + s * h.values[k];
}

double topFrequency(const TabulatedHistory &h) {
  double dt_max = 0;
  for (size_t k = 1; k < h.times.size(); ++k) dt_max = std::max(dt_max, h.times[k] - h.times[k - 1]);
  return dt_max > 0 ? 0.5 / dt_max : 0;
}

} // namespace slipwave::physics

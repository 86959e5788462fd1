#include "slipwave/physics/constant_q.hpp"

#include "slipwave/numerics/dense_solve.hpp"

#include <cmath>

namespace slipwave::physics {

ConstantQModel constantQFit(double damping_ratio, double f_min, double f_max, int mechanisms) {
  const int    n = mechanisms, samples = 4 * n + 1;
  const double q_inv = 2 * damping_ratio;
  ConstantQModel model;
  model.damping_ratio = damping_ratio;
  auto logSpaced = [&](int count, int i) { return count == 1 ? 2 * M_PI * std::sqrt(f_min * f_max) : 2 * M_PI * f_min * std::pow(f_max / f_min, (double)i / (count - 1)); };
  for (int l = 0; l < n; ++l) model.omega.push_back(logSpaced(n, l));
  // Normal equations A^T A y = A^T b of the sampled condition (b = Q0^{-1} at every sample).
  // (Weighting the rows for the relative error of Q instead was tried: no better.)
  std::vector<double> ata(n * n, 0.0), atb(n, 0.0), row(n);
  for (int k = 0; k < samples; ++k) {
    const double w = logSpaced(samples, k);
    for (int l = 0; l < n; ++l) {
      const double wl = model.omega[l];
      row[l]          = (wl * w + q_inv * wl * wl) / (wl * wl + w * w);
    }
    for (int i = 0; i < n; ++i) {
      atb[i] += row[i] * q_inv;
      for (int j = 0; j < n; ++j) ata[i * n + j] += row[i] * row[j];
    }
  }
  model.weight.assign(n, 0.0);
  numerics::solveDense(n, ata.data(), atb.data(), model.weight.data());
  return model;
}

std::complex<double> constantQModulusRatio(const ConstantQModel &model, double f) {
  const double         w = 2 * M_PI * f;
  std::complex<double> m = 1.0;
  for (size_t l = 0; l < model.omega.size(); ++l) m -= model.weight[l] * model.omega[l] / std::complex<double>(model.omega[l], w);
  return m;
}

double constantQQuality(const ConstantQModel &model, double f) {
  const std::complex<double> m = constantQModulusRatio(model, f);
  return m.real() / m.imag();
}

double constantQSpeedRatio(const ConstantQModel &model, double f) { return 1.0 / (1.0 / std::sqrt(constantQModulusRatio(model, f))).real(); }

double constantQUnrelaxedFactor(const ConstantQModel &model, double f_reference) {
  const double r = constantQSpeedRatio(model, f_reference);
  return 1.0 / (r * r);
}

double constantQReferenceForStepDrop(const ConstantQModel &model, double f_low, double max_step_drop) {
  auto dropAt = [&](double f) { return 1.0 - 1.0 / std::sqrt(constantQUnrelaxedFactor(model, f)); };
  if (dropAt(f_low) <= max_step_drop) return f_low;
  // Bisection in log f: the drop falls monotonically towards 0 above the band.
  double lo = f_low, hi = f_low;
  while (dropAt(hi) > max_step_drop) hi *= 2;
  for (int k = 0; k < 60; ++k) {
    const double mid = std::sqrt(lo * hi);
    (dropAt(mid) > max_step_drop ? lo : hi) = mid;
  }
  return hi;
}

MemoryUpdate memoryUpdate(double omega, double h) {
  const double x = omega * h;
  if (x == 0) return {1.0, 0.0, 0.0};
  const double decay = std::exp(-x);
  // 1 - phi and phi - e^{-x} are O(x) differences of O(1) numbers: their Taylor series below
  // x = 1e-3 (truncation x^4/120 relative, 1e-14), the closed form above (cancellation 1e-13).
  if (x < 1e-3) return {decay, x * (0.5 - x * (1.0 / 6 - x * (1.0 / 24 - x / 120))), x * (0.5 - x * (1.0 / 3 - x * (1.0 / 8 - x / 30)))};
  const double phi = -std::expm1(-x) / x;
  return {decay, 1.0 - phi, phi - decay};
}

} // namespace slipwave::physics

// Elastic response spectrum of an acceleration history, accumulated sample by sample: the
// damped oscillator  u'' + 2 zeta omega u' + omega^2 u = -a_g(t),  omega = 2 pi / T,  at rest
// at the first sample, with a_g linear between samples. Each step is the exact solution for
// that linear excitation (Nigam & Jennings, BSSA 59 (1969) 909-922), so the only error is
// the peak missed between samples. The same recursion as scripts/response_spectrum.py, so
// the run's own spectra and the script's agree to round-off on the same samples.
#pragma once
#include <cstddef>
#include <vector>

namespace slipwave::numerics {

// The exact step  [u, v]_{i+1} = A [u, v]_i + B [a_i, a_{i+1}]  (row-major 2 x 2 each) for
// the oscillator above over a step dt with a linear, 0 <= zeta < 1.
struct OscillatorStep {
  double A[4], B[4];
};
OscillatorStep oscillatorStep(double omega, double zeta, double dt);

// Oscillators of several periods driven by one history, with their peak |u|.
class ResponseSpectrum {
public:
  ResponseSpectrum(const std::vector<double> &periods, double zeta);
  // The next sample a at time t (the first one starts the oscillators at rest).
  void add(double t, double a);
  const std::vector<double> &periods() const { return periods_; }
  // PSA(T_k) = omega_k^2 max |u_k| [unit of a].
  double pseudoAcceleration(size_t k) const;
  // max |u_k| [unit of a times s^2].
  double peakDisplacement(size_t k) const { return peak_[k]; }

private:
  std::vector<double>         periods_;
  double                      zeta_;
  std::vector<OscillatorStep> steps_;     // for the step length dt_
  double                      dt_ = -1;
  bool                        started_ = false;
  double                      t_ = 0, a_ = 0; // the last sample
  std::vector<double>         state_;     // u, v per period
  std::vector<double>         peak_;
};

} // namespace slipwave::numerics

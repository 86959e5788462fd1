// Time histories of the incident wave's particle VELOCITY at the base, with the
// displacement / acceleration companions where the input needs them, and the highest
// frequency each one carries (for points-per-wavelength reports).
#pragma once
#include <vector>

namespace slipwave::physics {

// v(t) = A (1 - 2 pi^2 f0^2 tau^2) exp(-pi^2 f0^2 tau^2), tau = t - t0.
struct RickerWavelet {
  double amplitude;  // A, m/s
  double frequency;  // f0, the spectral peak, Hz
  double delay;      // t0, s
};
double velocity(const RickerWavelet &w, double t);
// The antiderivative that vanishes as t -> -inf: A tau exp(-pi^2 f0^2 tau^2).
double displacement(const RickerWavelet &w, double t);
double acceleration(const RickerWavelet &w, double t);
// Frequency above which the amplitude spectrum, |V(f)| ~ (f/f0)^2 exp(-f^2/f0^2), stays
// below 1% of its peak at f0: f = 2.7638 f0 (root of x e^{1-x} = 0.01, x = (f/f0)^2).
double topFrequency(const RickerWavelet &w);
constexpr double kRickerTopFrequencyRatio = 2.763756875702675;

// v(t) = A exp(-(2 pi f0 tau / gamma)^2) cos(2 pi f0 tau + theta), tau = t - t0.
struct GaborWavelet {
  double amplitude;  // A, m/s
  double frequency;  // f0, Hz
  double delay;      // t0, s
  double gamma;      // envelope width in periods (larger: more cycles)
  double phase;      // theta, rad
};
double velocity(const GaborWavelet &w, double t);
double acceleration(const GaborWavelet &w, double t);
// The Gaussian envelope makes the spectrum ~ exp(-gamma^2 (f - f0)^2 / (4 f0^2)) near f0;
// it falls below 1% of its peak at f = f0 (1 + 2 sqrt(ln 100) / gamma).
double topFrequency(const GaborWavelet &w);

// v(t) = A sin(2 pi f0 (t - t0)) from t0 on, 0 before: a steady harmonic force or motion
// switched on at t0 with zero value (the velocity is continuous; its slope jumps to
// 2 pi f0 A, which excites a transient that radiation damping carries away).
struct HarmonicWave {
  double amplitude;  // A
  double frequency;  // f0, Hz
  double delay;      // t0, s
};
double velocity(const HarmonicWave &w, double t);
double acceleration(const HarmonicWave &w, double t);
// The switch-on spreads the line at f0; twice f0 bounds where the spectrum of the first
// few cycles has fallen to a few per cent (for points-per-wavelength reports only).
double topFrequency(const HarmonicWave &w);

// Sampled velocity (e.g. integrated from a ground-motion record), times strictly
// increasing. Linear between samples; zero before the first sample; after the last one
// the velocity holds its last value (the acceleration is zero there, and a jump to zero
// would be an infinite acceleration pulse; baseline-correct the record to end at rest).
struct TabulatedHistory {
  std::vector<double> times;   // s
  std::vector<double> values;  // m/s
};
double velocity(const TabulatedHistory &h, double t);
// Nyquist frequency of the coarsest sampling interval: the highest frequency the samples
// resolve everywhere in the record.
double topFrequency(const TabulatedHistory &h);

} // namespace slipwave::physics

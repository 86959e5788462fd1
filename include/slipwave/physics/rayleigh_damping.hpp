// Rayleigh damping C = alpha M + beta K, fitted to a damping ratio at two frequencies.
#pragma once
#include <string>

namespace slipwave::physics {

struct RayleighCoefficients {
  double alpha;  // mass-proportional, 1/s
  double beta;   // stiffness-proportional, s
};

// Modal damping ratio at frequency f [Hz]: xi(f) = alpha/(4 pi f) + beta pi f.
double rayleighDampingRatio(const RayleighCoefficients &c, double f);

// alpha, beta with xi(f1) = xi(f2) = xi; with w = 2 pi f:
// alpha = 2 xi w1 w2 / (w1 + w2), beta = 2 xi / (w1 + w2). Between f1 and f2 the ratio
// is below xi, outside above it.
RayleighCoefficients rayleighFromDampingRatio(double xi, double f1, double f2);

// "" when 0 <= xi < 1 and 0 < f1 < f2 (finite), else a sentence naming the bad value.
std::string rayleighDampingProblem(double xi, double f1, double f2);

} // namespace slipwave::physics

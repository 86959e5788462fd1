#include "slipwave/physics/rayleigh_damping.hpp"

#include <cmath>
#include <cstdio>

namespace slipwave::physics {

double rayleighDampingRatio(const RayleighCoefficients &c, double f) {
  return c.alpha / (4 * M_PI * f) + c.beta * M_PI * f;
}

RayleighCoefficients rayleighFromDampingRatio(double xi, double f1, double f2) {
  const double w1 = 2 * M_PI * f1, w2 = 2 * M_PI * f2;
  return {2 * xi * w1 * w2 / (w1 + w2), 2 * xi / (w1 + w2)};
}

std::string rayleighDampingProblem(double xi, double f1, double f2) {
  char buf[256];
  if (!(xi >= 0 && xi < 1)) {
    std::snprintf(buf, sizeof buf, "damping ratio xi = %g is not allowed; it must satisfy 0 <= xi < 1", xi);
    return buf;
  }
  if (!(f1 > 0 && f2 > f1 && std::isfinite(f2))) {
    std::snprintf(buf, sizeof buf,
                  "damping frequencies f1 = %g Hz, f2 = %g Hz are not allowed; they must satisfy 0 < f1 < f2", f1, f2);
    return buf;
  }
  return "";
}

} // namespace slipwave::physics

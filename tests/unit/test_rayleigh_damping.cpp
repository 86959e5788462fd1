// Rayleigh coefficients against their definition xi(f) = alpha/(4 pi f) + beta pi f.
#include "slipwave/physics/rayleigh_damping.hpp"

#include "unit_check.hpp"

#include <cmath>

using namespace slipwave::physics;

int main() {
  const double xi = 0.05, f1 = 0.5, f2 = 8.0;
  const RayleighCoefficients c = rayleighFromDampingRatio(xi, f1, f2);
  // The definition, written out here independently of rayleighDampingRatio.
  auto ratio = [&c](double f) { return c.alpha / (4 * M_PI * f) + c.beta * M_PI * f; };
  unit::near(ratio(f1), xi, 1e-14, 0, "xi(f1) = xi");
  unit::near(ratio(f2), xi, 1e-14, 0, "xi(f2) = xi");
  unit::near(rayleighDampingRatio(c, 3.0), ratio(3.0), 1e-15, 0, "rayleighDampingRatio is the definition");
  unit::check(ratio(2.0) < xi && ratio(0.2) > xi && ratio(20.0) > xi, "below xi between f1 and f2, above outside");
  // Minimum at f = sqrt(f1 f2) = 2 (d xi/df = 0), where xi_min = 2 xi sqrt(f1 f2)/(f1 + f2) = 0.2/8.5.
  unit::near(ratio(2.0), 2 * xi * 2.0 / (f1 + f2), 1e-14, 0, "minimum ratio at sqrt(f1 f2)");
  unit::check(rayleighDampingProblem(xi, f1, f2).empty(), "valid input");
  unit::check(!rayleighDampingProblem(xi, f2, f1).empty(), "f1 > f2 rejected");
  unit::check(!rayleighDampingProblem(xi, 0, f2).empty(), "f1 = 0 rejected");
  unit::check(!rayleighDampingProblem(-0.01, f1, f2).empty(), "negative xi rejected");
  return unit::failures();
}

// Parameter ranges of spec section 3: each bad value is reported with the parameter's name,
// its value in input units and the allowed range.
#include "slipwave/physics/interface_params_check.hpp"

#include "unit_check.hpp"

#include <cmath>
#include <string>

using namespace slipwave::physics;

namespace {

constexpr double kDeg = M_PI / 180.0;

InterfaceParams good() {
  InterfaceParams p;
  p.E = 1e8;
  p.G = 5e7;
  p.phi = 30 * kDeg;
  p.psi = 10 * kDeg;
  p.c = 2e3;
  p.e_ini = 1e-3;
  p.tensile_strength = 1e3;
  return p;
}

void expectIssue(const InterfaceParams &p, const char *name, double value, const char *range_part, const std::string &what) {
  const auto issue = interfaceParamsCheck(p);
  const bool ok = issue && std::string(issue->name) == name && (std::isnan(value) ? std::isnan(issue->value) : std::fabs(issue->value - value) <= 1e-9 * (1 + std::fabs(value))) &&
                  issue->allowed.find(range_part) != std::string::npos;
  unit::report(ok, what, issue ? "(got " + std::string(issue->name) + " = " + std::to_string(issue->value) + "; " + issue->allowed + ")"
                               : "(accepted)");
}

} // namespace

int main() {
  unit::check(!interfaceParamsCheck(good()), "valid parameters accepted");
  InterfaceParams p = good();
  p.psi = p.phi;
  unit::check(!interfaceParamsCheck(p), "associated flow psi = phi accepted");
  p = good();
  p.tensile_strength = p.c / std::tan(p.phi);
  unit::check(!interfaceParamsCheck(p), "tensile strength at the apex c / tan(phi) accepted");

  p = good();
  p.E = -1.0;
  expectIssue(p, "E", -1.0, "E > 0", "negative E rejected");
  p = good();
  p.G = 0.0;
  expectIssue(p, "G", 0.0, "G > 0", "zero G rejected");
  p = good();
  p.phi = 90 * kDeg;
  expectIssue(p, "phi", 90.0, "0 <= phi < 90", "phi = 90 deg rejected, in degrees");
  p = good();
  p.psi = 35 * kDeg;
  expectIssue(p, "psi", 35.0, "psi <= phi = 30 deg", "psi > phi rejected, naming phi's value");
  p = good();
  p.psi = -1 * kDeg;
  expectIssue(p, "psi", -1.0, "0 <= psi", "negative psi rejected");
  p = good();
  p.c = -5.0;
  expectIssue(p, "c", -5.0, "c >= 0", "negative cohesion rejected");
  p = good();
  p.e_ini = -1e-3;
  expectIssue(p, "e_ini", -1e-3, "e_ini >= 0", "negative thickness rejected");
  p = good();
  p.tensile_strength = 4e3; // c / tan(30 deg) = 3464.1 Pa
  expectIssue(p, "tensile_strength", 4e3, "c / tan(phi) = 3464.1", "tensile strength beyond the apex rejected");
  p = good();
  p.E = NAN;
  expectIssue(p, "E", NAN, "E > 0", "NaN stiffness rejected");

  const auto s0 = interfaceInitialStressCheck(good(), 2e3);
  unit::check(s0 && std::string(s0->name) == "sigma_N0" && s0->allowed.find("tensile_strength = 1000") != std::string::npos,
              "initial tension beyond the cut-off rejected");
  unit::check(!interfaceInitialStressCheck(good(), -1e5), "initial compression accepted");
  return unit::failures();
}

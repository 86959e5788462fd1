// Elastic material conversions and validation messages.
#include "slipwave/physics/elastic_material.hpp"

#include "unit_check.hpp"

#include <cmath>

using namespace slipwave::physics;

int main() {
  // rho = 2000, vs = 200, vp = 400: mu = 2000*200^2 = 8e7, lambda = 2000*400^2 - 2 mu = 1.6e8,
  // nu = (vp^2 - 2vs^2) / (2 (vp^2 - vs^2)) = 8e4 / 2.4e5 = 1/3, E = 2 mu (1 + nu) = 2.1333e8.
  const ElasticMaterial m{2000, 400, 200};
  const auto l = lame(m);
  unit::near(l.mu, 8e7, 1e-15, 0, "mu = rho vs^2");
  unit::near(l.lambda, 1.6e8, 1e-15, 0, "lambda = rho vp^2 - 2 mu");
  unit::near(poissonRatio(m), 1.0 / 3.0, 1e-15, 0, "nu = 1/3 for vp = 2 vs");
  unit::near(youngModulus(m), 2 * 8e7 * (4.0 / 3.0), 1e-14, 0, "E = 2 mu (1 + nu)");
  unit::near(pWaveModulus(m), 2000.0 * 400 * 400, 1e-15, 0, "M = rho vp^2");
  // Round trip through (E, nu).
  const ElasticMaterial back = fromYoungPoisson(youngModulus(m), poissonRatio(m), m.rho);
  unit::near(back.vp, 400, 1e-14, 0, "fromYoungPoisson recovers vp");
  unit::near(back.vs, 200, 1e-14, 0, "fromYoungPoisson recovers vs");
  unit::near(back.rho, 2000, 0, 0, "fromYoungPoisson keeps rho");
  // nu = 0: lambda = 0, so vp = sqrt(2) vs exactly (the validation boundary).
  const ElasticMaterial zero_nu = fromYoungPoisson(1e8, 0.0, 1000);
  unit::near(zero_nu.vp / zero_nu.vs, std::sqrt(2.0), 1e-15, 0, "nu = 0 gives vp = sqrt(2) vs");

  unit::check(elasticMaterialProblem(m).empty(), "valid material has no problem");
  unit::check(elasticMaterialProblem(zero_nu).empty(), "vp = sqrt(2) vs (nu = 0) is allowed");
  const std::string rho_bad = elasticMaterialProblem({-1, 400, 200});
  unit::check(rho_bad.find("rho = -1") != std::string::npos && rho_bad.find("> 0") != std::string::npos,
              "negative density named with its value and the rule: " + rho_bad);
  const std::string vs_bad = elasticMaterialProblem({2000, 400, 0});
  unit::check(vs_bad.find("vs = 0") != std::string::npos, "zero vs named: " + vs_bad);
  const std::string vp_bad = elasticMaterialProblem({2000, 250, 200});
  unit::check(vp_bad.find("vp = 250") != std::string::npos && vp_bad.find("282.8") != std::string::npos,
              "vp < sqrt(2) vs named with the bound 282.8: " + vp_bad);
  unit::check(!elasticMaterialProblem({2000, NAN, 200}).empty(), "NaN vp rejected");
  unit::check(!elasticMaterialProblem({NAN, 400, 200}).empty(), "NaN rho rejected");

  unit::check(youngPoissonProblem(1e8, 0.25, 1800).empty(), "valid (E, nu)");
  unit::check(youngPoissonProblem(1e8, 0.5, 1800).find("nu = 0.5") != std::string::npos, "nu = 0.5 rejected");
  unit::check(youngPoissonProblem(1e8, -0.1, 1800).find("nu = -0.1") != std::string::npos, "nu < 0 rejected");
  unit::check(youngPoissonProblem(0, 0.3, 1800).find("E = 0") != std::string::npos, "E = 0 rejected");
  unit::check(youngPoissonProblem(1e8, 0.3, 0).find("rho = 0") != std::string::npos, "rho = 0 rejected");
  return unit::failures();
}

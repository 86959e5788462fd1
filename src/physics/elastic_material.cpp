#include "slipwave/physics/elastic_material.hpp"

#include "slipwave/physics/message_format.hpp"

#include <cmath>
#include <cstdio>

namespace slipwave::physics {
namespace {

// Every test below is written so that NaN fails it.
std::string densityProblem(double rho) {
  if (rho > 0 && std::isfinite(rho)) return "";
  return formatMessage("density rho = %g kg/m^3 is not allowed; it must be a finite number > 0", rho);
}

} // namespace

LameParameters lame(const ElasticMaterial &m) {
  const double mu = m.rho * m.vs * m.vs;
  return {m.rho * m.vp * m.vp - 2 * mu, mu};
}

ElasticMaterial fromYoungPoisson(double young, double poisson, double rho) {
  const double mu = young / (2 * (1 + poisson));
  const double lambda = young * poisson / ((1 + poisson) * (1 - 2 * poisson));
  return {rho, std::sqrt((lambda + 2 * mu) / rho), std::sqrt(mu / rho)};
}

double youngModulus(const ElasticMaterial &m) {
  const LameParameters l = lame(m);
  return l.mu * (3 * l.lambda + 2 * l.mu) / (l.lambda + l.mu);
}

double poissonRatio(const ElasticMaterial &m) {
  const double p2 = m.vp * m.vp, s2 = m.vs * m.vs;
  return (p2 - 2 * s2) / (2 * (p2 - s2));
}

double pWaveModulus(const ElasticMaterial &m) { return m.rho * m.vp * m.vp; }

std::string elasticMaterialProblem(const ElasticMaterial &m) {
  if (std::string p = densityProblem(m.rho); !p.empty()) return p;
  if (!(m.vs > 0 && std::isfinite(m.vs)))
    return formatMessage("S-wave speed vs = %g m/s is not allowed; it must be a finite number > 0", m.vs);
  if (!(m.vp >= std::sqrt(2.0) * m.vs && std::isfinite(m.vp)))
    return formatMessage("P-wave speed vp = %g m/s is not allowed with vs = %g m/s; it must be finite and at least "
                  "sqrt(2)*vs = %g m/s (Poisson's ratio >= 0)",
                  m.vp, m.vs, std::sqrt(2.0) * m.vs);
  return "";
}

std::string youngPoissonProblem(double young, double poisson, double rho) {
  if (std::string p = densityProblem(rho); !p.empty()) return p;
  if (!(young > 0 && std::isfinite(young)))
    return formatMessage("Young's modulus E = %g Pa is not allowed; it must be a finite number > 0", young);
  if (!(poisson >= 0 && poisson < 0.5))
    return formatMessage("Poisson's ratio nu = %g is not allowed; it must satisfy 0 <= nu < 0.5", poisson);
  return "";
}

} // namespace slipwave::physics

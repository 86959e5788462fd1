// Isotropic linear elastic material as the input files give it (density and wave speeds),
// with the conversions the kernels and reports need.
#pragma once
#include <string>

namespace slipwave::physics {

// What the stiffness of an isotropic material is made of: lambda and mu in Pa.
struct LameParameters {
  double lambda;
  double mu;
};

struct ElasticMaterial {
  double rho;  // kg/m^3
  double vp;   // m/s
  double vs;   // m/s
};

// mu = rho vs^2, lambda = rho vp^2 - 2 mu.
LameParameters lame(const ElasticMaterial &m);
ElasticMaterial fromYoungPoisson(double young, double poisson, double rho);
double youngModulus(const ElasticMaterial &m);
double poissonRatio(const ElasticMaterial &m);
double pWaveModulus(const ElasticMaterial &m);  // lambda + 2 mu = rho vp^2

// "" when valid, else one sentence naming the quantity, its value and what is allowed;
// the caller prefixes the option name. Requires rho > 0, vs > 0 and vp >= sqrt(2) vs
// (Poisson's ratio >= 0); nu < 0.5 follows from a finite vp.
std::string elasticMaterialProblem(const ElasticMaterial &m);
// The same for the (E, nu) form: E > 0, 0 <= nu < 0.5 (and rho > 0).
std::string youngPoissonProblem(double young, double poisson, double rho);

} // namespace slipwave::physics

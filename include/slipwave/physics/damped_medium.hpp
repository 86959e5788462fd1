// The complex density and Lame moduli of a damped isotropic medium at one angular frequency,
// time dependence e^{i w t}, as slipwave's discrete model damps it: the frequency-domain form
// of the plane-wave free field in a damped site (physics/plane_wave_layered.hpp).
//
// - Constant Q (physics/constant_q.hpp): the generalized Maxwell body acts on the whole
//   element force with one set of weights for P and S, so both Lame moduli take the same
//   complex factor: (lambda*, mu*) = f_U (lambda, mu) M(w)/M_U, where (lambda, mu) come from the
//   given speeds (at the reference frequency) and f_U = M_U / (rho c(f_r)^2) is the factor the
//   solver puts on its element moduli. The density stays real.
// - Rayleigh damping C = alpha M + beta K: M u'' + C u' + K u = 0 becomes
//   [-w^2 M + i w alpha M + (1 + i w beta) K] u = 0, i.e. -w^2 rho* + K* with
//     rho* = rho (1 - i alpha / w)        (the mass-proportional term as a complex density),
//     (lambda*, mu*) = (1 + i w beta) (lambda, mu).
//   The traction uses the moduli only, so rho* enters the wave speeds and not the interface
//   conditions: exactly the drag alpha rho u' of the lumped mass. At w = 0 rho* is singular;
//   there (the velocity's mean, which the free field's wavelets and corrected records do not
//   carry) the mass-proportional term is left out.
// Both damping kinds may act together (the solver allows it): the factors multiply.
#pragma once
#include <complex>

#include "slipwave/physics/constant_q.hpp"
#include "slipwave/physics/elastic_material.hpp"
#include "slipwave/physics/rayleigh_damping.hpp"

namespace slipwave::physics {

struct MediumDamping {
  RayleighCoefficients rayleigh{0, 0};
  ConstantQModel       constant_q;            // no mechanisms: no constant-Q damping
  double               unrelaxed_factor = 1;  // f_U of the constant-Q body
};

struct DampedMedium {
  std::complex<double> rho, lambda, mu;
  std::complex<double> vp() const { return std::sqrt((lambda + 2.0 * mu) / rho); }
  std::complex<double> vs() const { return std::sqrt(mu / rho); }
};

// The medium at angular frequency w >= 0 [rad/s].
DampedMedium dampedMedium(const ElasticMaterial &m, const MediumDamping &d, double w);

} // namespace slipwave::physics

// Backbone curves of cyclic soil behaviour: the shear stress tau(gamma) on first loading in
// simple shear, written as the secant modulus reduction G/Gmax(gamma) so that a backbone
// holds no stress unit (tau = Gmax gamma G/Gmax). gamma is the engineering shear strain
// (2 eps_xy), a plain ratio, never in percent. docs/hysteretic-soil.md gives the sources.
//
// - MKZ, modified hyperbolic (Matasovic & Vucetic 1993):
//     G/Gmax = 1 / (1 + beta (gamma/gamma_r)^s);  beta = s = 1 is Hardin & Drnevich's hyperbola.
// - Darendeli (2001): MKZ with beta = 1, s = a = phi5 and gamma_r from PI, OCR and the mean
//   effective stress (darendeli* below), the same curve his eq. 9.1 gives.
// - GQ/H, general quadratic/hyperbolic (Groholski et al. 2016), with the strength tau_max built
//   in: with x = gamma/gamma_r and gamma_r = tau_max/Gmax,
//     tau/tau_max = [1 + x - sqrt((1 + x)^2 - 4 theta x)] / (2 theta),
//     theta = theta1 + theta2 theta4 x^theta5 / (theta3^theta5 + theta4 x^theta5)  (at most 1).
// - A user table of G/Gmax against gamma, linear in (ln gamma, ln G/Gmax) between rows (a
//   power law), the first row's value below it, and the last row's stress (not its ratio)
//   beyond it.
// Any of them may carry a strength cap tau <= tau_max, as cap_strain = tau_max / Gmax (the
// undrained strength of a clay, or the drained one from phi' and the geostatic stress).
#pragma once
#include <vector>

namespace slipwave::physics {

enum class BackboneKind { Mkz, Gqh, Table };

struct SoilBackbone {
  BackboneKind        kind = BackboneKind::Mkz;
  double              reference_strain = 0; // MKZ: gamma_r; GQ/H: tau_max / Gmax
  double              curvature = 1;        // MKZ: s
  double              beta = 1;             // MKZ: beta
  double              theta[5] = {0, 0, 1, 1, 1}; // GQ/H: theta1 .. theta5
  double              cap_strain = 0;       // tau_max / Gmax of the strength cap; 0: no cap
  std::vector<double> table_strain, table_ratio; // Table: rows (gamma, G/Gmax), gamma ascending
};

// Constructors; they throw std::invalid_argument with the rule broken.
// gamma_r > 0, s > 0, beta > 0; cap_strain >= 0.
SoilBackbone mkzBackbone(double reference_strain, double curvature = 1, double beta = 1, double cap_strain = 0);
// tau_max > 0, Gmax > 0, theta3 > 0, theta4 >= 0, theta5 > 0; theta as published (theta1 may be < 0).
SoilBackbone gqhBackbone(double shear_modulus, double strength, const double theta[5]);
// At least 2 rows; strains > 0 and strictly increasing; ratios in (0, 1].
SoilBackbone tableBackbone(std::vector<double> strain, std::vector<double> ratio, double cap_strain = 0);

// G/Gmax at engineering shear strain gamma >= 0 (1 at gamma = 0).
double modulusReduction(const SoilBackbone &b, double gamma);
// tau(gamma) = Gmax gamma G/Gmax.
inline double backboneStress(const SoilBackbone &b, double shear_modulus, double gamma) { return shear_modulus * gamma * modulusReduction(b, gamma); }

// Damping ratio of the closed Masing loop of amplitude gamma_a on the continuous backbone F:
// unloading and reloading follow tau_a -+ 2 F((gamma_a -+ gamma)/2), so the loop's area is
// 8 int_0^gamma_a F - 4 tau_a gamma_a and, over 4 pi times the secant energy tau_a gamma_a/2,
//   xi = (2/pi) (2 int_0^gamma_a F dgamma / (gamma_a F(gamma_a)) - 1).
// The integral by Gauss-Legendre on log-spaced panels (relative error ~1e-12 on the smooth
// curves; the table's kinks are put on panel ends).
double masingDampingRatio(const SoilBackbone &b, double gamma_a);

// Darendeli (2001), the final model of his ch. 8 with the coefficients phi1 .. phi12 of his
// fit over all soils (the numbers DEEPSOIL and MASTODON use too). He writes strains and damping in percent; these take and
// return ratios. mean_effective_stress in Pa (he uses atm: 101325 Pa).
struct DarendeliSoil {
  double plasticity_index = 0;       // PI [%]
  double ocr = 1;                    // overconsolidation ratio [-]
  double mean_effective_stress = 101325; // sigma'_0 [Pa]
  double frequency = 1;              // loading frequency [Hz] (enters D_min only)
  double cycles = 10;                // number of loading cycles N (enters b only)
};
// gamma_r = (phi1 + phi2 PI OCR^phi3) (sigma'_0/p_a)^phi4 percent, returned as a ratio.
double darendeliReferenceStrain(const DarendeliSoil &s);
// The strain scale of Darendeli's curve at sigma'_0 against the curve at reference_stress:
// gamma_r grows as sigma'_0^phi4 and nothing else in G/Gmax moves, so G/Gmax(gamma; sigma'_0)
// = G/Gmax(gamma / scale; reference) and the backbone tau(gamma) = scale tau_ref(gamma /
// scale) (a point's Iwan model is the reference one in strains divided by the scale).
double darendeliStrainScale(double mean_effective_stress, double reference_stress);
// a = phi5.
double darendeliCurvature();
// G/Gmax = 1 / (1 + (gamma/gamma_r)^a).
double darendeliModulusReduction(const DarendeliSoil &s, double gamma);
// D_min = (phi6 + phi7 PI OCR^phi8) (sigma'_0/p_a)^phi9 (1 + phi10 ln f) percent, as a ratio.
double darendeliMinimumDamping(const DarendeliSoil &s);
// Masing damping of his backbone: his closed form for a = 1 corrected to a by the polynomial
// c1 D + c2 D^2 + c3 D^3 (percent inside), as a ratio.
double darendeliMasingDamping(double reference_strain, double curvature, double gamma);
// D = b (G/Gmax)^0.1 D_Masing + D_min, b = phi11 + phi12 ln N, as a ratio.
double darendeliDamping(const DarendeliSoil &s, double gamma);
// His modulus-reduction curve as an MKZ backbone (beta = 1, s = a), with an optional cap.
SoilBackbone darendeliBackbone(const DarendeliSoil &s, double cap_strain = 0);

} // namespace slipwave::physics

// Biot poroelasticity of a saturated region, as the u-p equations need it: the Biot
// coefficient and modulus from porosity and bulk moduli, the undrained moduli, Skempton's B
// and the 1D loading efficiency, the wave speeds, the consolidation coefficient, and the
// explicit diffusion limit of one pressure row. Plain doubles, no PETSc.
//
// Conventions (docs/saturated-soil.md): stress tension positive, pore pressure p positive in
// compression, total stress sigma = sigma' - alpha p I. K_drained, G: the skeleton's drained
// bulk and shear moduli [Pa]. Mobility kappa = k_h / (rho_f g) [m^2/(Pa s)] from the hydraulic
// conductivity k_h [m/s] (permeability over viscosity, the coefficient of grad p in Darcy).
#pragma once
#include <string>

namespace slipwave::physics {

struct BiotMaterial {
  double porosity;             // n [-], 0 < n < 1
  double fluid_bulk_modulus;   // K_f [Pa], > 0
  double grain_bulk_modulus;   // K_s [Pa], > K_drained; 0: incompressible grains (alpha = 1)
  double hydraulic_conductivity; // k_h [m/s], >= 0 (0: undrained)
  double fluid_density;        // rho_f [kg/m^3], > 0
  double gravity;              // g [m/s^2] that turns k_h into a mobility, > 0
};

// alpha = 1 - K_drained / K_s (1 for incompressible grains).
double biotCoefficient(const BiotMaterial &b, double K_drained);
// 1/M = n/K_f + (alpha - n)/K_s (Biot 1941; Wang 2000 eq. 2.45 form; K_s = 0: n/K_f).
double biotModulus(const BiotMaterial &b, double K_drained);
// kappa = k_h / (rho_f g) [m^2/(Pa s)].
double mobility(const BiotMaterial &b);
// K_u = K + alpha^2 M.
double undrainedBulkModulus(double K_drained, double alpha, double M);
// B = alpha M / K_u: pore pressure per unit isotropic compressive stress, undrained.
double skemptonB(double K_drained, double alpha, double M);
// gamma = alpha M / (K + 4G/3 + alpha^2 M): pore pressure per unit compressive stress under
// undrained uniaxial strain (the 1D column, the P wave) (Wang 2000, "loading efficiency").
double loadingEfficiency(double K_drained, double G, double alpha, double M);
// sqrt((K + 4G/3 + alpha^2 M)/rho): the P speed with the fluid locked in the pores.
double undrainedPWaveSpeed(double K_drained, double G, double alpha, double M, double rho);
// The excess pore pressure of an undrained plane wave (no change of fluid content:
// p = -alpha M eps_v) from two quantities continuous across horizontal interfaces: the total
// normal stress on a horizontal plane sigma_zz [Pa, tension positive] and the normal strain
// along the direction of travel eps_xx (the transverse strain of a plane wave is zero).
// With lambda_u = lambda + alpha^2 M, sigma_zz = lambda_u (eps_xx + eps_zz) + 2 mu eps_zz gives
// eps_zz, so each medium at an interface gets its own eps_v (the DRM's free field,
// docs/drm.md "Saturated sites").
double undrainedPlaneWavePressure(double sigma_zz, double eps_xx, double lambda_undrained, double mu, double alpha, double M);
// c_v = kappa / (1/M + alpha^2/(K + 4G/3)): the 1D (oedometric) consolidation coefficient.
double consolidationCoefficient(double K_drained, double G, double alpha, double M, double kappa);
// Forward Euler on s dp/dt = -sum_j H_ij p_j is stable (Gershgorin on s^{-1} H, whose
// eigenvalues are real and >= 0) for h <= 2 s / sum_j |H_ij|. Returns that bound, 1e300
// when the row has no diffusion.
double explicitDiffusionStepOfRow(double storage, double diffusion_row_abs_sum);
// Forward-Euler diffusion sub-steps in a step of size h: enough that each takes at most the
// bulk's default fraction (0.9) of the limit dt_diffusion; 1 without sub-cycling (the step is
// then within the limit) or for h = 0. The main mesh and the free-field columns share it, so
// they split a step alike.
int diffusionSubsteps(double h, double dt_diffusion, bool subcycle);

// "" when valid, else one sentence naming the quantity, its value and what is allowed.
std::string biotMaterialProblem(const BiotMaterial &b, double K_drained);

} // namespace slipwave::physics

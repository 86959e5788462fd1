// Biot kernels: closed forms from their definitions (Wang 2000, "Theory of Linear
// Poroelasticity", ch. 2-3), limits (incompressible constituents: alpha = 1, B = 1),
// and the poro element matrices: Q u of a uniform dilatation integrates div u, Q^T of a
// uniform p is the boundary force p n of the cell, H has constants in its null space and
// gives integral |grad p|^2 for a linear p.
#include "slipwave/fem/element_kernels.hpp"
#include "slipwave/physics/biot.hpp"

#include "unit_check.hpp"

#include <cmath>
#include <string>
#include <vector>

using namespace slipwave::physics;
using namespace slipwave::fem;
using namespace slipwave::numerics;

int main() {
  // A sandstone-like rock: K = 8 GPa, K_s = 36 GPa, K_f = 3.3 GPa, n = 0.19.
  const BiotMaterial berea{0.19, 3.3e9, 36e9, 1e-6, 1000, 9.81};
  const double       K = 8e9;
  const double       alpha = biotCoefficient(berea, K);
  unit::near(alpha, 1 - 8.0 / 36.0, 1e-15, 0, "alpha = 1 - K/K_s");
  const double M = biotModulus(berea, K);
  unit::near(1 / M, 0.19 / 3.3e9 + (alpha - 0.19) / 36e9, 1e-14, 0, "1/M = n/K_f + (alpha - n)/K_s");
  unit::near(undrainedBulkModulus(K, alpha, M), K + alpha * alpha * M, 1e-15, 0, "K_u = K + alpha^2 M");
  // B from the independent Gassmann-Skempton form (Wang 2000 eq. 3.18 with Gassmann's K_u) B = (1/K - 1/K_s) / (1/K - 1/K_s + n (1/K_f - 1/K_s)).
  const double B_gassmann = (1 / K - 1 / 36e9) / (1 / K - 1 / 36e9 + 0.19 * (1 / 3.3e9 - 1 / 36e9));
  unit::near(skemptonB(K, alpha, M), B_gassmann, 1e-12, 0, "B equals the Gassmann-Skempton form");

  // Incompressible grains: alpha = 1, M = K_f/n; incompressible fluid too (K_f -> inf): B -> 1.
  const BiotMaterial soil{0.4, 2.2e9, 0, 1e-4, 1000, 9.81};
  unit::near(biotCoefficient(soil, 5e7), 1.0, 0, 0, "K_s = 0: alpha = 1");
  unit::near(biotModulus(soil, 5e7), 2.2e9 / 0.4, 1e-15, 0, "K_s = 0: M = K_f / n");
  unit::near(skemptonB(5e7, 1, 1e16), 1.0, 1e-8, 0, "stiff fluid: B -> 1");
  // Loading efficiency: gamma = alpha M / (K + 4G/3 + alpha^2 M); in 1D undrained loading the
  // strain is eps = -sigma/(K + 4G/3 + alpha^2 M) and p = -alpha M eps.
  const double Gs = 3e7, Ks = 5e7, Ms = biotModulus(soil, Ks), sigma = 1e5;
  const double eps = -sigma / (Ks + 4 * Gs / 3 + Ms);
  unit::near(loadingEfficiency(Ks, Gs, 1, Ms) * sigma, -Ms * eps, 1e-14, 0, "loading efficiency: p = gamma sigma in undrained uniaxial strain");
  // The plane wave's undrained pressure: at vertical incidence (eps_xx = 0) p = gamma sigma_zz
  // with the compression positive; an inclined wave's strain state (eps_xx, eps_zz) taken
  // through Hooke's law with lambda_u gives sigma_zz, and the kernel returns -alpha M eps_v.
  const double lambda_u = Ks - 2 * Gs / 3 + Ms;
  unit::near(undrainedPlaneWavePressure(-sigma, 0, lambda_u, Gs, 1, Ms), loadingEfficiency(Ks, Gs, 1, Ms) * sigma, 1e-14, 0,
             "undrained plane-wave pressure: gamma times the vertical compression at eps_xx = 0");
  const double exx = 2e-5, ezz = -7e-5, szz = lambda_u * (exx + ezz) + 2 * Gs * ezz;
  unit::near(undrainedPlaneWavePressure(szz, exx, lambda_u, Gs, 0.8, Ms), -0.8 * Ms * (exx + ezz), 1e-12, 0,
             "undrained plane-wave pressure: -alpha M (eps_xx + eps_zz) from sigma_zz and eps_xx");
  unit::near(undrainedPWaveSpeed(Ks, Gs, 1, Ms, 2000), std::sqrt((Ks + 4 * Gs / 3 + Ms) / 2000), 1e-15, 0, "undrained P speed");
  unit::near(mobility(soil), 1e-4 / (1000 * 9.81), 1e-15, 0, "mobility k_h / (rho_f g)");
  // c_v = k E_oed / gamma_w when fluid and grains are incompressible (Terzaghi).
  unit::near(consolidationCoefficient(Ks, Gs, 1, 1e30, mobility(soil)), 1e-4 * (Ks + 4 * Gs / 3) / (1000 * 9.81), 1e-12, 0,
             "c_v -> k_h E_oed / gamma_w for incompressible constituents");
  unit::near(explicitDiffusionStepOfRow(2.0, 8.0), 0.5, 1e-15, 0, "diffusion row bound 2 s / sum |H|");
  unit::check(explicitDiffusionStepOfRow(2.0, 0.0) > 1e299, "no diffusion: no bound");
  // The explicit recurrence s (p+ - p)/h = -H p on two nodes joined by one link (H = [1 -1; -1 1]
  // c): the row bound is h = 2 s/(2c) = s/c, the exact limit of the mode (1,-1) is 2/(2c/s) too.
  {
    const double s = 1.5, c = 3.0, h = explicitDiffusionStepOfRow(s, 2 * c);
    auto         grow = [&](double step) {
      double p0 = 1, p1 = -1;
      for (int k = 0; k < 2000; ++k) {
        const double r0 = c * (p0 - p1), r1 = c * (p1 - p0);
        p0 -= step / s * r0;
        p1 -= step / s * r1;
      }
      return std::fabs(p0);
    };
    unit::check(grow(0.99 * h) < 1, "two-node diffusion decays just below the row bound");
    unit::check(grow(1.01 * h) > 1e3, "two-node diffusion grows just above the row bound");
  }
  unit::check(biotMaterialProblem(soil, 5e7).empty(), "valid material accepted");
  unit::check(!biotMaterialProblem(BiotMaterial{1.2, 2.2e9, 0, 1e-4, 1000, 9.81}, 5e7).empty(), "porosity 1.2 refused");
  unit::check(!biotMaterialProblem(BiotMaterial{0.4, 2.2e9, 1e7, 1e-4, 1000, 9.81}, 5e7).empty(), "K_s below K refused");

  // Element matrices on distorted cells.
  struct Cell {
    CellShape           shape;
    const char         *name;
    std::vector<double> x;
  };
  const std::vector<Cell> cells = {
      {CellShape::Tri3, "Tri3", {0.1, 0.2, 1.3, 0.1, 0.4, 1.1}},
      {CellShape::Quad4, "Quad4", {0.0, 0.0, 2.0, 0.2, 1.8, 1.5, 0.3, 1.2}},
      {CellShape::Tet4, "Tet4", {0.0, 0.0, 0.0, 1.2, 0.1, 0.2, 0.3, 1.1, -0.1, 0.2, 0.3, 0.9}},
      {CellShape::Hex8, "Hex8", {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1}},
  };
  for (const Cell &c : cells) {
    const int n = cellNodeCount(c.shape), dim = cellDimension(c.shape), nd = n * dim;
    std::vector<double> Q(n * nd), H(n * n), mass(n), u(nd);
    elementCoupling(c.shape, c.x.data(), Q.data());
    elementDiffusion(c.shape, c.x.data(), H.data());
    elementLumpedMass(c.shape, c.x.data(), 1.0, mass.data());
    // u = x (div u = dim): sum_a (Q u)_a = dim * volume, and row a is dim * integral N_a.
    for (int k = 0; k < nd; ++k) u[k] = c.x[k];
    double total = 0, worst = 0;
    for (int a = 0; a < n; ++a) {
      double qa = 0;
      for (int k = 0; k < nd; ++k) qa += Q[a * nd + k] * u[k];
      total += qa;
      worst = std::fmax(worst, std::fabs(qa - dim * mass[a]));
    }
    unit::near(total, dim * cellVolume(c.shape, c.x.data()), 1e-13, 0, std::string(c.name) + ": Q u of u = x integrates div u = dim");
    unit::near(worst, 0, 0, 1e-13, std::string(c.name) + ": (Q u)_a = dim integral N_a for a uniform dilatation");
    // Q^T 1: the nodal forces of a uniform pressure sum to zero over the closed cell surface.
    for (int j = 0; j < dim; ++j) {
      double s = 0;
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) s += Q[a * nd + b * dim + j];
      unit::near(s, 0, 0, 1e-13, std::string(c.name) + ": Q^T of a uniform p sums to zero force, component " + std::to_string(j));
    }
    // H: constants in the null space; p = x_0 + 2 x_1 gives p^T H p = |grad p|^2 volume = 5 V.
    double rowsum = 0, energy = 0;
    std::vector<double> p(n);
    for (int a = 0; a < n; ++a) p[a] = c.x[a * dim] + 2 * c.x[a * dim + 1];
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) energy += p[a] * H[a * n + b] * p[b];
    for (int a = 0; a < n; ++a) {
      double s = 0;
      for (int b = 0; b < n; ++b) s += H[a * n + b];
      rowsum = std::fmax(rowsum, std::fabs(s));
    }
    unit::near(rowsum, 0, 0, 1e-13, std::string(c.name) + ": H 1 = 0");
    unit::near(energy, 5 * cellVolume(c.shape, c.x.data()), 1e-12, 0, std::string(c.name) + ": p^T H p = |grad p|^2 V for a linear p");
  }
  return unit::failures();
}

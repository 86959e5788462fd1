#include "slipwave/porous/pore_pressure.hpp"

#include <cmath>
#include <cstdio>

// What a saturated region is: its pore-fluid options, the Biot numbers derived from them, and
// the report lines that state them with what the pore pressure costs in step.
namespace slipwave::porous {
namespace {

// Standard gravity turns a hydraulic conductivity into a mobility; it is a unit conversion
// (k_h is measured under g), not the scene's -gravity.
constexpr double kStandardGravity = 9.80665;

PetscErrorCode readRegion(MPI_Comm comm, medium::RegionMaterialInfo *info, SaturatedRegion *r) {
  PetscBool saturated = PETSC_FALSE, has_porosity = PETSC_FALSE, has_k = PETSC_FALSE;
  PetscReal porosity = 0, K_f = 2.2e9, K_s = 0, k_h = 0, rho_f = 1000;
  const std::string prefix = "material_" + info->region + "_";
  const std::string title  = "Pore fluid of region " + info->region;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, prefix.c_str(), title.c_str(), "slipwave");
  PetscCall(PetscOptionsBool("-saturated", "the region is a saturated porous medium (Biot u-p; -material_<r>_rho is then the mixture density)", "PorePressureReadMaterials",
                             saturated, &saturated, nullptr));
  if (saturated) {
    PetscCall(PetscOptionsReal("-porosity", "porosity n [-], 0 < n < 1 (saturated region, required)", "PorePressureReadMaterials", porosity, &porosity, &has_porosity));
    PetscCall(PetscOptionsReal("-hydraulic_conductivity", "hydraulic conductivity k [m/s], >= 0 (0: undrained; mobility k/(rho_f g), g = 9.80665) (required)",
                               "PorePressureReadMaterials", k_h, &k_h, &has_k));
    PetscCall(PetscOptionsReal("-fluid_bulk_modulus", "bulk modulus of the pore fluid K_f [Pa], > 0 (default water, 2.2e9)", "PorePressureReadMaterials", K_f, &K_f, nullptr));
    PetscCall(PetscOptionsReal("-grain_bulk_modulus", "bulk modulus of the solid grains K_s [Pa], 0 (incompressible, Biot coefficient 1) or > drained K", "PorePressureReadMaterials",
                               K_s, &K_s, nullptr));
    PetscCall(PetscOptionsReal("-fluid_density", "density of the pore fluid rho_f [kg/m^3], > 0 (default 1000)", "PorePressureReadMaterials", rho_f, &rho_f, nullptr));
  }
  PetscOptionsEnd();
  r->saturated = saturated;
  if (!saturated) PetscFunctionReturn(0);
  const char *name = info->region.c_str();
  PetscCheck(has_porosity, comm, PETSC_ERR_USER_INPUT, "-material_%s_porosity is missing; allowed: 0 < n < 1 (region %s is saturated)", name, name);
  PetscCheck(has_k, comm, PETSC_ERR_USER_INPUT, "-material_%s_hydraulic_conductivity is missing; allowed: >= 0 m/s (region %s is saturated)", name, name);
  const physics::LameParameters lame = physics::lame(info->elastic);
  const double                  K    = lame.lambda + 2.0 * lame.mu / 3.0;
  r->biot                            = physics::BiotMaterial{porosity, K_f, K_s, k_h, rho_f, kStandardGravity};
  const std::string problem          = physics::biotMaterialProblem(r->biot, K);
  PetscCheck(problem.empty(), comm, PETSC_ERR_USER_INPUT, "pore fluid of region '%s' (-material_%s_...): %s", name, name, problem.c_str());
  r->alpha           = physics::biotCoefficient(r->biot, K);
  r->M               = physics::biotModulus(r->biot, K);
  r->kappa           = physics::mobility(r->biot);
  info->vp_undrained = physics::undrainedPWaveSpeed(K, lame.mu, r->alpha, r->M, info->elastic.rho);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode PorePressureReadMaterials(MPI_Comm comm, std::vector<medium::RegionMaterialInfo> *materials, std::vector<SaturatedRegion> *regions, bool *any) {
  PetscFunctionBeginUser;
  regions->assign(materials->size(), SaturatedRegion{});
  *any = false;
  for (size_t i = 0; i < materials->size(); ++i) {
    PetscCall(readRegion(comm, &(*materials)[i], &(*regions)[i]));
    *any = *any || (*regions)[i].saturated;
  }
  PetscFunctionReturn(0);
}

std::vector<std::string> PorePressureReport(const PorePressure *pp, const std::vector<medium::RegionMaterialInfo> &materials, double dt_drained, double dt_undrained,
                                            double coupling_factor, double dt_limit, double dt) {
  std::vector<std::string> lines;
  char                     buf[512];
  for (size_t i = 0; i < materials.size(); ++i) {
    const SaturatedRegion &r = pp->regions[i];
    if (!r.saturated) continue;
    const physics::LameParameters lame = physics::lame(materials[i].elastic);
    const double                  K    = lame.lambda + 2.0 * lame.mu / 3.0;
    std::snprintf(buf, sizeof buf,
                  "  saturated %s: alpha %.4g, M %.4g Pa, Skempton B %.4g, loading efficiency %.4g, undrained vp %.1f m/s (drained %.1f), k %.3g m/s = mobility %.3g m^2/(Pa s), c_v %.4g m^2/s",
                  materials[i].region.c_str(), r.alpha, r.M, physics::skemptonB(K, r.alpha, r.M), physics::loadingEfficiency(K, lame.mu, r.alpha, r.M),
                  materials[i].vp_undrained, materials[i].elastic.vp, r.biot.hydraulic_conductivity, r.kappa,
                  physics::consolidationCoefficient(K, lame.mu, r.alpha, r.M, r.kappa));
    lines.push_back(buf);
  }
  auto names = [](const std::vector<std::string> &list) {
    std::string s;
    for (const auto &n : list) s += (s.empty() ? "" : ",") + n;
    return s.empty() ? std::string("none") : s;
  };
  std::snprintf(buf, sizeof buf, "  pore fluid boundaries: drained %s; prescribed inflow %s; all others no flow", names(pp->drained).c_str(), names(pp->flux).c_str());
  lines.push_back(buf);
  // Without sub-cycling at degree p > 1 the diffusion also governs where it pulls the wave's
  // bound down (a coupling factor above 2: the diffusion step overshoots, g < 0).
  const bool governs = !pp->subcycle && (pp->dt_diffusion < dt_undrained || coupling_factor > 2);
  std::snprintf(buf, sizeof buf,
                "  pore pressure step cost: drained wave %.4e s, undrained wave %.4e s (%.2fx the drained), diffusion %.4e s; the %s governs (limit %.4e s, %.2fx the drained)",
                dt_drained, dt_undrained, dt_drained / dt_undrained, pp->dt_diffusion, governs ? "diffusion" : "undrained wave", dt_limit, dt_drained / dt_limit);
  lines.push_back(buf);
  if (pp->degree > 1) {
    const double c = PorePressureCouplingFactor(pp, dt);
    std::snprintf(buf, sizeof buf,
                  "  pore pressure at degree %" PetscInt_FMT ": the split step counts the undrained stiffening %.3gx in the wave step at its step %.4e s (K + c alpha^2 Q^T S^-1 Q, "
                  "c = 2/(1 + g), g = %.3g the diffusion's smallest amplification per step; docs/saturated-soil.md)",
                  pp->degree, c, dt, 2 / c - 1);
    lines.push_back(buf);
  }
  const PetscInt substeps = PorePressureSubsteps(pp, dt);
  if (substeps > 1) {
    std::snprintf(buf, sizeof buf, "  pore-pressure diffusion sub-cycled: %" PetscInt_FMT " sub-steps per step (-pore_pressure_subcycle)", substeps);
    lines.push_back(buf);
  }
  if (governs && pp->dt_diffusion < 0.1 * dt_undrained) {
    std::snprintf(buf, sizeof buf,
                  "  warning: the explicit pore-pressure diffusion forces a step %.3gx smaller than the undrained wave's; -pore_pressure_subcycle sub-steps it instead",
                  dt_undrained / pp->dt_diffusion);
    lines.push_back(buf);
  }
  return lines;
}

} // namespace slipwave::porous

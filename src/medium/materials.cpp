#include "slipwave/medium/materials.hpp"

#include <algorithm>
#include <cstring>
#include <sstream>

#include "slipwave/core/option_choice.hpp"

namespace slipwave::medium {
namespace {

// Names X of every -material_X_<property> option given, so a material for a region that does
// not exist gets its own message instead of a generic "unused option".
PetscErrorCode materialNamesGiven(std::vector<std::string> *names) {
  char *all = nullptr;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetAll(nullptr, &all));
  std::stringstream ss(all ? all : "");
  std::string       token;
  // With the pore-fluid properties of saturated regions (porous/pore_pressure.cpp).
  const char       *properties[] = {"_rho", "_vp", "_vs", "_E", "_nu", "_damping_ratio", "_reference_frequency", "_saturated", "_porosity",
                                    "_hydraulic_conductivity", "_fluid_bulk_modulus", "_grain_bulk_modulus", "_fluid_density", "_model"};
  while (ss >> token) {
    if (token.rfind("-material_", 0) != 0) continue;
    std::string rest = token.substr(std::strlen("-material_"));
    for (const char *p : properties) {
      const size_t n = std::strlen(p);
      if (rest.size() > n && rest.compare(rest.size() - n, n, p) == 0) names->push_back(rest.substr(0, rest.size() - n));
    }
  }
  PetscCall(PetscFree(all));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode MaterialsRead(MPI_Comm comm, const std::vector<std::string> &regions, std::vector<RegionMaterialInfo> *materials) {
  PetscFunctionBeginUser;
  std::vector<std::string> given;
  PetscCall(materialNamesGiven(&given));
  for (const std::string &name : given) {
    PetscCheck(std::find(regions.begin(), regions.end(), name) != regions.end(), comm, PETSC_ERR_USER_INPUT,
               "a material is given for '%s' (-material_%s_...), which is not a region; allowed regions (-regions): %s", name.c_str(), name.c_str(),
               [&] {
                 std::string list;
                 for (const auto &r : regions) list += (list.empty() ? "" : ", ") + r;
                 return list;
               }()
                 .c_str());
  }
  materials->clear();
  for (const std::string &region : regions) {
    const std::string prefix = "material_" + region + "_";
    const std::string title  = "Material of region " + region;
    PetscReal         rho = 0, vp = 0, vs = 0, young = 0, nu = 0, damping_ratio = 0, reference_frequency = 0;
    PetscBool         has_rho, has_vp, has_vs, has_e, has_nu, has_reference;
    PetscInt          model = (PetscInt)MaterialModel::Elastic;
    PetscOptionsBegin(comm, prefix.c_str(), title.c_str(), "slipwave");
    PetscCall(PetscOptionsReal("-rho", "mass density [kg/m^3], > 0", "MaterialsRead", rho, &rho, &has_rho));
    PetscCall(PetscOptionsReal("-vp", "P-wave speed [m/s], >= sqrt(2) vs (with -vs)", "MaterialsRead", vp, &vp, &has_vp));
    PetscCall(PetscOptionsReal("-vs", "S-wave speed [m/s], > 0 (with -vp)", "MaterialsRead", vs, &vs, &has_vs));
    PetscCall(PetscOptionsReal("-E", "Young's modulus [Pa], > 0 (with -nu, instead of -vp/-vs)", "MaterialsRead", young, &young, &has_e));
    PetscCall(PetscOptionsReal("-nu", "Poisson's ratio [-], 0 <= nu < 0.5 (with -E)", "MaterialsRead", nu, &nu, &has_nu));
    PetscCall(PetscOptionsReal("-damping_ratio", "constant-Q damping ratio xi [-] of P and S waves, Q = 1/(2 xi) (0 <= xi < 0.5; 0: elastic)", "MaterialsRead",
                               damping_ratio, &damping_ratio, nullptr));

    PetscCall(PetscOptionsReal("-reference_frequency",
                               "frequency [Hz] at which this damped region's vp, vs hold (> 0; default: -attenuation_reference_frequency, or automatic)",
                               "MaterialsRead", reference_frequency, &reference_frequency, &has_reference));
    PetscCall(core::OptionsChoice(PetscOptionsObject, "-model",
                                  "how the region deforms: elastic, or rigid (one rigid body: no internal waves, no step limit of its own; for a structure "
                                  "far stiffer than the soil)",
                                  kMaterialModelNames, 2, &model, nullptr));
    PetscOptionsEnd();
    const char *r = region.c_str();
    PetscCheck(has_rho || has_vp || has_vs || has_e || has_nu, comm, PETSC_ERR_USER_INPUT,
               "region '%s' has no material; allowed: -material_%s_rho with -material_%s_vp and -material_%s_vs, or with -material_%s_E and -material_%s_nu", r, r, r, r,
               r, r);
    PetscCheck(has_rho, comm, PETSC_ERR_USER_INPUT, "-material_%s_rho is missing; allowed: a density > 0 [kg/m^3]", r);
    const bool velocities = has_vp || has_vs, moduli = has_e || has_nu;
    PetscCheck(!(velocities && moduli), comm, PETSC_ERR_USER_INPUT,
               "region '%s' has both wave speeds (-material_%s_vp/_vs) and moduli (-material_%s_E/_nu); allowed: one pair only", r, r, r);
    physics::ElasticMaterial m{rho, vp, vs};
    std::string              problem;
    if (moduli) {
      PetscCheck(has_e && has_nu, comm, PETSC_ERR_USER_INPUT, "-material_%s_%s is missing; allowed: -material_%s_E [Pa] together with -material_%s_nu", r,
                 has_e ? "nu" : "E", r, r);
      problem = physics::youngPoissonProblem(young, nu, rho);
      if (problem.empty()) m = physics::fromYoungPoisson(young, nu, rho);
    } else {
      PetscCheck(has_vp && has_vs, comm, PETSC_ERR_USER_INPUT, "-material_%s_%s is missing; allowed: -material_%s_vp together with -material_%s_vs [m/s]", r,
                 has_vp ? "vs" : "vp", r, r);
      problem = physics::elasticMaterialProblem(m);
    }
    PetscCheck(problem.empty(), comm, PETSC_ERR_USER_INPUT, "material of region '%s' (-material_%s_...): %s", r, r, problem.c_str());
    PetscCheck(damping_ratio >= 0 && damping_ratio < 0.5, comm, PETSC_ERR_USER_INPUT, "-material_%s_damping_ratio = %g; allowed: 0 <= xi < 0.5 (0: elastic)", r,
               (double)damping_ratio);
    PetscCheck(!has_reference || (reference_frequency > 0 && damping_ratio > 0), comm, PETSC_ERR_USER_INPUT,
               "-material_%s_reference_frequency = %g; allowed: > 0 Hz, in a region with -material_%s_damping_ratio > 0", r, (double)reference_frequency, r);
    // A rigid region has no strain: nothing for a damping law to act on.
    PetscCheck(model != (PetscInt)MaterialModel::Rigid || damping_ratio == 0, comm, PETSC_ERR_USER_INPUT,
               "-material_%s_damping_ratio = %g with -material_%s_model rigid; allowed: 0 (a rigid region does not deform)", r, (double)damping_ratio, r);
    RegionMaterialInfo info;
    info.region  = region;
    info.elastic = m;
    info.fe      = fem::RegionMaterial{m.rho, physics::lame(m), model != (PetscInt)MaterialModel::Rigid};
    info.damping_ratio = damping_ratio;
    info.reference_frequency = reference_frequency;
    info.model               = (MaterialModel)model;
    materials->push_back(info);
  }
  PetscFunctionReturn(0);
}

} // namespace slipwave::medium

#include "slipwave/medium/materials.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "slipwave/core/option_choice.hpp"
#include "slipwave/core/warnings.hpp"
#include "slipwave/physics/plausible_values.hpp"
#include "slipwave/medium/backbone_table.hpp"

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
                                    "_hydraulic_conductivity", "_fluid_bulk_modulus", "_grain_bulk_modulus", "_fluid_density", "_model",
                                    // A hysteretic region's backbone (hystereticRead below).
                                    "_backbone", "_backbone_file", "_reference_strain", "_curvature", "_beta", "_strength", "_gqh_theta", "_plasticity_index", "_ocr",
                                    "_mean_effective_stress", "_surfaces", "_stress_points", "_dilatation"};
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

// The backbone options of region r, read in its options block (prefix material_<r>_), and the
// model built from them. Every option is checked here, before the mesh work: one given to a
// region that is not hysteretic, or to a backbone that does not use it, stops the run.
// elastic: the region's small-strain material, or null where it is not valid (its own check
// below stops the run then).
PetscErrorCode hystereticRead(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, const char *r, bool hysteretic, const physics::ElasticMaterial *elastic,
                              HystereticSpec *spec) {
  PetscInt  choice = (PetscInt)BackboneChoice::Mkz, surfaces = physics::HystereticSurfaces{}.count, ntheta = 5, points = (PetscInt)StressPoints::Gauss;
  PetscReal gamma_r = 0, curvature = 1, beta = 1, strength = 0, pi = 0, ocr = 1, mean_stress = 0, theta[5] = {0, 0, 1, 1, 1};
  PetscBool has_choice, has_gamma, has_curvature, has_beta, has_strength, has_pi, has_ocr, has_mean, has_theta, has_surfaces, has_points, has_file;
  char      file[PETSC_MAX_PATH_LEN] = "";
  PetscFunctionBeginUser;
  PetscCall(core::OptionsChoice(PetscOptionsObject, "-backbone",
                                "backbone of a hysteretic region: mkz (Matasovic-Vucetic, from -reference_strain), darendeli (Darendeli 2001, from "
                                "-plasticity_index, -ocr, -mean_effective_stress), gqh (Groholski et al. 2016, from -strength and -gqh_theta) or table (G/Gmax "
                                "against strain from -backbone_file)",
                                kBackboneNames, 4, &choice, &has_choice));
  PetscCall(PetscOptionsString("-backbone_file",
                               "CSV file of a table backbone: a '# source: ...' line, the header strain,G/Gmax or strain_percent,G/Gmax, then the rows "
                               "(docs/hysteretic-soil.md)",
                               "MaterialsRead", file, file, sizeof file, &has_file));
  PetscCall(PetscOptionsReal("-reference_strain", "MKZ reference shear strain gamma_r [-] (a ratio, not percent), > 0", "MaterialsRead", gamma_r, &gamma_r, &has_gamma));
  PetscCall(PetscOptionsReal("-curvature", "MKZ curvature s [-], > 0 (1: hyperbolic)", "MaterialsRead", curvature, &curvature, &has_curvature));
  PetscCall(PetscOptionsReal("-beta", "MKZ coefficient beta [-], > 0 (1: hyperbolic)", "MaterialsRead", beta, &beta, &has_beta));
  PetscCall(PetscOptionsReal("-strength", "shear strength tau_max [Pa], > 0: the cap of an mkz or darendeli backbone (optional), the strength of gqh (required)",
                             "MaterialsRead", strength, &strength, &has_strength));
  PetscCall(PetscOptionsRealArray("-gqh_theta", "GQ/H curve-fitting parameters theta1,...,theta5 [-] as published (theta3, theta5 > 0, theta4 >= 0; default 0,0,1,1,1: "
                                  "the hyperbola)", "MaterialsRead", theta, &ntheta, &has_theta));
  PetscCall(PetscOptionsReal("-plasticity_index", "Darendeli plasticity index PI [%], 0 to 200", "MaterialsRead", pi, &pi, &has_pi));
  PetscCall(PetscOptionsReal("-ocr", "Darendeli overconsolidation ratio OCR [-], 1 to 100", "MaterialsRead", ocr, &ocr, &has_ocr));
  char mean_text[64] = "";
  PetscCall(PetscOptionsString("-mean_effective_stress",
                               "Darendeli mean effective stress sigma'_0 [Pa], > 0, or geostatic (each element's from the geostatic stage, the free-field columns' "
                               "from their weight: -(sigma_xx + sigma_yy + sigma_zz)/3) (required)",
                               "MaterialsRead", mean_text, mean_text, sizeof mean_text, &has_mean));
  const bool mean_geostatic = has_mean && std::strcmp(mean_text, "geostatic") == 0;
  if (has_mean && !mean_geostatic) {
    char *end = nullptr;
    mean_stress = std::strtod(mean_text, &end);
    PetscCheck(end != mean_text && *end == '\0', comm, PETSC_ERR_USER_INPUT, "-material_%s_mean_effective_stress = %s; allowed: sigma'_0 > 0 [Pa] or geostatic", r, mean_text);
  }
  PetscCall(PetscOptionsInt("-surfaces", "number N of Iwan surfaces of a hysteretic region, 2 to 1000 (docs/hysteretic-soil.md: error and cost against N)", "MaterialsRead",
                            surfaces, &surfaces, &has_surfaces));
  PetscCall(core::OptionsChoice(PetscOptionsObject, "-stress_points",
                                "where a hysteretic region's stress is evaluated: gauss (the quadrature points of the linear stiffness: 4 per quadrilateral, 8 "
                                "per hexahedron, the GLL nodes at degree p > 1) or mean (once per cell from its mean strain, the linear part still fully integrated: 4x or 8x fewer updates, exact for a "
                                "uniform strain)",
                                kStressPointNames, 2, &points, &has_points));
  const struct {
    const char *name;
    PetscBool   set;
    bool        used; // by the chosen backbone
  } given[] = {{"backbone", has_choice, true},
               {"reference_strain", has_gamma, choice == (PetscInt)BackboneChoice::Mkz},
               {"curvature", has_curvature, choice == (PetscInt)BackboneChoice::Mkz},
               {"beta", has_beta, choice == (PetscInt)BackboneChoice::Mkz},
               {"strength", has_strength, true},
               {"gqh_theta", has_theta, choice == (PetscInt)BackboneChoice::Gqh},
               {"backbone_file", has_file, choice == (PetscInt)BackboneChoice::Table},
               {"plasticity_index", has_pi, choice == (PetscInt)BackboneChoice::Darendeli},
               {"ocr", has_ocr, choice == (PetscInt)BackboneChoice::Darendeli},
               {"mean_effective_stress", has_mean, choice == (PetscInt)BackboneChoice::Darendeli},
               {"surfaces", has_surfaces, true},
               {"stress_points", has_points, true}};
  for (const auto &g : given) {
    PetscCheck(!g.set || hysteretic, comm, PETSC_ERR_USER_INPUT, "-material_%s_%s is given but region '%s' is not hysteretic; allowed: with -material_%s_model hysteretic", r,
               g.name, r, r);
    PetscCheck(!g.set || g.used, comm, PETSC_ERR_USER_INPUT, "-material_%s_%s does not apply to -material_%s_backbone %s; allowed: %s", r, g.name, r, kBackboneNames[choice],
               choice == (PetscInt)BackboneChoice::Mkz       ? "-reference_strain, -curvature, -beta, -strength, -surfaces, -stress_points"
               : choice == (PetscInt)BackboneChoice::Gqh     ? "-strength, -gqh_theta, -surfaces, -stress_points"
               : choice == (PetscInt)BackboneChoice::Table   ? "-backbone_file, -strength, -surfaces, -stress_points"
                                                              : "-plasticity_index, -ocr, -mean_effective_stress, -strength, -surfaces, -stress_points");
  }
  if (!hysteretic || !elastic) PetscFunctionReturn(0);
  const physics::ElasticMaterial &m = *elastic;
  PetscCheck(has_choice, comm, PETSC_ERR_USER_INPUT, "-material_%s_backbone is missing (region '%s' is hysteretic); allowed: mkz, darendeli, gqh, table", r, r);
  PetscCheck(!has_theta || ntheta == 5, comm, PETSC_ERR_USER_INPUT, "-material_%s_gqh_theta has %" PetscInt_FMT " values; allowed: five, theta1,...,theta5", r, ntheta);
  PetscCheck(!has_strength || (strength > 0 && std::isfinite(strength)), comm, PETSC_ERR_USER_INPUT, "-material_%s_strength = %g; allowed: tau_max > 0 [Pa]", r, (double)strength);
  PetscCheck(surfaces >= 2 && surfaces <= 1000, comm, PETSC_ERR_USER_INPUT, "-material_%s_surfaces = %" PetscInt_FMT "; allowed: 2 to 1000", r, surfaces);
  const double gmax = m.rho * m.vs * m.vs, bulk = m.rho * (m.vp * m.vp - 4.0 / 3.0 * m.vs * m.vs);
  spec->choice      = (BackboneChoice)choice;
  spec->strength    = strength;
  spec->points      = (StressPoints)points;
  const double cap  = strength / gmax;
  // The constructors state the rule a value breaks (std::invalid_argument); the option names
  // are ours, so each parameter is checked against its range here first, and what is left
  // (a combination the model cannot hold) is caught below.
  try {
    switch (spec->choice) {
    case BackboneChoice::Mkz:
      PetscCheck(has_gamma, comm, PETSC_ERR_USER_INPUT, "-material_%s_reference_strain is missing (-material_%s_backbone mkz); allowed: gamma_r > 0 [-]", r, r);
      PetscCheck(gamma_r > 0 && gamma_r < 1, comm, PETSC_ERR_USER_INPUT, "-material_%s_reference_strain = %g; allowed: 0 < gamma_r < 1 [-] (a ratio, not percent)", r,
                 (double)gamma_r);
      PetscCheck(curvature > 0 && curvature <= 1, comm, PETSC_ERR_USER_INPUT,
                 "-material_%s_curvature = %g; allowed: 0 < s <= 1 (a larger s is not concave: no parallel Iwan model holds it)", r, (double)curvature);
      PetscCheck(beta > 0 && std::isfinite(beta), comm, PETSC_ERR_USER_INPUT, "-material_%s_beta = %g; allowed: beta > 0", r, (double)beta);
      spec->backbone = physics::mkzBackbone(gamma_r, curvature, beta, cap);
      break;
    case BackboneChoice::Darendeli:
      PetscCheck(has_mean, comm, PETSC_ERR_USER_INPUT, "-material_%s_mean_effective_stress is missing (-material_%s_backbone darendeli); allowed: sigma'_0 > 0 [Pa] or geostatic",
                 r, r);
      // geostatic: the model is the curve at 1 atm, each point's strains scaled by its
      // sigma'_0 (physics::darendeliStrainScale); core/option_rules.cpp refuses a cap with it.
      if (mean_geostatic) mean_stress = kDarendeliReferenceStress;
      PetscCheck(mean_stress > 0 && std::isfinite(mean_stress), comm, PETSC_ERR_USER_INPUT, "-material_%s_mean_effective_stress = %g; allowed: sigma'_0 > 0 [Pa] or geostatic", r,
                 (double)mean_stress);
      spec->mean_stress_geostatic           = mean_geostatic;
      PetscCheck(pi >= 0 && pi <= 200, comm, PETSC_ERR_USER_INPUT, "-material_%s_plasticity_index = %g; allowed: 0 to 200 [%%]", r, (double)pi);
      PetscCheck(ocr >= 1 && ocr <= 100, comm, PETSC_ERR_USER_INPUT, "-material_%s_ocr = %g; allowed: 1 to 100", r, (double)ocr);
      spec->darendeli.plasticity_index      = pi;
      spec->darendeli.ocr                   = ocr;
      spec->darendeli.mean_effective_stress = mean_stress;
      spec->backbone                        = physics::darendeliBackbone(spec->darendeli, cap);
      break;
    case BackboneChoice::Gqh:
      PetscCheck(has_strength, comm, PETSC_ERR_USER_INPUT, "-material_%s_strength is missing (-material_%s_backbone gqh); allowed: tau_max > 0 [Pa]", r, r);
      PetscCheck(theta[2] > 0 && theta[3] >= 0 && theta[4] > 0, comm, PETSC_ERR_USER_INPUT,
                 "-material_%s_gqh_theta = %g,%g,%g,%g,%g; allowed: theta3 > 0, theta4 >= 0, theta5 > 0", r, (double)theta[0], (double)theta[1], (double)theta[2],
                 (double)theta[3], (double)theta[4]);
      {
        const double t[5] = {theta[0], theta[1], theta[2], theta[3], theta[4]};
        spec->backbone    = physics::gqhBackbone(gmax, strength, t);
      }
      break;
    case BackboneChoice::Table: {
      PetscCheck(has_file, comm, PETSC_ERR_USER_INPUT, "-material_%s_backbone_file is missing (-material_%s_backbone table); allowed: a CSV file of strain,G/Gmax rows", r, r);
      BackboneTable     table;
      const std::string problem = ReadBackboneTable(file, &table);
      PetscCheck(problem.empty(), comm, PETSC_ERR_USER_INPUT, "-material_%s_backbone_file = %s", r, problem.c_str());
      spec->table_file   = file;
      spec->table_source = table.source;
      spec->backbone     = physics::tableBackbone(table.strain, table.ratio, cap);
    } break;
    }
    physics::HystereticSurfaces s;
    s.count     = (int)surfaces;
    spec->model = std::make_shared<const physics::HystereticSoilModel>(gmax, bulk, spec->backbone, s);
  } catch (const std::invalid_argument &e) {
    SETERRQ(comm, PETSC_ERR_USER_INPUT, "-material_%s_backbone %s with these parameters: %s", r, kBackboneNames[choice], e.what());
  }
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
    PetscInt          model = (PetscInt)MaterialModel::Elastic, dilatation = (PetscInt)fem::Dilatation::Gauss;
    PetscBool         has_dilatation;
    HystereticSpec    hysteretic;
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
                                  "how the region deforms: elastic, rigid (one rigid body: no internal waves, no step limit of its own; for a structure "
                                  "far stiffer than the soil) or hysteretic (Masing soil, -backbone; its -vs is the small-strain one)",
                                  kMaterialModelNames, 3, &model, nullptr));
    // A yielding soil flows at constant volume, which fully integrated quadrilaterals cannot
    // follow (they lock: a footing's collapse load is not reached, tests/cases/
    // hysteretic_footing_collapse.sh), so a hysteretic region takes the mean by default.
    if (model == (PetscInt)MaterialModel::Hysteretic) dilatation = (PetscInt)fem::Dilatation::Mean;
    PetscCall(core::OptionsChoice(PetscOptionsObject, "-dilatation",
                                  "where the elements of degree 1 take the volumetric strain: gauss (at each Gauss point, full integration) or mean (each "
                                  "element's mean, the B-bar element: no locking under isochoric flow; the default of a hysteretic region)",
                                  kDilatationNames, 2, &dilatation, &has_dilatation));
    // Read here so that -help lists them with the region's other options; checked below, once
    // the elastic material (Gmax) is known.
    physics::ElasticMaterial given_elastic{rho, vp, vs};
    if (has_e && has_nu && physics::youngPoissonProblem(young, nu, rho).empty()) given_elastic = physics::fromYoungPoisson(young, nu, rho);
    const bool     usable = physics::elasticMaterialProblem(given_elastic).empty() && has_rho;
    PetscCall(hystereticRead(PetscOptionsObject, comm, region.c_str(), model == (PetscInt)MaterialModel::Hysteretic, usable ? &given_elastic : nullptr, &hysteretic));
    PetscOptionsEnd();
    const char *r = region.c_str();
    PetscBool   help;
    PetscCall(PetscOptionsHasHelp(nullptr, &help));
    if (help && !(has_rho || has_vp || has_vs || has_e || has_nu)) { // -help alone: a stand-in lets the listing reach every module; nothing runs
      rho = 2000, vp = 400, vs = 200;
      has_rho = has_vp = has_vs = PETSC_TRUE;
    }
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
    const std::string speed = physics::ShearSpeedImplausible(m.vs), density = physics::DensityImplausible(m.rho), name = "-material_" + region + "_";
    if (!speed.empty()) PetscCall(core::WarningPrint(comm, (moduli ? name + "E and " + name + "nu give vs = " : name + "vs = ") + speed));
    if (!density.empty()) PetscCall(core::WarningPrint(comm, name + "rho = " + density));
    PetscCheck(damping_ratio >= 0 && damping_ratio < 0.5, comm, PETSC_ERR_USER_INPUT, "-material_%s_damping_ratio = %g; allowed: 0 <= xi < 0.5 (0: elastic)", r,
               (double)damping_ratio);
    PetscCheck(!has_reference || (reference_frequency > 0 && damping_ratio > 0), comm, PETSC_ERR_USER_INPUT,
               "-material_%s_reference_frequency = %g; allowed: > 0 Hz, in a region with -material_%s_damping_ratio > 0", r, (double)reference_frequency, r);
    // A rigid region has no strain: nothing for a damping law to act on.
    PetscCheck(model != (PetscInt)MaterialModel::Rigid || damping_ratio == 0, comm, PETSC_ERR_USER_INPUT,
               "-material_%s_damping_ratio = %g with -material_%s_model rigid; allowed: 0 (a rigid region does not deform)", r, (double)damping_ratio, r);
    PetscCheck(!has_dilatation || model != (PetscInt)MaterialModel::Rigid, comm, PETSC_ERR_USER_INPUT,
               "-material_%s_dilatation %s with -material_%s_model rigid; allowed: only on a region that deforms", r, kDilatationNames[dilatation], r);
    RegionMaterialInfo info;
    info.region  = region;
    info.elastic = m;
    info.fe      = fem::RegionMaterial{m.rho, physics::lame(m), model != (PetscInt)MaterialModel::Rigid, (fem::Dilatation)dilatation};
    info.dilatation_given = has_dilatation;
    info.damping_ratio = damping_ratio;
    info.reference_frequency = reference_frequency;
    info.model               = (MaterialModel)model;
    info.hysteretic          = hysteretic;
    materials->push_back(info);
  }
  PetscFunctionReturn(0);
}

} // namespace slipwave::medium

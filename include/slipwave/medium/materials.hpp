// Linear elastic isotropic material per region, from -material_<region>_{rho,vp,vs} or
// -material_<region>_{rho,E,nu}, and a constant-Q damping ratio -material_<region>_damping_ratio.
// -material_<region>_model says how the region deforms: elastic (the default), rigid (the
// region moves as one rigid body, problem/rigid_bodies.hpp; its elastic constants still serve
// the geostatic stage's static solve) or hysteretic (Masing soil: the elastic constants are
// the small-strain ones, Gmax = rho vs^2, and -material_<region>_backbone with its parameters
// gives the curve; physics/hysteretic_soil.hpp, docs/hysteretic-soil.md).
// A region without a material, or a -material_<name>_*
// option naming no region, stops the run.
#pragma once
#include <petscsys.h>

#include <memory>
#include <string>
#include <vector>

#include "slipwave/fem/bulk_operator.hpp"
#include "slipwave/physics/elastic_material.hpp"
#include "slipwave/physics/hysteretic_soil.hpp"

namespace slipwave::medium {

// How a region's material deforms (-material_<region>_model).
enum class MaterialModel { Elastic, Rigid, Hysteretic };
inline constexpr const char *kMaterialModelNames[] = {"elastic", "rigid", "hysteretic"};

// The backbone of a hysteretic region (-material_<region>_backbone; physics/soil_backbone.hpp).
enum class BackboneChoice { Mkz, Darendeli, Gqh, Table };
inline constexpr const char *kBackboneNames[] = {"mkz", "darendeli", "gqh", "table"};

// Where a hysteretic region's stress is evaluated (-material_<region>_stress_points;
// medium/hysteresis.hpp): the Gauss points of the linear K, or once per cell from its mean strain.
enum class StressPoints { Gauss, Mean };
inline constexpr const char *kStressPointNames[] = {"gauss", "mean"};

// Where a region's elements take the volumetric strain (-material_<region>_dilatation;
// fem/element_kernels.hpp), in the order of fem::Dilatation.
inline constexpr const char *kDilatationNames[] = {"gauss", "mean"};

// What a hysteretic region was given, for the report, and the model built from it (once, when
// the options are read, so that a backbone the model cannot hold stops the run before the mesh
// work; shared because every copy of the material list describes the same region).
struct HystereticSpec {
  BackboneChoice                                     choice = BackboneChoice::Mkz;
  physics::SoilBackbone                              backbone;
  physics::DarendeliSoil                             darendeli; // choice Darendeli
  double                                             strength = 0; // tau_max [Pa]; 0: no cap (MKZ, Darendeli, table)
  std::string                                        table_file, table_source; // choice Table: the CSV file and its "# source:"
  StressPoints                                       points = StressPoints::Gauss;
  // choice Darendeli with -material_<r>_mean_effective_stress geostatic: the model is the curve
  // at kDarendeliReferenceStress, each element's strains scaled by its own sigma'_0
  // (medium/hysteresis.hpp, physics/free_field_column.hpp).
  bool                                               mean_stress_geostatic = false;
  std::shared_ptr<const physics::HystereticSoilModel> model;
};

// The sigma'_0 of the curve a geostatic Darendeli region's model holds [Pa]: 1 atm.
constexpr double kDarendeliReferenceStress = 101325;

struct RegionMaterialInfo {
  std::string               region;
  physics::ElasticMaterial  elastic;
  fem::RegionMaterial       fe;            // element moduli: unrelaxed ones in a damped region (medium/attenuation.hpp)
  double                    damping_ratio = 0; // constant-Q damping ratio; 0: elastic
  double                    reference_frequency = 0; // where vp, vs hold in a damped region [Hz]; 0: the global choice
  double                    vp_undrained = 0; // saturated region: P speed with the pore fluid locked in (porous/pore_pressure.hpp); 0: dry
  MaterialModel             model = MaterialModel::Elastic;
  HystereticSpec            hysteretic; // model Hysteretic only
  bool                      dilatation_given = false; // -material_<region>_dilatation (fe.dilatation) given, not the model's default
};

// What a boundary of the region sees (absorbing dashpots, free-field columns): a saturated
// region's P wave is the undrained one (the fluid moves with the skeleton).
inline physics::ElasticMaterial boundaryElastic(const RegionMaterialInfo &m) {
  physics::ElasticMaterial e = m.elastic;
  if (m.vp_undrained > 0) e.vp = m.vp_undrained;
  return e;
}

PetscErrorCode MaterialsRead(MPI_Comm comm, const std::vector<std::string> &regions, std::vector<RegionMaterialInfo> *materials);

} // namespace slipwave::medium

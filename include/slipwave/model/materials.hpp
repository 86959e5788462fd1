// Linear elastic isotropic material per region, from -material_<region>_{rho,vp,vs} or
// -material_<region>_{rho,E,nu}. A region without a material, or a -material_<name>_*
// option naming no region, stops the run.
#pragma once
#include <petscsys.h>

#include <string>
#include <vector>

#include "slipwave/fem/bulk_operator.hpp"
#include "slipwave/physics/elastic_material.hpp"

namespace slipwave::model {

struct RegionMaterialInfo {
  std::string               region;
  physics::ElasticMaterial  elastic;
  fem::RegionMaterial       fe;
};

PetscErrorCode MaterialsRead(MPI_Comm comm, const std::vector<std::string> &regions, std::vector<RegionMaterialInfo> *materials);

} // namespace slipwave::model

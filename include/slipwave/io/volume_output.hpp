// The volume grid for FieldWriter: node coordinates and cell connectivity in the global node
// numbering of the displacement vector (node i = entries [i*dim, (i+1)*dim) of a global
// vector), and per output step u, v, a at nodes plus cell stress and region id.
#pragma once
#include <petscdm.h>

#include <string>
#include <vector>

#include "slipwave/fem/bulk_operator.hpp"
#include "slipwave/io/field_writer.hpp"

namespace slipwave::io {

class VolumeOutput {
public:
  // previous: output steps (step, time) already in DIR/volume.h5 to keep (a restart), or null.
  // pore_layout: a pore-pressure vector of a saturated scene (its layout names the pressure
  // fields of the frames a restart carries over), or null.
  PetscErrorCode Open(DM dm, const fem::BulkOperator &bulk, const std::string &dir, const std::vector<std::pair<PetscInt, PetscReal>> *previous = nullptr,
                      Vec pore_layout = nullptr);
  // initial_stress: 6 per local cell added to the stress of u (the geostatic state), or empty.
  // p_total, p_excess: saturated scenes, one value per node in the same node order (global
  // vectors of porous/pore_pressure.hpp), written as the node fields pore_pressure and
  // excess_pore_pressure [Pa]; else null. The stress written is then the effective stress
  // (total = effective - alpha p I).
  PetscErrorCode Write(DM dm, const fem::BulkOperator &bulk, PetscInt step, PetscReal t, Vec u, Vec v, Vec a, const std::vector<double> &initial_stress,
                       Vec p_total = nullptr, Vec p_excess = nullptr);
  PetscErrorCode Close();

private:
  FieldWriter writer_;
  Vec         geometry_ = nullptr, stress_ = nullptr, region_ = nullptr, u_local_ = nullptr;
  IS          topology_ = nullptr;
};

} // namespace slipwave::io

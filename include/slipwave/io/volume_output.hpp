// The volume grid for FieldWriter: node coordinates and cell connectivity in the global node
// numbering of the displacement vector (node i = entries [i*dim, (i+1)*dim) of a global
// vector), and per output step u, v, a at nodes plus cell stress and region id (and, with
// hysteretic soil, its largest shear strain and secant G/Gmax per cell), and
// displacement_relative, u less the base's displacement (io/base_displacement.hpp).
#pragma once
#include <petscdm.h>

#include <string>
#include <vector>

#include "slipwave/fem/bulk_operator.hpp"
#include "slipwave/io/field_writer.hpp"

namespace slipwave::io {

// Hysteretic soil (medium/hysteresis.hpp), per local cell: what the linear cell stress holds
// beyond the soil's (6 per cell, subtracted from it), and the cell fields max_shear_strain and
// secant_modulus_ratio (1 and 0 in other cells).
struct SoilCellOutput {
  const double *relaxation_stress, *max_shear_strain, *modulus_ratio;
};

// The stress the volume output shows in local cell c (6: xx, yy, zz, xy, yz, xz): the linear
// stress of u_local (fem::BulkOperator::cellStress), plus initial_stress (6 per local cell, or
// empty), less relaxation (the cell's 6 values of SoilCellOutput::relaxation_stress, or null).
// The stations record the same stress (io/stations.hpp).
void CellStressShown(const fem::BulkOperator &bulk, PetscInt c, const PetscScalar *u_local, const std::vector<double> &initial_stress, const double *relaxation, double *s);

class VolumeOutput {
public:
  // previous: output steps (step, time) already in DIR/volume.h5 to keep (a restart), or null.
  // pore_layout: a pore-pressure vector of a saturated scene (its layout names the pressure
  // fields of the frames a restart carries over), or null.
  // soil: the scene has hysteretic regions (their cell fields are written). cavities: a
  // saturated scene with a cavitation limit (its frames carry cavity_fraction).
  PetscErrorCode Open(DM dm, const fem::BulkOperator &bulk, const std::string &dir, const std::vector<std::pair<PetscInt, PetscReal>> *previous = nullptr,
                      Vec pore_layout = nullptr, bool soil = false, bool cavities = false);
  // initial_stress: 6 per local cell added to the stress of u (the geostatic state), or empty.
  // p_total, p_excess: saturated scenes, one value per node in the same node order (global
  // vectors of porous/pore_pressure.hpp), written as the node fields pore_pressure and
  // excess_pore_pressure [Pa]; else null. The stress written is then the effective stress
  // (total = effective - alpha p I). cavity_fraction: with a cavitation limit, each node's
  // cavity over the volume it stands for [-], written as the node field cavity_fraction.
  // base: the base's displacement (dim values) taken off u in displacement_relative.
  PetscErrorCode Write(DM dm, const fem::BulkOperator &bulk, PetscInt step, PetscReal t, Vec u, const PetscScalar *base, Vec v, Vec a, const std::vector<double> &initial_stress,
                       Vec p_total = nullptr, Vec p_excess = nullptr, Vec cavity_fraction = nullptr, const SoilCellOutput *soil = nullptr);
  PetscErrorCode Close();

private:
  FieldWriter writer_;
  Vec         u_relative_ = nullptr; // displacement_relative
  Vec         geometry_ = nullptr, stress_ = nullptr, region_ = nullptr, u_local_ = nullptr;
  Vec         max_strain_ = nullptr, modulus_ratio_ = nullptr; // hysteretic soil's cell fields, or null
  IS          topology_ = nullptr;
};

} // namespace slipwave::io

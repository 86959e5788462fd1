#include "slipwave/io/volume_output.hpp"

#include <vector>

#include "slipwave/core/log_events.hpp"

namespace slipwave::io {

void CellStressShown(const fem::BulkOperator &bulk, PetscInt c, const PetscScalar *u_local, const std::vector<double> &initial_stress, const double *relaxation, double *s) {
  bulk.cellStress(c, u_local, s);
  for (int k = 0; k < fem::kStressComponents; ++k) {
    if (!initial_stress.empty()) s[k] += initial_stress[c * fem::kStressComponents + k];
    if (relaxation) s[k] -= relaxation[k];
  }
}

PetscErrorCode VolumeOutput::Open(DM dm, const fem::BulkOperator &bulk, const std::string &dir, const std::vector<std::pair<PetscInt, PetscReal>> *previous,
                                  Vec pore_layout, bool soil, bool cavities) {
  MPI_Comm     comm = PetscObjectComm((PetscObject)dm);
  const PetscInt dim = bulk.dimension(), nen = bulk.nodesPerCell(), ncell = bulk.cellCount();
  PetscSection gsection;
  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalSection(dm, &gsection));
  std::vector<PetscInt> conn(ncell * nen);
  for (PetscInt c = 0; c < ncell; ++c)
    for (PetscInt a = 0; a < nen; ++a) {
      PetscInt off;
      PetscCall(PetscSectionGetOffset(gsection, bulk.cellVertex(c, a), &off));
      if (off < 0) off = -(off + 1); // a ghost vertex: its owner's offset
      conn[c * nen + a] = off / dim;
    }
  PetscCall(ISCreateGeneral(comm, ncell * nen, conn.data(), PETSC_COPY_VALUES, &topology_));
  PetscCall(ISSetBlockSize(topology_, nen));

  PetscCall(DMCreateLocalVector(dm, &u_local_));
  PetscCall(DMCreateGlobalVector(dm, &geometry_));
  PetscScalar *x;
  PetscCall(VecGetArray(u_local_, &x));
  bulk.nodeCoordinates(x);
  PetscCall(VecRestoreArray(u_local_, &x));
  PetscCall(DMLocalToGlobal(dm, u_local_, INSERT_VALUES, geometry_));
  PetscCall(VecSetBlockSize(geometry_, dim));
  PetscCall(VecDuplicate(geometry_, &u_relative_));

  PetscCall(VecCreateMPI(comm, ncell * fem::kStressComponents, PETSC_DETERMINE, &stress_));
  PetscCall(VecSetBlockSize(stress_, fem::kStressComponents));
  PetscCall(VecCreateMPI(comm, ncell, PETSC_DETERMINE, &region_));
  PetscScalar *r;
  PetscCall(VecGetArray(region_, &r));
  for (PetscInt c = 0; c < ncell; ++c) r[c] = bulk.cellRegion(c);
  PetscCall(VecRestoreArray(region_, &r));
  if (soil) {
    PetscCall(VecCreateMPI(comm, ncell, PETSC_DETERMINE, &max_strain_));
    PetscCall(VecDuplicate(max_strain_, &modulus_ratio_));
  }

  const char *types[4] = {"Triangle", "Quadrilateral", "Tetrahedron", "Hexahedron"};
  GridLayout  grid;
  grid.name           = "volume";
  grid.dim            = (int)dim;
  grid.cell_type      = types[(int)bulk.shape()];
  grid.nodes_per_cell = (int)nen;
  if (previous) {
    // The node fields have the geometry's layout; the cell fields those of stress and region.
    std::vector<FieldRef> layout = {{"displacement", Centering::Node, geometry_},
                                    {"displacement_relative", Centering::Node, geometry_},
                                    {"velocity", Centering::Node, geometry_},
                                    {"acceleration", Centering::Node, geometry_},
                                    {"stress", Centering::Cell, stress_},
                                    {"region", Centering::Cell, region_}};
    if (pore_layout) layout.insert(layout.end(), {{"pore_pressure", Centering::Node, pore_layout}, {"excess_pore_pressure", Centering::Node, pore_layout}});
    if (cavities) layout.push_back({"cavity_fraction", Centering::Node, pore_layout});
    if (soil) layout.insert(layout.end(), {{"max_shear_strain", Centering::Cell, region_}, {"secant_modulus_ratio", Centering::Cell, region_}});
    PetscCall(writer_.Resume(comm, dir, grid, geometry_, topology_, *previous, layout));
  } else {
    PetscCall(writer_.Open(comm, dir, grid, geometry_, topology_));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode VolumeOutput::Write(DM dm, const fem::BulkOperator &bulk, PetscInt step, PetscReal t, Vec u, const PetscScalar *base, Vec v, Vec a,
                                   const std::vector<double> &initial_stress, Vec p_total, Vec p_excess, Vec cavity_fraction, const SoilCellOutput *soil) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(core::event_output, 0, 0, 0, 0));
  PetscCall(DMGlobalToLocal(dm, u, INSERT_VALUES, u_local_));
  const PetscScalar *ul;
  PetscScalar       *s;
  PetscCall(VecGetArrayRead(u_local_, &ul));
  PetscCall(VecGetArray(stress_, &s));
  for (PetscInt c = 0; c < bulk.cellCount(); ++c) CellStressShown(bulk, c, ul, initial_stress, soil ? &soil->relaxation_stress[c * fem::kStressComponents] : nullptr, &s[c * fem::kStressComponents]);
  if (soil) {
    PetscScalar *g, *ratio;
    PetscCall(VecGetArray(max_strain_, &g));
    PetscCall(VecGetArray(modulus_ratio_, &ratio));
    for (PetscInt c = 0; c < bulk.cellCount(); ++c) {
      g[c]     = soil->max_shear_strain[c];
      ratio[c] = soil->modulus_ratio[c];
    }
    PetscCall(VecRestoreArray(modulus_ratio_, &ratio));
    PetscCall(VecRestoreArray(max_strain_, &g));
  }
  PetscCall(VecRestoreArray(stress_, &s));
  PetscCall(VecRestoreArrayRead(u_local_, &ul));
  for (Vec x : {u, v, a}) PetscCall(VecSetBlockSize(x, bulk.dimension()));
  PetscInt     n;
  PetscScalar *r;
  PetscCall(VecCopy(u, u_relative_));
  PetscCall(VecGetLocalSize(u_relative_, &n));
  PetscCall(VecGetArray(u_relative_, &r));
  for (PetscInt i = 0; i < n; ++i) r[i] -= base[i % bulk.dimension()];
  PetscCall(VecRestoreArray(u_relative_, &r));
  std::vector<FieldRef> fields = {{"displacement", Centering::Node, u},
                                            {"displacement_relative", Centering::Node, u_relative_},
                                            {"velocity", Centering::Node, v},
                                            {"acceleration", Centering::Node, a},
                                            {"stress", Centering::Cell, stress_},
                                            {"region", Centering::Cell, region_}};
  if (p_total) fields.push_back({"pore_pressure", Centering::Node, p_total});
  if (p_excess) fields.push_back({"excess_pore_pressure", Centering::Node, p_excess});
  if (cavity_fraction) fields.push_back({"cavity_fraction", Centering::Node, cavity_fraction});
  if (soil) fields.insert(fields.end(), {{"max_shear_strain", Centering::Cell, max_strain_}, {"secant_modulus_ratio", Centering::Cell, modulus_ratio_}});
  PetscCall(writer_.WriteStep(step, t, fields));
  PetscCall(PetscLogEventEnd(core::event_output, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode VolumeOutput::Close() {
  PetscFunctionBeginUser;
  PetscCall(writer_.Close());
  PetscCall(VecDestroy(&geometry_));
  PetscCall(VecDestroy(&u_relative_));
  PetscCall(VecDestroy(&stress_));
  PetscCall(VecDestroy(&max_strain_));
  PetscCall(VecDestroy(&modulus_ratio_));
  PetscCall(VecDestroy(&region_));
  PetscCall(ISDestroy(&topology_));
  if (u_local_) PetscCall(VecDestroy(&u_local_));
  PetscFunctionReturn(0);
}

} // namespace slipwave::io

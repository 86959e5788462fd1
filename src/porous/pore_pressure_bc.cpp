#include "slipwave/porous/pore_pressure.hpp"

#include "slipwave/core/option_choice.hpp"
#include "slipwave/input/boundary_faces.hpp"

// The pore fluid's boundary conditions: -bc_<b>_fluid on named boundaries,
// -interface_<n>_fluid on interfaces over saturated soil, and the drained nodes they make.
namespace slipwave::porous {
namespace {

enum FluidCondition { NoFlow, Drained, Flux };
const char *const kFluidNames[] = {"noflow", "drained", "flux"};

} // namespace

PetscErrorCode PorePressureReadFluidBoundaries(DM dm, DM pdm, const std::vector<std::string> &boundaries, const std::vector<SaturatedRegion> &regions,
                                               Vec drained_local, Vec inflow_local, PorePressure *pp) {
  MPI_Comm     comm = PetscObjectComm((PetscObject)dm);
  PetscSection section;
  PetscScalar *drained, *inflow;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(pdm, &section));
  PetscCall(VecGetArray(drained_local, &drained));
  PetscCall(VecGetArray(inflow_local, &inflow));
  for (const std::string &b : boundaries) {
    const std::string prefix = "bc_" + b + "_";
    const std::string title  = "Pore fluid on boundary " + b;
    PetscInt          condition = NoFlow;
    PetscReal         q         = 0;
    PetscBool         q_set     = PETSC_FALSE;
    PetscOptionsBegin(comm, prefix.c_str(), title.c_str(), "slipwave");
    PetscCall(core::OptionsChoice(PetscOptionsObject, "-fluid", "pore fluid condition: noflow (default), drained (p = 0), flux (prescribed inflow)", kFluidNames, 3, &condition,
                                  nullptr));
    PetscCall(PetscOptionsReal("-fluid_flux", "Darcy inflow through the boundary q [m/s], inward positive (with -bc_<b>_fluid flux)", "PorePressureCreate", q, &q, &q_set));
    PetscOptionsEnd();
    PetscCheck(!q_set || condition == Flux, comm, PETSC_ERR_USER_INPUT, "-%sfluid_flux is given but -%sfluid = %s; allowed: -%sfluid flux", prefix.c_str(), prefix.c_str(),
               kFluidNames[condition], prefix.c_str());
    if (condition == NoFlow) continue;
    (condition == Drained ? pp->drained : pp->flux).push_back(b);
    std::vector<input::BoundaryFace> faces;
    PetscCall(input::BoundaryFacesGet(dm, b, &faces));
    for (const input::BoundaryFace &f : faces) {
      if (!regions[f.region].saturated) continue;
      for (PetscInt k = 0; k < f.nvert; ++k) {
        PetscInt off;
        PetscCall(PetscSectionGetOffset(section, f.vertices[k], &off));
        if (condition == Drained) drained[off] = 1;
        else inflow[off] += q * f.weights[k];
      }
    }
  }
  PetscCall(VecRestoreArray(inflow_local, &inflow));
  PetscCall(VecRestoreArray(drained_local, &drained));
  PetscFunctionReturn(0);
}

PetscErrorCode PorePressureInterfaceFluid(PorePressure *pp, MPI_Comm comm, const std::string &name, const std::vector<PetscInt> &soil_dofs) {
  const std::string prefix = "interface_" + name + "_";
  const std::string title  = "Pore fluid at interface " + name;
  const char *const kInterfaceFluid[] = {"noflow", "drained", "gap"};
  PetscInt          condition         = 0;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, prefix.c_str(), title.c_str(), "slipwave");
  PetscCall(core::OptionsChoice(PetscOptionsObject, "-fluid",
                                "pore fluid on the soil side of the interface: noflow (default), drained (excess pore pressure 0), gap (noflow while in contact, "
                                "drained where a pair opens: water or air fills the gap)",
                                kInterfaceFluid, 3, &condition, nullptr));
  PetscOptionsEnd();
  Vec marker;
  PetscCall(VecDuplicate(pp->p, &marker));
  PetscCall(VecZeroEntries(marker));
  for (PetscInt dof : soil_dofs) PetscCall(VecSetValue(marker, dof / pp->dim, 1.0, INSERT_VALUES));
  PetscCall(VecAssemblyBegin(marker));
  PetscCall(VecAssemblyEnd(marker));
  if (condition == 1) {
    pp->drained.push_back("interface " + name);
    PetscCall(PorePressureDrainNodes(pp, marker));
  } else if (condition == 2) {
    pp->sealed_interfaces.push_back(name);
  }
  if (condition != 1 && pp->at_water_table) {
    // noflow: the structure seals the soil surface it rests on, so soil nodes that the water
    // table drained only because they lie on it (a footing on a water table at the surface)
    // keep their excess pore pressure. Fluid boundaries (-bc_<b>_fluid drained) still win.
    PetscInt           n, sealed = 0;
    PetscScalar       *mask, *inv;
    const PetscScalar *mk, *at, *S;
    PetscCall(VecGetLocalSize(marker, &n));
    PetscCall(VecGetArrayRead(marker, &mk));
    PetscCall(VecGetArrayRead(pp->at_water_table, &at));
    PetscCall(VecGetArrayRead(pp->storage, &S));
    PetscCall(VecGetArray(pp->free_mask, &mask));
    PetscCall(VecGetArray(pp->inv_storage, &inv));
    for (PetscInt i = 0; i < n; ++i)
      if (PetscRealPart(mk[i]) > 0 && PetscRealPart(at[i]) > 0) {
        mask[i] = 1.0;
        inv[i]  = 1.0 / S[i];
        ++sealed;
      }
    PetscCall(VecRestoreArray(pp->inv_storage, &inv));
    PetscCall(VecRestoreArray(pp->free_mask, &mask));
    PetscCall(VecRestoreArrayRead(pp->storage, &S));
    PetscCall(VecRestoreArrayRead(pp->at_water_table, &at));
    PetscCall(VecRestoreArrayRead(marker, &mk));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &sealed, 1, MPIU_INT, MPI_SUM, comm));
    if (sealed) pp->drained.push_back("(not the " + std::to_string(sealed) + " soil nodes of interface " + name + " on the water table: noflow seals them)");
  }
  PetscCall(VecDestroy(&marker));
  PetscFunctionReturn(0);
}

PetscErrorCode PorePressureDrainOpenGaps(PorePressure *pp, Vec open_marker) {
  PetscInt           n;
  PetscScalar       *mask, *inv;
  const PetscScalar *open, *mask0, *inv0;
  PetscFunctionBeginUser;
  if (!pp->sealed_free_mask) {
    // The first call comes after the set-up: its conditions are those without a gap.
    PetscCall(VecDuplicate(pp->free_mask, &pp->sealed_free_mask));
    PetscCall(VecCopy(pp->free_mask, pp->sealed_free_mask));
    PetscCall(VecDuplicate(pp->inv_storage, &pp->sealed_inv_storage));
    PetscCall(VecCopy(pp->inv_storage, pp->sealed_inv_storage));
  }
  PetscCall(VecGetLocalSize(open_marker, &n));
  PetscCall(VecGetArrayRead(open_marker, &open));
  PetscCall(VecGetArrayRead(pp->sealed_free_mask, &mask0));
  PetscCall(VecGetArrayRead(pp->sealed_inv_storage, &inv0));
  PetscCall(VecGetArray(pp->free_mask, &mask));
  PetscCall(VecGetArray(pp->inv_storage, &inv));
  for (PetscInt i = 0; i < n; ++i) {
    const bool gap = PetscRealPart(open[i]) > 0;
    mask[i]        = gap ? 0.0 : mask0[i];
    inv[i]         = gap ? 0.0 : inv0[i];
  }
  PetscCall(VecRestoreArray(pp->inv_storage, &inv));
  PetscCall(VecRestoreArray(pp->free_mask, &mask));
  PetscCall(VecRestoreArrayRead(pp->sealed_inv_storage, &inv0));
  PetscCall(VecRestoreArrayRead(pp->sealed_free_mask, &mask0));
  PetscCall(VecRestoreArrayRead(open_marker, &open));
  PetscFunctionReturn(0);
}

PetscErrorCode PorePressureDrainNodes(PorePressure *pp, Vec marker) {
  PetscInt           n;
  PetscScalar       *mask, *inv;
  const PetscScalar *mk;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(marker, &n));
  PetscCall(VecGetArrayRead(marker, &mk));
  PetscCall(VecGetArray(pp->free_mask, &mask));
  PetscCall(VecGetArray(pp->inv_storage, &inv));
  // Fewer free nodes only raise the diffusion limit: the one computed stays a valid bound.
  for (PetscInt i = 0; i < n; ++i)
    if (PetscRealPart(mk[i]) > 0) mask[i] = inv[i] = 0.0;
  PetscCall(VecRestoreArray(pp->inv_storage, &inv));
  PetscCall(VecRestoreArray(pp->free_mask, &mask));
  PetscCall(VecRestoreArrayRead(marker, &mk));
  PetscFunctionReturn(0);
}

} // namespace slipwave::porous

#include "slipwave/fem/node_fields.hpp"

namespace slipwave::fem {

PetscErrorCode NodeFieldSetSection(DM dm, PetscInt dofs_per_vertex) {
  PetscSection s;
  PetscInt     p_start, p_end, v_start, v_end;
  PetscFunctionBeginUser;
  PetscCall(PetscSectionCreate(PetscObjectComm((PetscObject)dm), &s));
  PetscCall(DMPlexGetChart(dm, &p_start, &p_end));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v_start, &v_end));
  PetscCall(PetscSectionSetChart(s, p_start, p_end));
  for (PetscInt v = v_start; v < v_end; ++v) PetscCall(PetscSectionSetDof(s, v, dofs_per_vertex));
  PetscCall(PetscSectionSetUp(s));
  PetscCall(DMSetLocalSection(dm, s));
  PetscCall(PetscSectionDestroy(&s));
  PetscFunctionReturn(0);
}

PetscErrorCode NodeFieldCreateDM(DM dm, PetscInt dofs_per_vertex, DM *node_dm) {
  PetscFunctionBeginUser;
  PetscCall(DMClone(dm, node_dm));
  PetscCall(NodeFieldSetSection(*node_dm, dofs_per_vertex));
  PetscFunctionReturn(0);
}

} // namespace slipwave::fem

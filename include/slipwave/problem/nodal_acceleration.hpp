// The nodal part of the right-hand side, a* = M^{-1}(f_ext - K u - beta K v_{n+1/2} + f_interface
// + f_anelastic + f_contact_damping + f_hysteretic) on free dofs, in one pass over the dofs that reads only the
// force vectors a scene has, and the external force f_ext = f_constant + v_in(t) F_in + timed
// loads written only where it can be nonzero. With absorbing sides and an incident wave that is
// the boundary: a fraction of a percent of the dofs of a large mesh, which whole-vector
// operations would sweep every step.
#pragma once
#include <petscvec.h>

#include <vector>

#include "slipwave/input/timed_load.hpp"

namespace slipwave::problem {

// What a* and f_ext are formed from. The geostatic stage swaps the mask and rewrites the
// constant load, and a restart rewrites it: NodalAccelerationUpdate notices (PETSc object
// states) and rebuilds what depends on them.
struct NodalSources {
  Vec                           inv_mass, free_mask, input_force, constant_force;
  const std::vector<input::TimedLoad> *timed_loads;
  bool                          others_add_external; // a module (free field, DRM) adds to f_ext anywhere
};

struct NodalAcceleration {
  Vec                   free_inv_mass = nullptr; // 1/m on free dofs, 0 on held ones
  // Local dofs where f_input and f_external can be nonzero (when `listed`): the supports of
  // the incident-wave force, the constant loads and the timed loads' patterns.
  std::vector<PetscInt> external_dofs;
  bool                  listed = false; // false: f_ext is formed over every dof
  std::vector<PetscInt> held_dofs;      // local dofs with a prescribed motion (free mask 0)
  Vec                   seen_mask = nullptr, seen_constant = nullptr; // what the above was built from
  PetscObjectState      mask_state = -1, constant_state = -1;
};

// Builds (or, when a source has changed since, rebuilds) `na`; a rebuild zeroes f_input and
// f_external, which the RHS then forms again. Call at the start of every RHS (O(1) otherwise).
PetscErrorCode NodalAccelerationUpdate(const NodalSources &src, Vec f_input, Vec f_external, NodalAcceleration *na);
PetscErrorCode NodalAccelerationDestroy(NodalAcceleration *na);

// f_input = v_in F_in (where listed: on the listed dofs only; nothing else changes elsewhere).
PetscErrorCode NodalAccelerationInput(const NodalAcceleration &na, double v_in, Vec input_force, Vec f_input);
// f_external = f_constant + f_input.
PetscErrorCode NodalAccelerationExternal(const NodalAcceleration &na, Vec constant_force, Vec f_input, Vec f_external);

// The force vectors of a*; a null one is zero and not read.
struct NodalForces {
  Vec external, internal, stiffness_damping, interface, anelastic, contact_damping, hysteretic;
};
// a = (free 1/m) (f_ext - f_int - f_sd + f_if + f_an + f_cd + f_hy), summed in this order at every dof
// (a zero term changes no bit), so the result does not depend on which terms a scene has.
PetscErrorCode NodalAccelerationAssemble(const NodalAcceleration &na, const NodalForces &f, Vec a);

} // namespace slipwave::problem

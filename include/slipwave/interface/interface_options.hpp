// Command-line options of one interface law: -<prefix>E, -<prefix>G, -<prefix>phi,
// -<prefix>psi, -<prefix>c, -<prefix>e_ini, -<prefix>tensile_strength, -<prefix>sigma_N0,
// and, for an interface of a mesh, -<prefix>penalty_factor and -<prefix>contact_damping;
// default prefix "interface_" (a simulation with several interfaces passes its own). The
// interface's geometry (-interfaces, -interface_<n>_regions, _faces) is the mesh's: see
// mesh/mesh_builder.hpp.
#pragma once

#include "slipwave/physics/mohr_coulomb_interface.hpp"

#include <petscsys.h>

namespace slipwave::interface {

struct InterfaceOptions {
  physics::InterfaceParams params; // angles converted to radians
  double sigma_N0 = 0.0;           // initial normal traction [Pa], tension positive
  // E or G given as `auto`: the caller derives them from the mesh, then calls
  // InterfaceOptionsCheck; params holds 0 for them until then.
  PetscBool E_auto = PETSC_FALSE;
  PetscBool G_auto = PETSC_FALSE;
  double    penalty_factor = 1.0; // `auto`: factor x (lambda+2mu)/h and x mu/h of the softer side
  // Fraction of each closed pair's critical normal damping. 0.1 removes the contact stress
  // ripple of the two-bar impact (48 % -> 0.02 %) and the energy the switching created
  // (2.3e-4 -> 0) while moving the exit velocities by 0.1 % and the step by 1.4 % in the
  // default scene; larger ratios cost more step and raised the block's peaks there (README,
  // interfaces).
  double contact_damping = 0.1;
};

// Where the law is used: alone (slipwave-law: one pair, no mesh) or on the split pairs of a
// mesh, which adds the penalty factor and the contact damping.
enum class InterfaceUse { LawAlone, Mesh };

// Reads and validates the options (stiffnesses given as `auto` are left unchecked).
// prefix nullptr means "interface_".
PetscErrorCode InterfaceOptionsRead(MPI_Comm comm, const char *prefix, InterfaceUse use, InterfaceOptions *options);

// Stops with a user-input error naming the first option out of range, its value and the
// allowed range.
PetscErrorCode InterfaceOptionsCheck(MPI_Comm comm, const char *prefix, const InterfaceOptions &options);

} // namespace slipwave::interface

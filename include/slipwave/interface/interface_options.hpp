// Command-line options of one interface law: -<prefix>E, -<prefix>G, -<prefix>phi,
// -<prefix>psi, -<prefix>c, -<prefix>e_ini, -<prefix>tensile_strength, -<prefix>sigma_N0,
// default prefix "interface_" (a simulation with several interfaces passes its own).
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
};

// Reads and validates the options (stiffnesses given as `auto` are left unchecked).
// prefix nullptr means "interface_".
PetscErrorCode InterfaceOptionsRead(MPI_Comm comm, const char *prefix, InterfaceOptions *options);

// Stops with a user-input error naming the first option out of range, its value and the
// allowed range.
PetscErrorCode InterfaceOptionsCheck(MPI_Comm comm, const char *prefix, const InterfaceOptions &options);

} // namespace slipwave::interface

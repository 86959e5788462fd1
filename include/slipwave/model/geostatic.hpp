// Geostatic stage: gravity equilibrium of soil, structure and interfaces before shaking, by
// dynamic relaxation. The absorbing boundaries are held (a dashpot carries no static load)
// and the incident wave is off; explicit steps with local damping (each dof's unbalanced force
// is reduced by 0.8 of its size against the velocity) run until the unbalanced-force ratio
//   max |M a| / max |f_applied|   over the free dofs
// is below the tolerance. That state becomes the reference of the dynamic stage:
//  - displacements start again from zero, and the cell stresses of the geostatic state are
//    added to the output stress;
//  - the constant loads become what the geostatic state leaves unbalanced (f - K u_geo), and
//    at the held absorbing nodes the support reactions become constant forces, so the model
//    starts at rest in equilibrium;
//  - interfaces keep their tractions and state, with the jump measured from the new zero.
#pragma once
#include <petscsys.h>

#include <vector>

#include "slipwave/model/elastodynamics.hpp"

namespace slipwave::model {

struct GeostaticOptions {
  PetscBool enabled   = PETSC_FALSE;
  PetscReal tolerance = 1e-5;
  PetscInt  max_steps = 1000000;
};

struct GeostaticReport {
  PetscInt steps = 0;
  double   ratio = 0;
  double   wall  = 0;
};

PetscErrorCode GeostaticOptionsRead(MPI_Comm comm, GeostaticOptions *options);
PetscErrorCode GeostaticStage(Elastodynamics *model, const GeostaticOptions &options, double dt, GeostaticReport *report);

} // namespace slipwave::model

// main() of a unit test that needs PETSc: initialise, run, count a PETSc error as a failed
// check, finalise. -distribute selects the test's parallel variant (run under mpiexec).
#pragma once
#include <petscsys.h>

#include "unit_check.hpp"

namespace unit {

inline int runPetscTest(int argc, char **argv, PetscErrorCode (*run)(bool distribute)) {
  PetscBool distribute = PETSC_FALSE;
  PetscCall(PetscInitialize(&argc, &argv, nullptr, nullptr));
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-distribute", &distribute, nullptr));
  const PetscErrorCode ierr = run(distribute == PETSC_TRUE);
  check(ierr == 0, "no PETSc error");
  PetscCall(PetscFinalize());
  return failures();
}

} // namespace unit

// A choice option (one word out of a fixed list) read inside an options block. PETSc's
// PetscOptionsEList lists the choices in -help but stops an unknown value with PETSC_ERR_USER
// and a multi-line traceback; OptionsChoice checks the value first, so a bad one stops with
// the one-line user-input error "-<prefix><name> = <value>; allowed: a, b, c".
#pragma once
#include <petscsys.h>

namespace slipwave::core {

// Call between PetscOptionsBegin and PetscOptionsEnd. *index holds the default on entry and
// the chosen entry of choices[0..n) on return (matched case-insensitively, as PETSc does).
PetscErrorCode OptionsChoice(PetscOptionItems *PetscOptionsObject, const char *name, const char *help, const char *const *choices, PetscInt n,
                             PetscInt *index, PetscBool *set);

} // namespace slipwave::core

// PETSc runs a whole job with a misspelled option and only mentions it at exit. Call
// OptionsErrorIfUnused after every *SetFromOptions and options block, before the first
// step, so a typo stops the run at once.
#pragma once
#include <petscsys.h>

#include <map>
#include <string>

namespace slipwave::core {

// Moves each renamed option given under its old name to its new name and says so once on
// stdout; call before any option is read. Both names given stop the run.
PetscErrorCode OptionsApplyRenames(MPI_Comm comm);

// The options given and not read so far, name (without the dash) to value ("" for none),
// left unread: a check that looks at an option before its module (the record and station
// files, before the mesh) keeps the unused-option check intact.
PetscErrorCode OptionsNotYetRead(std::map<std::string, std::string> *given);

// Stops with PETSC_ERR_USER_INPUT naming every option given but never read.
PetscErrorCode OptionsErrorIfUnused(MPI_Comm comm);

} // namespace slipwave::core

// -help opens with slipwave's own options. PETSc prints its generic options (version, debugger,
// malloc, logging: about 60 lines) inside PetscInitialize, before any of slipwave's; they are
// held back while PETSc initialises and printed after slipwave's, under their own heading.
#pragma once
#include <petscsys.h>

namespace slipwave::core {

// Before PetscInitialize: with -help (or -h) on the command line, what PETSc prints through
// PetscHelpPrintf from now on is held instead of printed.
void HelpHoldPetscGeneric(int argc, const char *const *argv);
// After PetscInitialize: help is printed as it comes again.
void HelpStopHolding();
// At the end of a -help run: the held text, on rank 0 of comm.
PetscErrorCode HelpPrintHeld(MPI_Comm comm);

} // namespace slipwave::core

#include "slipwave/core/help_order.hpp"

#include <cstdarg>
#include <cstring>
#include <string>

namespace slipwave::core {
namespace {

std::string g_held;

PetscErrorCode holdHelp(MPI_Comm comm, const char format[], ...) {
  PetscMPIInt rank = 0;
  if (comm != MPI_COMM_NULL) MPI_Comm_rank(comm, &rank);
  if (rank != 0) return 0;
  char    buffer[8192];
  va_list args;
  va_start(args, format);
  const PetscErrorCode ierr = PetscVSNPrintf(buffer, sizeof buffer, format, nullptr, args); // PETSc's own formats (%D, "1.")
  va_end(args);
  if (!ierr) g_held += buffer;
  return 0;
}

} // namespace

void HelpHoldPetscGeneric(int argc, const char *const *argv) {
  for (int i = 1; i < argc; ++i)
    if (!std::strcmp(argv[i], "-help") || !std::strcmp(argv[i], "-h") || !std::strcmp(argv[i], "--help")) PetscHelpPrintf = holdHelp;
}

void HelpStopHolding() { PetscHelpPrintf = PetscHelpPrintfDefault; }

PetscErrorCode HelpPrintHeld(MPI_Comm comm) {
  PetscFunctionBeginUser;
  if (g_held.empty()) PetscFunctionReturn(0);
  PetscCall(PetscPrintf(comm, "\nPETSc's own options (any PETSc program; debugging, memory, logging):\n%s", g_held.c_str()));
  g_held.clear();
  PetscFunctionReturn(0);
}

} // namespace slipwave::core

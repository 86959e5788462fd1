#include "slipwave/app/setup_cost.hpp"

#include <sys/resource.h>

namespace slipwave::app {

PetscErrorCode ReportSetupCost(MPI_Comm comm, PetscLogDouble start, double mesh_seconds) {
  PetscLogDouble now;
  PetscMPIInt    size;
  struct rusage  usage;
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&now));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  getrusage(RUSAGE_SELF, &usage);
  // Linux gives ru_maxrss in KiB.
  const double peak = usage.ru_maxrss / 1024.0;
  double       low = peak, high = peak, sum = peak, root = peak;
  double       seconds = now - start, mesh = mesh_seconds;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &low, 1, MPI_DOUBLE, MPI_MIN, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &high, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPI_DOUBLE, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &seconds, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &mesh, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscCall(PetscPrintf(comm, "  set-up: %.2f s wall (mesh %.2f s); peak memory per rank %.1f / %.1f / %.1f MB (min / avg / max), rank 0 %.1f MB\n", seconds, mesh, low,
                        sum / size, high, root));
  PetscFunctionReturn(0);
}

} // namespace slipwave::app

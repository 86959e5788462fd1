#include "slipwave/core/mpi_singleton.hpp"

#include <cstdlib>
#include <initializer_list>

namespace slipwave::core {

void MpiSingletonDefaults() {
  // Set by Open MPI's mpiexec (OMPI_*), by a PMIx or PMI server (mpiexec of Open MPI and MPICH,
  // srun) and by Slurm in a job step: any of them means a launcher started this process.
  for (const char *launched : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_FD", "PMI_SIZE", "SLURM_STEP_ID"})
    if (std::getenv(launched)) return;
  setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  setenv("OMPI_MCA_pml", "ob1", 0);
}

} // namespace slipwave::core

// A program started without a launcher (`slipwave ...`, no mpiexec) is an MPI singleton. Open
// MPI then forks a helper daemon (orted) in MPI_Init, and its default transport (UCX) probes
// the machine's network devices: 0.3 s of the 0.4 s a small run took to start here, where the
// rest is the dynamic loader and MPI's own set-up. A singleton needs neither: it spawns no
// processes and has no peer to send to. So before MPI_Init, and only when no launcher started
// the process (no variable of Open MPI's mpiexec, a PMIx or PMI server or Slurm's srun in the
// environment), the two Open MPI settings that skip them are given as defaults (a value the
// user set is kept): OMPI_MCA_ess_singleton_isolated=1 (no daemon) and OMPI_MCA_pml=ob1 (Open
// MPI's own point-to-point layer; with no peer nothing is sent). Other MPI libraries ignore
// them. A launched run keeps every setting of its launcher.
#pragma once

namespace slipwave::core {

// Before PetscInitialize (MPI_Init reads the environment there).
void MpiSingletonDefaults();

} // namespace slipwave::core

#include "slipwave/mesh/memory_estimate.hpp"

#include <fstream>
#include <sstream>
#include <string>

namespace slipwave::mesh {
namespace {

// MemAvailable in bytes, or a negative number when the kernel does not say.
double availableBytes() {
  std::ifstream in("/proc/meminfo");
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string        key;
    double             kib = 0;
    if (fields >> key >> kib && key == "MemAvailable:") return kib * 1024.0;
  }
  return -1;
}

} // namespace

PetscErrorCode MemoryCheck(MPI_Comm comm, double cells, double dofs, const char *what) {
  PetscBool   check = PETSC_TRUE;
  PetscMPIInt rank, size, node_size;
  MPI_Comm    node;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "Memory check", "slipwave");
  PetscCall(PetscOptionsBool("-memory_check", "refuse a mesh whose estimated memory exceeds MemAvailable of a node (false: skip)", "MemoryCheck", check, &check,
                             nullptr));
  PetscOptionsEnd();
  if (!check) PetscFunctionReturn(0);
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &node));
  PetscCallMPI(MPI_Comm_size(node, &node_size));
  int holds_rank0 = rank == 0;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &holds_rank0, 1, MPI_INT, MPI_MAX, node));
  PetscCallMPI(MPI_Comm_free(&node));
  const double total = dofs * kBytesPerDof;
  const double need  = holds_rank0 ? total : total * node_size / size;
  const double have  = availableBytes();
  // The node with the least room for its share speaks for all.
  struct {
    double ratio;
    int    rank;
  } worst = {have > 0 ? need / have : 0, rank};
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm));
  if (worst.ratio <= 1) PetscFunctionReturn(0);
  double needed_available[2] = {need, have};
  PetscCallMPI(MPI_Bcast(needed_available, 2, MPI_DOUBLE, worst.rank, comm));
  SETERRQ(comm, PETSC_ERR_USER_INPUT,
          "%s: the model needs about %.3g GB on a node (%.3g cells, %.3g degrees of freedom at ~%.0f bytes each) but the node has %.3g GB available "
          "(/proc/meminfo MemAvailable); allowed: a smaller mesh, more nodes, or -memory_check false",
          what, needed_available[0] / 1e9, cells, dofs, kBytesPerDof, needed_available[1] / 1e9);
}

} // namespace slipwave::mesh

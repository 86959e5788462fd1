#include "slipwave/meshing/memory_estimate.hpp"

#include <fstream>
#include <sstream>
#include <string>

namespace slipwave::meshing {
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

// Gmsh ASCII header counts, read without loading the mesh: the dimension from $Entities
// (4.1; 2.2 has none and 2 is assumed, the smaller estimate) and the node count from the
// line after $Nodes. False for binary files and files without a $Nodes section.
bool gmshCounts(const std::string &path, PetscInt *dim, double *nodes) {
  std::ifstream in(path);
  std::string   line, version;
  int           binary = 0;
  *dim               = 2;
  while (std::getline(in, line)) {
    if (line.rfind("$MeshFormat", 0) == 0 && std::getline(in, line)) {
      std::istringstream f(line);
      f >> version >> binary;
      if (binary) return false;
    } else if (line.rfind("$Entities", 0) == 0 && std::getline(in, line)) {
      std::istringstream f(line);
      double             points = 0, curves = 0, surfaces = 0, volumes = 0;
      f >> points >> curves >> surfaces >> volumes;
      if (volumes > 0) *dim = 3;
    } else if (line.rfind("$Nodes", 0) == 0 && std::getline(in, line)) {
      std::istringstream f(line);
      double             first = 0, second = 0;
      f >> first;
      // 4.1: numEntityBlocks numNodes minTag maxTag; 2.2: numNodes.
      *nodes = version.rfind("4", 0) == 0 && f >> second ? second : first;
      return true;
    }
  }
  return false;
}

} // namespace

std::string MeshFileDescription(const char *file, PetscInt refine) {
  return "-mesh_file = " + std::string(file) + (refine > 0 ? " refined " + std::to_string(refine) + " times" : "");
}

PetscErrorCode MemoryCheckGmshFile(MPI_Comm comm, const char *file, PetscInt refine, bool whole_on_rank0) {
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  double counts[2] = {0, 0}; // dimension, nodes; 0 nodes: unknown
  if (rank == 0) {
    PetscInt dim   = 2;
    double   nodes = 0;
    if (gmshCounts(file, &dim, &nodes)) counts[0] = (double)dim, counts[1] = nodes;
  }
  PetscCallMPI(MPI_Bcast(counts, 2, MPI_DOUBLE, 0, comm));
  const PetscInt dim = (PetscInt)counts[0];
  if (counts[1] > 0) PetscCall(MemoryCheck(comm, counts[1] * RefinedPointFactor(dim, refine), dim, MeshFileDescription(file, refine).c_str(), whole_on_rank0));
  PetscFunctionReturn(0);
}

PetscErrorCode MemoryCheck(MPI_Comm comm, double nodes, PetscInt dim, const char *what, bool whole_on_rank0) {
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
  const double total = nodes * dim * kBytesPerDof;
  const double need  = holds_rank0 && whole_on_rank0 ? total : total * node_size / size;
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
          "%s: the model needs about %.3g GB on a node (%.3g nodes x %" PetscInt_FMT " components at ~%.0f bytes each) but the node has %.3g GB available "
          "(/proc/meminfo MemAvailable); allowed: a smaller mesh, more nodes, or -memory_check false",
          what, needed_available[0] / 1e9, nodes, dim, kBytesPerDof, needed_available[1] / 1e9);
}

} // namespace slipwave::meshing

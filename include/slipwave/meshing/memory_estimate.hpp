// Refuses a mesh the machine cannot hold, before it is built: the model's memory is
// estimated from its degrees of freedom and compared with what /proc/meminfo calls
// MemAvailable on each node. Rank 0 builds (or reads) the whole serial mesh before it is
// distributed, so its node must hold all of it; every other node its ranks' share.
// Option: -memory_check (default true; false skips the check, for a machine whose
// /proc/meminfo does not tell the truth, e.g. with swap or overcommit to rely on).
#pragma once
#include <petscsys.h>

#include <string>

namespace slipwave::meshing {

// Measured resident memory per degree of freedom after setup (dry runs of boxes, 2D
// 200^2 -> 400^2 quadrilaterals: 520 B; 3D 20^3 -> 40^3 hexahedra: 640 B), rounded up for
// the serial mesh that exists beside the distributed one during setup.
constexpr double kBytesPerDof = 1024;

// nodes x dim degrees of freedom; what: the option and value the mesh comes from, for the
// message; whole_on_rank0 false: a mesh refined on the distributed mesh (box_refinement.hpp,
// mesh_refinement.hpp), where rank 0's
// node needs its ranks' share only, as every other node.
PetscErrorCode MemoryCheck(MPI_Comm comm, double nodes, PetscInt dim, const char *what, bool whole_on_rank0 = true);

// The same for a Gmsh file, from the node count in its header, before the file is loaded
// (ASCII files; a binary one is checked by the caller once loaded), refined `refine` times
// (-mesh_refine; whole_on_rank0 false: refined on the distributed mesh).
PetscErrorCode MemoryCheckGmshFile(MPI_Comm comm, const char *file, PetscInt refine = 0, bool whole_on_rank0 = true);

// Uniform refinement (mesh_refinement.hpp) multiplies the points of every depth by about
// 2^dim per level; those on the boundary by less, so this is an upper estimate.
inline double RefinedPointFactor(PetscInt dim, PetscInt levels) { return (double)((PetscInt64)1 << (dim * levels)); }

// "-mesh_file = <file>[ refined k times]", for the messages.
std::string MeshFileDescription(const char *file, PetscInt refine);

} // namespace slipwave::meshing

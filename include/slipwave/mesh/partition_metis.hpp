// A PetscPartitioner of type "metis" on top of serial METIS 5, because Debian's PETSc 3.18
// is built without METIS/ParMETIS. The cell graph, which
// may be spread over several ranks, is gathered on rank 0, partitioned there and the
// assignment is sent back; output follows PETSc's own partitioners, so
//   -petscpartitioner_type metis
// works with DMPlexDistribute once PartitionerRegisterMetis has been called.
//
// Options (read by PetscPartitionerSetFromOptions):
//   -petscpartitioner_metis_type <auto|kway|rb>  METIS_PartGraphKway or METIS_PartGraphRecursive;
//                                            auto (default): rb up to 8 parts (better balanced), kway above
//   -petscpartitioner_metis_ufactor <int>    allowed imbalance in 1/1000 (METIS default: 30 kway, 1 rb)
//   -petscpartitioner_metis_seed <int>       random seed (METIS default: -1, its own seed)
// Vertex weights (vertSection) and target part weights (targetSection) are passed to METIS.
#pragma once
#include <petscpartitioner.h>

namespace slipwave::mesh {

// Name of the partitioner type, for PetscPartitionerSetType.
inline constexpr const char *kPartitionerMetis = "metis";

// Registers the "metis" PetscPartitioner type. Safe to call more than once; call it after
// PetscInitialize and before any PetscPartitionerSetFromOptions that should see it.
PetscErrorCode PartitionerRegisterMetis();

} // namespace slipwave::mesh

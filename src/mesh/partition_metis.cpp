#include "slipwave/mesh/partition_metis.hpp"

#include <petsc/private/partitionerimpl.h>

#include <metis.h>

#include <algorithm>
#include <vector>

namespace slipwave::mesh {
namespace {

enum MetisMethod : PetscInt { kAuto = 0, kKway = 1, kRecursiveBisection = 2 };
const char *const kMethodNames[] = {"auto", "kway", "rb"};

// Up to this many parts "auto" uses recursive bisection: on box meshes of 40x20 and 8^3
// cells into 2, 3, 4, 8 parts it balanced to within 0.2% and cut at most one edge more than
// k-way (fewer at 4 and 8 parts), where k-way used up to its 3% allowance
// (tests/unit/test_partition_metis.cpp prints both).
constexpr PetscInt kMaxPartsRecursive = 8;

struct MetisSettings {
  PetscInt method = kAuto;
  PetscInt ufactor = -1; // -1: METIS' own default (30 for kway, 1 for rb)
  PetscInt seed = -1;    // -1: METIS' own default seed
};

PetscErrorCode PartitionerDestroyMetis(PetscPartitioner part) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree(part->data));
  PetscFunctionReturn(0);
}

PetscErrorCode PartitionerViewMetis(PetscPartitioner part, PetscViewer viewer) {
  const auto *settings = static_cast<const MetisSettings *>(part->data);
  PetscBool ascii = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(viewer), PETSCVIEWERASCII, &ascii));
  if (!ascii) PetscFunctionReturn(0);
  PetscCall(PetscViewerASCIIPushTab(viewer));
  PetscCall(PetscViewerASCIIPrintf(viewer, "METIS method: %s\n", kMethodNames[settings->method]));
  PetscCall(PetscViewerASCIIPrintf(viewer, "METIS ufactor: %" PetscInt_FMT " (-1: METIS default)\n", settings->ufactor));
  PetscCall(PetscViewerASCIIPrintf(viewer, "METIS seed: %" PetscInt_FMT " (-1: METIS default)\n", settings->seed));
  PetscCall(PetscViewerASCIIPopTab(viewer));
  PetscFunctionReturn(0);
}

// The parameter name is fixed: PETSc's PetscOptions* macros refer to PetscOptionsObject.
PetscErrorCode PartitionerSetFromOptionsMetis(PetscPartitioner part, PetscOptionItems *PetscOptionsObject) {
  auto *settings = static_cast<MetisSettings *>(part->data);

  PetscFunctionBeginUser;
  PetscOptionsHeadBegin(PetscOptionsObject, "PetscPartitioner METIS options");
  PetscCall(PetscOptionsEList("-petscpartitioner_metis_type",
                              "METIS method: kway (METIS_PartGraphKway), rb (METIS_PartGraphRecursive, recursive bisection) or "
                              "auto (rb up to 8 parts, kway above)",
                              "PartitionerRegisterMetis", kMethodNames, 3, kMethodNames[settings->method], &settings->method, nullptr));
  PetscCall(PetscOptionsInt("-petscpartitioner_metis_ufactor",
                            "Allowed load imbalance in 1/1000: the largest part may hold (1000+ufactor)/1000 of the mean; -1 keeps "
                            "METIS' default (30 for kway, 1 for rb)",
                            "PartitionerRegisterMetis", settings->ufactor, &settings->ufactor, nullptr));
  PetscCall(PetscOptionsInt("-petscpartitioner_metis_seed", "Seed of METIS' random number generator; -1 keeps METIS' default",
                            "PartitionerRegisterMetis", settings->seed, &settings->seed, nullptr));
  PetscOptionsHeadEnd();
  PetscCheck(settings->ufactor == -1 || settings->ufactor >= 1, PetscObjectComm(reinterpret_cast<PetscObject>(part)),
             PETSC_ERR_USER_INPUT, "-petscpartitioner_metis_ufactor = %" PetscInt_FMT "; allowed: -1 (METIS default) or >= 1",
             settings->ufactor);
  PetscFunctionReturn(0);
}

// Part weights as fractions summing to one, from targetSection (dof of part p = its
// weight). METIS rejects a zero fraction, so empty targets get a tiny share.
PetscErrorCode TargetFractions(PetscSection target_section, PetscInt nparts, std::vector<real_t> &fractions) {
  PetscFunctionBeginUser;
  PetscCallCXX(fractions.assign(static_cast<size_t>(nparts), static_cast<real_t>(1.0 / nparts)));
  if (!target_section) PetscFunctionReturn(0);
  std::vector<PetscInt> weights;
  PetscCallCXX(weights.resize(static_cast<size_t>(nparts)));
  PetscInt sum = 0;
  for (PetscInt p = 0; p < nparts; ++p) {
    PetscCall(PetscSectionGetDof(target_section, p, &weights[p]));
    sum += weights[p];
  }
  if (sum <= 0) PetscFunctionReturn(0); // no usable targets: equal parts
  const double tiny = 1e-6;
  double total = 0.0;
  for (PetscInt p = 0; p < nparts; ++p) total += std::max(static_cast<double>(weights[p]) / sum, tiny);
  for (PetscInt p = 0; p < nparts; ++p)
    fractions[p] = static_cast<real_t>(std::max(static_cast<double>(weights[p]) / sum, tiny) / total);
  PetscFunctionReturn(0);
}

// Partitions the whole graph on rank 0. The local rows of every rank are gathered there in
// rank order; their column ids are already global in that order (the numbering
// DMPlexCreatePartitionerGraph and ParMETIS' vtxdist use), so the gathered CSR is the
// global graph as is.
PetscErrorCode PartitionerPartitionMetis(PetscPartitioner part, PetscInt nparts, PetscInt num_vertices, PetscInt start[],
                                         PetscInt adjacency[], PetscSection vert_section, PetscSection target_section,
                                         PetscSection part_section, IS *partition) {
  const auto *settings = static_cast<const MetisSettings *>(part->data);
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(part));
  PetscMPIInt size = 0, rank = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));

  // Per-rank vertex and edge counts, and whether any rank has vertex weights.
  PetscMPIInt local_vertices = 0, local_edges = 0;
  PetscCall(PetscMPIIntCast(num_vertices, &local_vertices));
  PetscCall(PetscMPIIntCast(num_vertices > 0 ? start[num_vertices] - start[0] : 0, &local_edges));
  std::vector<PetscMPIInt> vertex_counts, edge_counts, vertex_offsets, edge_offsets;
  PetscCallCXX(vertex_counts.resize(static_cast<size_t>(size)));
  PetscCallCXX(edge_counts.resize(static_cast<size_t>(size)));
  PetscCallMPI(MPI_Allgather(&local_vertices, 1, MPI_INT, vertex_counts.data(), 1, MPI_INT, comm));
  PetscCallMPI(MPI_Allgather(&local_edges, 1, MPI_INT, edge_counts.data(), 1, MPI_INT, comm));
  PetscCallCXX(vertex_offsets.assign(static_cast<size_t>(size) + 1, 0));
  PetscCallCXX(edge_offsets.assign(static_cast<size_t>(size) + 1, 0));
  for (PetscMPIInt r = 0; r < size; ++r) {
    vertex_offsets[r + 1] = vertex_offsets[r] + vertex_counts[r];
    edge_offsets[r + 1] = edge_offsets[r] + edge_counts[r];
  }
  const PetscInt total_vertices = vertex_offsets[size];
  int has_weights = vert_section ? 1 : 0;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &has_weights, 1, MPI_INT, MPI_LOR, comm));

  // Local rows as METIS index type: degrees, neighbours, weights.
  std::vector<idx_t> degrees, neighbours, weights;
  PetscCallCXX(degrees.resize(static_cast<size_t>(num_vertices)));
  PetscCallCXX(neighbours.resize(static_cast<size_t>(local_edges)));
  for (PetscInt v = 0; v < num_vertices; ++v) degrees[v] = static_cast<idx_t>(start[v + 1] - start[v]);
  for (PetscMPIInt e = 0; e < local_edges; ++e) neighbours[e] = static_cast<idx_t>(adjacency[start[0] + e]);
  if (has_weights) {
    PetscCallCXX(weights.assign(static_cast<size_t>(num_vertices), 1));
    for (PetscInt v = 0; v < num_vertices && vert_section; ++v) {
      PetscInt w = 0;
      PetscCall(PetscSectionGetDof(vert_section, v, &w));
      weights[v] = static_cast<idx_t>(w);
    }
  }

  // Global graph and assignment on rank 0.
  const bool root = rank == 0;
  std::vector<idx_t> xadj, adjncy, vwgt, global_assignment;
  if (root) {
    PetscCallCXX(xadj.assign(static_cast<size_t>(total_vertices) + 1, 0));
    PetscCallCXX(adjncy.resize(static_cast<size_t>(edge_offsets[size])));
    PetscCallCXX(global_assignment.assign(static_cast<size_t>(total_vertices), 0));
    if (has_weights) PetscCallCXX(vwgt.resize(static_cast<size_t>(total_vertices)));
  }
  static_assert(sizeof(idx_t) == sizeof(int), "METIS idx_t is gathered as MPI_INT");
  PetscCallMPI(MPI_Gatherv(degrees.data(), local_vertices, MPI_INT, root ? xadj.data() + 1 : nullptr, vertex_counts.data(),
                           vertex_offsets.data(), MPI_INT, 0, comm));
  PetscCallMPI(MPI_Gatherv(neighbours.data(), local_edges, MPI_INT, adjncy.data(), edge_counts.data(), edge_offsets.data(),
                           MPI_INT, 0, comm));
  if (has_weights)
    PetscCallMPI(MPI_Gatherv(weights.data(), local_vertices, MPI_INT, vwgt.data(), vertex_counts.data(), vertex_offsets.data(),
                             MPI_INT, 0, comm));

  int status = METIS_OK;
  idx_t edge_cut = 0;
  PetscReal balance = 1.0;
  if (root && total_vertices > 0) {
    for (PetscInt v = 0; v < total_vertices; ++v) xadj[v + 1] += xadj[v];
    if (nparts > 1) {
      std::vector<real_t> fractions;
      PetscCall(TargetFractions(target_section, nparts, fractions));
      idx_t options[METIS_NOPTIONS];
      METIS_SetDefaultOptions(options);
      if (settings->ufactor > 0) options[METIS_OPTION_UFACTOR] = static_cast<idx_t>(settings->ufactor);
      options[METIS_OPTION_SEED] = static_cast<idx_t>(settings->seed);
      idx_t n = static_cast<idx_t>(total_vertices), ncon = 1, np = static_cast<idx_t>(nparts);
      const bool bisect =
          settings->method == kRecursiveBisection || (settings->method == kAuto && nparts <= kMaxPartsRecursive);
      auto method = bisect ? METIS_PartGraphRecursive : METIS_PartGraphKway;
      status = method(&n, &ncon, xadj.data(), adjncy.data(), has_weights ? vwgt.data() : nullptr, nullptr, nullptr, &np,
                      fractions.data(), nullptr, options, &edge_cut, global_assignment.data());
    }
    // Ratio of the heaviest to the lightest part, what PetscPartitioner reports as balance.
    std::vector<double> load;
    PetscCallCXX(load.assign(static_cast<size_t>(nparts), 0.0));
    for (PetscInt v = 0; v < total_vertices; ++v) load[global_assignment[v]] += has_weights ? vwgt[v] : 1.0;
    const double lightest = *std::min_element(load.begin(), load.end());
    balance = lightest > 0 ? *std::max_element(load.begin(), load.end()) / lightest : PETSC_INFINITY;
  }
  // Every rank learns the outcome before checking it, so a METIS failure stops all ranks.
  PetscCallMPI(MPI_Bcast(&status, 1, MPI_INT, 0, comm));
  PetscCheck(status == METIS_OK, comm, PETSC_ERR_LIB, "METIS partitioning of %" PetscInt_FMT " vertices into %" PetscInt_FMT
             " parts failed with code %d", total_vertices, nparts, status);
  PetscCallMPI(MPI_Bcast(&edge_cut, 1, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(&balance, 1, MPIU_REAL, 0, comm));
  part->edgeCut = static_cast<PetscInt>(edge_cut);
  part->balance = balance;

  std::vector<idx_t> assignment;
  PetscCallCXX(assignment.resize(static_cast<size_t>(num_vertices)));
  PetscCallMPI(MPI_Scatterv(global_assignment.data(), vertex_counts.data(), vertex_offsets.data(), MPI_INT, assignment.data(),
                            local_vertices, MPI_INT, 0, comm));

  // As PETSc's partitioners: partSection holds how many local vertices go to each part, the
  // IS lists the local vertex numbers grouped by target part (counting sort keeps them
  // ascending within a part).
  std::vector<PetscInt> first;
  PetscCallCXX(first.assign(static_cast<size_t>(nparts) + 1, 0));
  for (PetscInt v = 0; v < num_vertices; ++v) {
    PetscCall(PetscSectionAddDof(part_section, assignment[v], 1));
    ++first[assignment[v] + 1];
  }
  for (PetscInt p = 0; p < nparts; ++p) first[p + 1] += first[p];
  PetscInt *points = nullptr;
  PetscCall(PetscMalloc1(num_vertices, &points));
  for (PetscInt v = 0; v < num_vertices; ++v) points[first[assignment[v]]++] = v;
  PetscCall(ISCreateGeneral(comm, num_vertices, points, PETSC_OWN_POINTER, partition));
  PetscFunctionReturn(0);
}

PetscErrorCode PartitionerCreateMetis(PetscPartitioner part) {
  MetisSettings *settings = nullptr;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&settings));
  *settings = MetisSettings{};
  part->data = settings;
  part->noGraph = PETSC_FALSE;
  part->ops->view = PartitionerViewMetis;
  part->ops->setfromoptions = PartitionerSetFromOptionsMetis;
  part->ops->destroy = PartitionerDestroyMetis;
  part->ops->partition = PartitionerPartitionMetis;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode PartitionerRegisterMetis() {
  PetscFunctionBeginUser;
  PetscCall(PetscPartitionerRegister(kPartitionerMetis, PartitionerCreateMetis));
  PetscFunctionReturn(0);
}

} // namespace slipwave::mesh

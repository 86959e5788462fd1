// The "metis" PetscPartitioner on DMPlex box meshes.
//   test_partition_metis               one rank: partitions cell graphs, checks coverage, balance, edge cut
//   test_partition_metis -distribute   any number of ranks: DMPlexDistribute with the options given
//                                      (tests/cases/partition_metis_mpi.sh passes -petscpartitioner_type metis),
//                                      then redistributes the distributed mesh, so the graph METIS sees is
//                                      spread over the ranks; every rank must own cells after each step.
#include "slipwave/mesh/partition_metis.hpp"

#include "petsc_test_main.hpp"

#include <petscdmplex.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct Graph {
  PetscInt num_vertices = 0;
  PetscInt *offsets = nullptr;
  PetscInt *adjacency = nullptr;
};

struct Outcome {
  bool each_once = false;         // every vertex in exactly one part
  std::vector<PetscInt> part_of;  // part of each vertex
  std::vector<double> load;       // (weighted) size of each part
  PetscInt edge_cut = 0;          // graph edges between different parts
};

PetscErrorCode CreateBox(MPI_Comm comm, PetscInt dim, const PetscInt faces[], DM *dm) {
  PetscFunctionBeginUser;
  PetscCall(DMPlexCreateBoxMesh(comm, dim, PETSC_FALSE, faces, nullptr, nullptr, nullptr, PETSC_TRUE, dm));
  PetscFunctionReturn(0);
}

PetscErrorCode GraphCreate(DM dm, Graph *graph) {
  PetscFunctionBeginUser;
  PetscCall(DMPlexCreatePartitionerGraph(dm, 0, &graph->num_vertices, &graph->offsets, &graph->adjacency, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode GraphDestroy(Graph *graph) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree(graph->offsets));
  PetscCall(PetscFree(graph->adjacency));
  PetscFunctionReturn(0);
}

// Runs a partitioner of `type` (options from the database) and reads back its answer.
PetscErrorCode Partition(const char *type, const Graph &graph, PetscInt nparts, PetscSection weights, PetscSection targets,
                         Outcome *out) {
  PetscPartitioner part = nullptr;
  PetscSection part_section = nullptr;
  IS is = nullptr;

  PetscFunctionBeginUser;
  PetscCall(PetscPartitionerCreate(PETSC_COMM_WORLD, &part));
  PetscCall(PetscPartitionerSetType(part, type));
  PetscCall(PetscPartitionerSetFromOptions(part));
  PetscCall(PetscSectionCreate(PETSC_COMM_WORLD, &part_section));
  PetscCall(PetscPartitionerPartition(part, nparts, graph.num_vertices, graph.offsets, graph.adjacency, weights, targets,
                                      part_section, &is));
  PetscInt n = 0;
  const PetscInt *points = nullptr;
  PetscCall(ISGetLocalSize(is, &n));
  PetscCall(ISGetIndices(is, &points));
  out->part_of.assign(static_cast<size_t>(graph.num_vertices), -1);
  out->load.assign(static_cast<size_t>(nparts), 0.0);
  bool each_once = n == graph.num_vertices;
  for (PetscInt p = 0; p < nparts && each_once; ++p) {
    PetscInt dof = 0, off = 0;
    PetscCall(PetscSectionGetDof(part_section, p, &dof));
    PetscCall(PetscSectionGetOffset(part_section, p, &off));
    for (PetscInt i = off; i < off + dof && each_once; ++i) {
      const PetscInt v = points[i];
      each_once = v >= 0 && v < graph.num_vertices && out->part_of[v] == -1;
      if (!each_once) break;
      out->part_of[v] = p;
      PetscInt w = 1;
      if (weights) PetscCall(PetscSectionGetDof(weights, v, &w));
      out->load[p] += w;
    }
  }
  out->each_once = each_once && std::count(out->part_of.begin(), out->part_of.end(), -1) == 0;
  PetscCall(ISRestoreIndices(is, &points));
  out->edge_cut = 0;
  for (PetscInt v = 0; v < graph.num_vertices && out->each_once; ++v)
    for (PetscInt e = graph.offsets[v]; e < graph.offsets[v + 1]; ++e)
      if (graph.adjacency[e] > v && out->part_of[graph.adjacency[e]] != out->part_of[v]) ++out->edge_cut;
  PetscCall(ISDestroy(&is));
  PetscCall(PetscSectionDestroy(&part_section));
  PetscCall(PetscPartitionerDestroy(&part));
  PetscFunctionReturn(0);
}

// Tolerance of a ratio compared with a bound it may equal exactly (103 cells / 100 mean = 1.03).
constexpr double kRoundoff = 1e-12;

double MaxOverMean(const Outcome &o) {
  double total = 0.0;
  for (double l : o.load) total += l;
  return *std::max_element(o.load.begin(), o.load.end()) / (total / o.load.size());
}

// Partitions the cell graph of a box mesh into 2, 3, 4, 8 parts, checks METIS' answer and
// prints how METIS k-way and PETSc's "simple" partitioner compare.
PetscErrorCode CheckBox(PetscInt dim, const PetscInt faces[], PetscInt slab_cut) {
  DM dm = nullptr;
  Graph graph;
  const std::string mesh = dim == 2 ? std::to_string(faces[0]) + "x" + std::to_string(faces[1])
                                    : std::to_string(faces[0]) + "x" + std::to_string(faces[1]) + "x" + std::to_string(faces[2]);

  PetscFunctionBeginUser;
  PetscCall(CreateBox(PETSC_COMM_WORLD, dim, faces, &dm));
  PetscCall(GraphCreate(dm, &graph));
  for (PetscInt nparts : {2, 3, 4, 8}) {
    Outcome metis, kway, simple;
    PetscCall(Partition(slipwave::mesh::kPartitionerMetis, graph, nparts, nullptr, nullptr, &metis));
    PetscCall(PetscOptionsSetValue(nullptr, "-petscpartitioner_metis_type", "kway"));
    PetscCall(Partition(slipwave::mesh::kPartitionerMetis, graph, nparts, nullptr, nullptr, &kway));
    PetscCall(PetscOptionsClearValue(nullptr, "-petscpartitioner_metis_type"));
    PetscCall(Partition(PETSCPARTITIONERSIMPLE, graph, nparts, nullptr, nullptr, &simple));
    const std::string what = mesh + " into " + std::to_string(nparts) + " parts";
    std::printf("# %s: metis (default) max/mean %.4f cut %d | metis kway max/mean %.4f cut %d | simple max/mean %.4f cut %d\n",
                what.c_str(), MaxOverMean(metis), static_cast<int>(metis.edge_cut), MaxOverMean(kway),
                static_cast<int>(kway.edge_cut), MaxOverMean(simple), static_cast<int>(simple.edge_cut));
    unit::check(metis.each_once && kway.each_once, what + ": every cell assigned exactly once");
    // METIS 5.1 manual, METIS_OPTION_UFACTOR: default 30 (imbalance 1.03) for k-way, 1 (1.001 per
    // bisection) for recursive bisection; 1.03 bounds both.
    unit::check(MaxOverMean(metis) <= 1.03 + kRoundoff, what + ": default (auto) max part / mean <= 1.03");
    unit::check(MaxOverMean(kway) <= 1.03 + kRoundoff, what + ": kway max part / mean <= 1.03 (METIS default ufactor 30)");
    // Straight cuts into slabs along the longest side cut (nparts-1)*slab_cut edges. METIS'
    // multilevel heuristic leaves jagged but short borders; 1.5x that leaves room for them
    // across METIS versions while a broken partitioner (a random one cuts about half of
    // all edges) fails by far.
    const double bound = 1.5 * static_cast<double>((nparts - 1) * slab_cut);
    unit::check(metis.edge_cut <= bound, what + ": edge cut " + std::to_string(metis.edge_cut) + " <= 1.5 x slab cut (" +
                                             std::to_string(static_cast<int>(bound)) + ")");
  }

  // nparts = 1: everything in part 0.
  Outcome one;
  PetscCall(Partition(slipwave::mesh::kPartitionerMetis, graph, 1, nullptr, nullptr, &one));
  unit::check(one.each_once && one.load[0] == graph.num_vertices, mesh + " into 1 part: all cells in part 0");

  // Vertex weights: the first half of the cells (by number) weigh 3, the rest 1; METIS must
  // balance the weight, not the count.
  PetscSection weights = nullptr;
  PetscCall(PetscSectionCreate(PETSC_COMM_SELF, &weights));
  PetscCall(PetscSectionSetChart(weights, 0, graph.num_vertices));
  for (PetscInt v = 0; v < graph.num_vertices; ++v) PetscCall(PetscSectionSetDof(weights, v, v < graph.num_vertices / 2 ? 3 : 1));
  PetscCall(PetscSectionSetUp(weights));
  Outcome weighted;
  PetscCall(Partition(slipwave::mesh::kPartitionerMetis, graph, 2, weights, nullptr, &weighted));
  std::printf("# %s weighted 3:1 into 2: load %g / %g, cells %d / %d\n", mesh.c_str(), weighted.load[0], weighted.load[1],
              static_cast<int>(std::count(weighted.part_of.begin(), weighted.part_of.end(), 0)),
              static_cast<int>(std::count(weighted.part_of.begin(), weighted.part_of.end(), 1)));
  unit::check(weighted.each_once && MaxOverMean(weighted) <= 1.03 + kRoundoff, mesh + ": vertex weights balanced to <= 1.03");
  PetscCall(PetscSectionDestroy(&weights));

  // Target part weights 1:3: part 1 should get three quarters of the cells.
  PetscSection targets = nullptr;
  PetscCall(PetscSectionCreate(PETSC_COMM_SELF, &targets));
  PetscCall(PetscSectionSetChart(targets, 0, 2));
  PetscCall(PetscSectionSetDof(targets, 0, 1));
  PetscCall(PetscSectionSetDof(targets, 1, 3));
  PetscCall(PetscSectionSetUp(targets));
  Outcome targeted;
  PetscCall(Partition(slipwave::mesh::kPartitionerMetis, graph, 2, nullptr, targets, &targeted));
  const double share = targeted.load[1] / graph.num_vertices;
  std::printf("# %s targets 1:3: part 1 holds %.4f of the cells\n", mesh.c_str(), share);
  unit::check(targeted.each_once && share >= 0.75 / 1.03 && share <= 0.75 * 1.03, mesh + ": target weights 1:3 met within 3%");
  PetscCall(PetscSectionDestroy(&targets));

  PetscCall(GraphDestroy(&graph));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

PetscErrorCode CheckEmptyGraph() {
  Graph graph;
  PetscInt zero = 0;
  Outcome out;

  PetscFunctionBeginUser;
  graph.offsets = &zero;
  PetscCall(Partition(slipwave::mesh::kPartitionerMetis, graph, 3, nullptr, nullptr, &out));
  unit::check(out.each_once && out.part_of.empty(), "empty graph into 3 parts: empty partition");
  PetscFunctionReturn(0);
}

PetscErrorCode CountCells(DM dm, PetscInt *local, PetscInt *fewest, PetscInt *total) {
  PetscInt start = 0, end = 0;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &start, &end));
  *local = end - start;
  PetscCallMPI(MPI_Allreduce(local, fewest, 1, MPIU_INT, MPI_MIN, PetscObjectComm(reinterpret_cast<PetscObject>(dm))));
  PetscCallMPI(MPI_Allreduce(local, total, 1, MPIU_INT, MPI_SUM, PetscObjectComm(reinterpret_cast<PetscObject>(dm))));
  PetscFunctionReturn(0);
}

// Distributes a 40x20 box mesh (serial on rank 0) with the partitioner chosen by the
// options, then redistributes the result, and prints each rank's cell count.
PetscErrorCode Distribute() {
  const PetscInt faces[2] = {40, 20};
  DM dm = nullptr, dist = nullptr;
  PetscPartitioner part = nullptr;
  PetscMPIInt rank = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCall(CreateBox(PETSC_COMM_WORLD, 2, faces, &dm));
  for (int round = 0; round < 2; ++round) {
    PetscCall(DMPlexGetPartitioner(dm, &part));
    PetscCall(PetscPartitionerSetFromOptions(part));
    PetscPartitionerType type_name = nullptr;
    PetscCall(PetscPartitionerGetType(part, &type_name));
    const std::string type = type_name; // the partitioner goes away with the serial mesh
    PetscCall(DMPlexDistribute(dm, 0, nullptr, &dist));
    if (dist) {
      PetscCall(DMDestroy(&dm));
      dm = dist;
      dist = nullptr;
    }
    PetscInt local = 0, fewest = 0, total = 0;
    PetscCall(CountCells(dm, &local, &fewest, &total));
    PetscCall(PetscSynchronizedPrintf(PETSC_COMM_WORLD, "# %s round %d (partitioner %s): rank %d owns %d cells\n",
                                      round == 0 ? "distribute" : "redistribute", round, type.c_str(), rank, static_cast<int>(local)));
    PetscCall(PetscSynchronizedFlush(PETSC_COMM_WORLD, PETSC_STDOUT));
    const std::string what = std::string(round == 0 ? "distribute" : "redistribute") + " with " + type;
    if (rank == 0) {
      unit::check(type == slipwave::mesh::kPartitionerMetis, what + ": partitioner is metis");
      unit::check(fewest > 0, what + ": every rank owns cells");
      unit::check(total == faces[0] * faces[1], what + ": all 800 cells kept");
    }
  }
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

PetscErrorCode Run(bool distribute) {
  PetscFunctionBeginUser;
  PetscCall(slipwave::mesh::PartitionerRegisterMetis());
  if (distribute) {
    PetscCall(Distribute());
    PetscFunctionReturn(0);
  }
  const PetscInt faces2[2] = {40, 20}, faces3[3] = {8, 8, 8};
  PetscCall(CheckBox(2, faces2, 20)); // a straight cut across the 40x20 grid crosses 20 cell faces
  PetscCall(CheckBox(3, faces3, 64)); // a plane through the 8x8x8 grid crosses 64 cell faces
  PetscCall(CheckEmptyGraph());
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char **argv) { return unit::runPetscTest(argc, argv, Run); }

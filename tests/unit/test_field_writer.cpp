// FieldWriter on hand-made grids (no DM): two quads in 2D, one hex in 3D and a 2-segment
// polyline grid named "interface" in 2D, three output steps each, on any number of ranks
// (rows split evenly, so with 2 ranks the hex's only cell lives on rank 0 and rank 1 writes
// no cell rows). Reads the HDF5 back with VecLoad
// and checks the padding of 2D data, the symmetric tensors expanded to 3x3, and that only
// final names are left (every file written under a partial name is renamed when complete).
//   test_field_writer [-output_dir DIR]   (default build/tests/field_writer)
// writes DIR/quad2d/volume.{h5,xmf} + volume/0000NN.h5, DIR/hex3d/volume..., DIR/line2d/interface...;
// tests/cases/field_writer_parallel.sh checks them with scripts/check_output.py.
#include "slipwave/io/field_writer.hpp"

#include "unit_check.hpp"

#include <petscviewerhdf5.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using slipwave::io::Centering;
using slipwave::io::FieldRef;
using slipwave::io::FieldWriter;
using slipwave::io::GridLayout;

const PetscInt kSteps[3] = {0, 10, 20}; // output step numbers need not be consecutive
const PetscReal kTimes[3] = {0.0, 0.25, 0.5};

// Rows [first, first + count) of `total` on this rank: an even split, remainder first.
void LocalRows(PetscInt total, PetscInt *first, PetscInt *count) {
  PetscMPIInt rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  const PetscInt base = total / size, extra = total % size;
  *count = base + (rank < extra ? 1 : 0);
  *first = rank * base + (rank < extra ? rank : extra);
}

// Global Vec of `rows` blocks of `bs`, entry (r, k) = value(r, k).
template <class Value>
PetscErrorCode RowVec(PetscInt rows, PetscInt bs, Value value, Vec *v) {
  PetscInt first = 0, count = 0;
  PetscScalar *a = nullptr;

  PetscFunctionBeginUser;
  LocalRows(rows, &first, &count);
  PetscCall(VecCreate(PETSC_COMM_WORLD, v));
  PetscCall(VecSetSizes(*v, count * bs, rows * bs));
  PetscCall(VecSetBlockSize(*v, bs));
  PetscCall(VecSetType(*v, VECSTANDARD));
  PetscCall(VecGetArray(*v, &a));
  for (PetscInt r = 0; r < count; ++r)
    for (PetscInt k = 0; k < bs; ++k) a[r * bs + k] = value(first + r, k);
  PetscCall(VecRestoreArray(*v, &a));
  PetscFunctionReturn(0);
}

// Reads dataset `path` of `h5` and returns all of it on every rank, row-major.
PetscErrorCode ReadAll(const std::string &h5, const std::string &group, const std::string &name, std::vector<double> *all) {
  PetscViewer viewer = nullptr;
  Vec v = nullptr, seq = nullptr;
  VecScatter to_all = nullptr;
  const PetscScalar *a = nullptr;
  PetscInt n = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5Open(PETSC_COMM_WORLD, h5.c_str(), FILE_MODE_READ, &viewer));
  PetscCall(PetscViewerHDF5PushGroup(viewer, group.c_str()));
  PetscCall(VecCreate(PETSC_COMM_WORLD, &v));
  PetscCall(PetscObjectSetName(reinterpret_cast<PetscObject>(v), name.c_str()));
  PetscCall(VecLoad(v, viewer));
  PetscCall(PetscViewerHDF5PopGroup(viewer));
  PetscCall(PetscViewerDestroy(&viewer));
  PetscCall(VecScatterCreateToAll(v, &to_all, &seq));
  PetscCall(VecScatterBegin(to_all, v, seq, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(to_all, v, seq, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetSize(seq, &n));
  PetscCall(VecGetArrayRead(seq, &a));
  all->assign(a, a + n);
  PetscCall(VecRestoreArrayRead(seq, &a));
  PetscCall(VecScatterDestroy(&to_all));
  PetscCall(VecDestroy(&seq));
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

// Field values: distinct per (step, row, component), so a misplaced entry shows.
double NodeValue(PetscInt s, PetscInt node, PetscInt k) { return 1000.0 * s + 10.0 * node + k + 0.5; }
double CellValue(PetscInt s, PetscInt cell, PetscInt k) { return -(1000.0 * s + 10.0 * cell + k + 0.25); }

struct Mesh {
  std::string label;
  GridLayout layout;
  std::vector<double> coordinates; // dim per node
  std::vector<PetscInt> cells;     // nodes_per_cell per cell
};

Mesh TwoQuads() {
  // 3---4---5
  // |   |   |
  // 0---1---2   counter-clockwise quads, XDMF/VTK node order
  return {"2D two quads", {"volume", 2, "Quadrilateral", 4}, {0, 0, 1, 0, 2, 0, 0, 1, 1, 1, 2, 1}, {0, 1, 4, 3, 1, 2, 5, 4}};
}

// An interface as 2-node lines in 2D: 0---1---2
Mesh ThreeNodeLine() { return {"2D polyline", {"interface", 2, "Polyline", 2}, {0, 0, 1, 0.5, 2, 0}, {0, 1, 1, 2}}; }

Mesh OneHex() {
  return {"3D one hex",
          {"volume", 3, "Hexahedron", 8},
          {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1},
          {0, 1, 2, 3, 4, 5, 6, 7}};
}

PetscErrorCode WriteAndCheck(const Mesh &mesh, const std::string &dir) {
  const int dim = mesh.layout.dim, npc = mesh.layout.nodes_per_cell;
  const PetscInt num_nodes = static_cast<PetscInt>(mesh.coordinates.size()) / dim;
  const PetscInt num_cells = static_cast<PetscInt>(mesh.cells.size()) / npc;
  Vec geometry = nullptr, displacement = nullptr, pressure = nullptr, stress = nullptr, damage = nullptr;
  IS topology = nullptr;
  FieldWriter writer;

  PetscFunctionBeginUser;
  PetscCall(RowVec(num_nodes, dim, [&](PetscInt n, PetscInt k) { return mesh.coordinates[n * dim + k]; }, &geometry));
  PetscInt first = 0, count = 0;
  LocalRows(num_cells, &first, &count);
  PetscCall(ISCreateGeneral(PETSC_COMM_WORLD, count * npc, mesh.cells.data() + first * npc, PETSC_COPY_VALUES, &topology));

  PetscCall(writer.Open(PETSC_COMM_WORLD, dir, mesh.layout, geometry, topology));
  for (int i = 0; i < 3; ++i) {
    const PetscInt s = kSteps[i];
    PetscCall(RowVec(num_nodes, dim, [s](PetscInt n, PetscInt k) { return NodeValue(s, n, k); }, &displacement));
    PetscCall(RowVec(num_nodes, 1, [s](PetscInt n, PetscInt k) { return NodeValue(s, n, k); }, &pressure));
    PetscCall(RowVec(num_cells, 6, [s](PetscInt c, PetscInt k) { return CellValue(s, c, k); }, &stress));
    PetscCall(RowVec(num_cells, 1, [s](PetscInt c, PetscInt k) { return CellValue(s, c, k); }, &damage));
    PetscCall(writer.WriteStep(s, kTimes[i],
                               {{"displacement", Centering::Node, displacement},
                                {"pressure", Centering::Node, pressure},
                                {"stress", Centering::Cell, stress},
                                {"damage", Centering::Cell, damage}}));
    PetscCall(VecDestroy(&displacement));
    PetscCall(VecDestroy(&pressure));
    PetscCall(VecDestroy(&stress));
    PetscCall(VecDestroy(&damage));
  }

  // A step that does not advance is refused, on every rank, without writing anything.
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  const PetscErrorCode repeated = writer.WriteStep(kSteps[2], kTimes[2], {});
  PetscCall(PetscPopErrorHandler());
  unit::check(repeated == PETSC_ERR_ARG_WRONG, mesh.label + ": a repeated step is refused");
  PetscCall(writer.Close());

  const std::string stem = dir + "/" + mesh.layout.name;
  const std::string h5 = stem + ".h5";
  std::vector<double> data;
  PetscCall(ReadAll(h5, "/", "geometry", &data));
  bool geometry_ok = data.size() == static_cast<size_t>(num_nodes * 3);
  for (PetscInt n = 0; n < num_nodes && geometry_ok; ++n)
    for (int k = 0; k < 3; ++k) geometry_ok = geometry_ok && data[n * 3 + k] == (k < dim ? mesh.coordinates[n * dim + k] : 0.0);
  unit::check(geometry_ok, mesh.label + ": /geometry holds x y z per node" + (dim == 2 ? " (z = 0)" : ""));

  PetscCall(ReadAll(stem + "/000010.h5", "/", "displacement", &data));
  bool vector_ok = data.size() == static_cast<size_t>(num_nodes * 3);
  for (PetscInt n = 0; n < num_nodes && vector_ok; ++n)
    for (int k = 0; k < 3; ++k) vector_ok = vector_ok && data[n * 3 + k] == (k < dim ? NodeValue(10, n, k) : 0.0);
  unit::check(vector_ok, mesh.label + ": node vector written with 3 components" + (dim == 2 ? " (z = 0)" : ""));

  PetscCall(ReadAll(stem + "/000020.h5", "/", "pressure", &data));
  bool scalar_ok = data.size() == static_cast<size_t>(num_nodes);
  for (PetscInt n = 0; n < num_nodes && scalar_ok; ++n) scalar_ok = data[n] == NodeValue(20, n, 0);
  unit::check(scalar_ok, mesh.label + ": node scalar written");

  // Ours xx,yy,zz,xy,yz,xz (k = 0..5) written as the row-major 3x3 xx,xy,xz / xy,yy,yz / xz,yz,zz.
  const PetscInt ours_at[9] = {0, 3, 5, 3, 1, 4, 5, 4, 2};
  PetscCall(ReadAll(stem + "/000020.h5", "/", "stress", &data));
  bool tensor_ok = data.size() == static_cast<size_t>(num_cells * 9);
  for (PetscInt c = 0; c < num_cells && tensor_ok; ++c)
    for (int j = 0; j < 9; ++j) tensor_ok = tensor_ok && data[c * 9 + j] == CellValue(20, c, ours_at[j]);
  unit::check(tensor_ok, mesh.label + ": cell tensor written as symmetric row-major 3x3");

  PetscMPIInt rank = 0;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  if (rank == 0) {
    std::ifstream in(stem + ".xmf");
    std::stringstream text;
    text << in.rdbuf();
    const std::string xmf = text.str();
    size_t times = 0;
    for (size_t at = xmf.find("<Time Value="); at != std::string::npos; at = xmf.find("<Time Value=", at + 1)) ++times;
    unit::check(times == 3, mesh.label + ": index lists 3 steps (" + std::to_string(times) + ")");
    std::vector<std::string> files;
    for (const auto &entry : std::filesystem::recursive_directory_iterator(dir)) files.push_back(entry.path().lexically_relative(dir).string());
    std::sort(files.begin(), files.end());
    const std::string name = mesh.layout.name;
    std::vector<std::string> expected = {name, name + "/000000.h5", name + "/000010.h5", name + "/000020.h5", name + ".h5", name + ".xmf"};
    std::sort(expected.begin(), expected.end());
    unit::check(files == expected, mesh.label + ": the folder holds the mesh file, 3 frame files and the index, no partial file");
    unit::check(xmf.find(">" + mesh.layout.name + "/000020.h5:/stress<") != std::string::npos &&
                    xmf.find("AttributeType=\"Tensor\" Center=\"Cell\"") != std::string::npos,
                mesh.label + ": index points at the step 20 stress as a cell Tensor");
  }

  PetscCall(ISDestroy(&topology));
  PetscCall(VecDestroy(&geometry));
  PetscFunctionReturn(0);
}

PetscErrorCode Run() {
  char dir[PETSC_MAX_PATH_LEN] = "build/tests/field_writer";

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-output_dir", dir, sizeof dir, nullptr));
  PetscCall(WriteAndCheck(TwoQuads(), std::string(dir) + "/quad2d"));
  PetscCall(WriteAndCheck(OneHex(), std::string(dir) + "/hex3d"));
  PetscCall(WriteAndCheck(ThreeNodeLine(), std::string(dir) + "/line2d"));
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char **argv) {
  PetscCall(PetscInitialize(&argc, &argv, nullptr, nullptr));
  const PetscErrorCode ierr = Run();
  unit::check(ierr == 0, "no PETSc error");
  PetscCall(PetscFinalize());
  return unit::failures();
}

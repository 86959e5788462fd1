#include "slipwave/mesh/cell_quality_check.hpp"

#include <climits>
#include <cstdio>
#include <functional>
#include <string>

#include "slipwave/core/option_choice.hpp"
#include "slipwave/mesh/cell_quality.hpp"
#include "slipwave/mesh/spectral_layout.hpp"

namespace slipwave::mesh {
namespace {

enum Mode { kError, kWarn, kOff };
const char *const kModeNames[] = {"error", "warn", "off"};

struct Thresholds {
  PetscInt  mode = kError;
  PetscReal max_aspect = 50, min_jacobian_ratio = 0.1;
};

PetscErrorCode readThresholds(MPI_Comm comm, Thresholds *t) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "Mesh quality", "slipwave");
  PetscCall(core::OptionsChoice(PetscOptionsObject, "-mesh_quality_check",
                                "what a distorted cell does: error, warn or off (inverted and degenerate cells always stop the run)", kModeNames, 3, &t->mode,
                                nullptr));
  PetscCall(PetscOptionsReal("-mesh_quality_max_aspect", "largest aspect ratio (longest edge over thickness; r for an r:1 rectangle) [-], 1 to 1e6",
                             "CellQualityCheck", t->max_aspect, &t->max_aspect, nullptr));
  PetscCall(PetscOptionsReal("-mesh_quality_min_jacobian_ratio", "smallest ratio of corner Jacobians min/max (1 for parallelograms) [-], 0 < r <= 1",
                             "CellQualityCheck", t->min_jacobian_ratio, &t->min_jacobian_ratio, nullptr));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

std::string describe(CellDefect d, const CellShapeQuality &q, const Thresholds &t) {
  char text[256];
  switch (d) {
  case CellDefect::Degenerate: return "is degenerate (zero area or volume)";
  case CellDefect::Inverted:
    std::snprintf(text, sizeof text, "is inverted (its Jacobian changes sign or vanishes at a corner: min/max corner Jacobian %.3g)", q.jacobian_ratio);
    return text;
  default:
    std::snprintf(text, sizeof text, "is distorted (aspect %.3g, limit -mesh_quality_max_aspect %g; corner Jacobian ratio %.3g, limit -mesh_quality_min_jacobian_ratio %g)",
                  q.aspect, (double)t.max_aspect, q.jacobian_ratio, (double)t.min_jacobian_ratio);
    return text;
  }
}

std::string coordinates(const double *cell, PetscInt nodes, PetscInt dim) {
  std::string text;
  for (PetscInt a = 0; a < nodes; ++a) {
    const double *x = cell + a * dim;
    char          one[96];
    if (dim == 2) std::snprintf(one, sizeof one, "%s(%g, %g)", a ? " " : "", x[0], x[1]);
    else std::snprintf(one, sizeof one, "%s(%g, %g, %g)", a ? " " : "", x[0], x[1], x[2]);
    text += one;
  }
  return text;
}

} // namespace

PetscErrorCode CellQualityCheck(DM dm, numerics::CellShape shape, PetscInt ncell, const CellCoordinates &cell_coords, const std::vector<PetscInt> &serial_cell) {
  const MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  Thresholds  t;
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCall(readThresholds(comm, &t));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  // The worst defect first (degenerate, inverted, distorted), then the lowest cell number.
  // The mesh is distributed without overlap: every local cell is this rank's own.
  struct {
    long key;
    int  rank;
  } first = {LONG_MAX, rank};
  std::string message;
  long        distorted = 0;
  for (PetscInt c = 0; c < ncell; ++c) {
    const CellShapeQuality q = cellShapeQuality(shape, cell_coords(c));
    const CellDefect       d = cellDefect(q, t.max_aspect, t.min_jacobian_ratio);
    if (d == CellDefect::None || (d == CellDefect::Distorted && t.mode == kOff)) continue;
    distorted += d == CellDefect::Distorted;
    const int  rank_of_defect = d == CellDefect::Degenerate ? 0 : d == CellDefect::Inverted ? 1 : 2;
    const long key            = rank_of_defect * (long)1e15 + serial_cell[c];
    if (key < first.key) {
      first.key = key;
      message   = "cell " + std::to_string(serial_cell[c]) + " at " + coordinates(cell_coords(c), numerics::cellNodeCount(shape), numerics::cellDimension(shape)) + " " + describe(d, q, t);
    }
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_LONG_INT, MPI_MINLOC, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &distorted, 1, MPI_LONG, MPI_SUM, comm));
  if (first.key == LONG_MAX) PetscFunctionReturn(0);
  // The owner of the first defect tells every rank, so rank 0 prints it.
  char text[1024] = "";
  if (rank == first.rank) std::snprintf(text, sizeof text, "%s", message.c_str());
  PetscCallMPI(MPI_Bcast(text, sizeof text, MPI_CHAR, first.rank, comm));
  const bool fatal = first.key < 2 * (long)1e15 || t.mode == kError;
  PetscCheck(!fatal, comm, PETSC_ERR_USER_INPUT, "mesh: %s; allowed: cells with positive Jacobians at every corner%s", text,
             first.key < 2 * (long)1e15 ? "" : ", or -mesh_quality_check warn to run with distorted cells");
  PetscCall(PetscPrintf(comm, "warning: mesh: %ld distorted cell(s), the first: %s\n", distorted, text));
  PetscFunctionReturn(0);
}

PetscErrorCode CellQualityCheckSerialMesh(DM dm) {
  PetscInt dim, c_start, c_end;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
  const PetscInt nen = dim == 2 ? 4 : 8;
  // The element frame is lexicographic; the kernels go around each face.
  const PetscInt        kernel_order[8] = {0, 1, 3, 2, 4, 5, 7, 6};
  std::vector<double>   coords((size_t)(c_end - c_start) * nen * dim);
  std::vector<PetscInt> serial_cell(c_end - c_start);
  mesh::VertexCoordinates vc;
  PetscCall(vc.Open(dm));
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscInt lex[8];
    PetscCall(mesh::SpectralCellFrame(dm, vc, c, lex));
    for (PetscInt a = 0; a < nen; ++a) PetscCall(vc.Get(lex[kernel_order[a]], &coords[((size_t)(c - c_start) * nen + a) * dim]));
    serial_cell[c - c_start] = c - c_start;
  }
  PetscCall(vc.Close());
  PetscCall(CellQualityCheck(dm, dim == 2 ? numerics::CellShape::Quad4 : numerics::CellShape::Hex8, c_end - c_start,
                       [&](PetscInt c) { return &coords[(size_t)c * nen * dim]; }, serial_cell));
  PetscFunctionReturn(0);
}

} // namespace slipwave::mesh

#include "slipwave/input/boundary_faces.hpp"

#include "slipwave/mesh/cell_vertices.hpp"
#include "slipwave/mesh/labels.hpp"
#include "slipwave/mesh/spectral_face_weights.hpp"
#include "slipwave/mesh/vertex_coordinates.hpp"
#include "slipwave/numerics/reference_cell.hpp"

namespace slipwave::input {

PetscErrorCode BoundaryFacesGet(DM dm, const std::string &name, std::vector<BoundaryFace> *faces) {
  DMLabel  label, region_label;
  PetscInt dim, f_start, f_end, v_start, v_end;
  IS       values_is;
  PetscFunctionBeginUser;
  faces->clear();
  PetscCall(DMGetLabel(dm, name.c_str(), &label));
  PetscCheck(label, PetscObjectComm((PetscObject)dm), PETSC_ERR_USER_INPUT, "boundary '%s' does not exist in the mesh; allowed: the boundary names the mesh defines (run with -dry_run to list them)",
             name.c_str());
  PetscCall(DMGetLabel(dm, mesh::kRegionLabel, &region_label));
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &f_start, &f_end));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v_start, &v_end));
  const mesh::SpectralLayout *spectral; // degree > 1: GLL face weights of the elements' sides
  PetscCall(mesh::SpectralLayoutOf(dm, &spectral));
  PetscInt c_start;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, nullptr));
  mesh::VertexCoordinates   coords;
  const mesh::CellVertices *cell_vertices;
  PetscCall(coords.Open(dm));
  PetscCall(mesh::CellVerticesOf(dm, &cell_vertices));

  PetscCall(DMLabelGetValueIS(label, &values_is));
  PetscInt        nvalues;
  const PetscInt *values;
  PetscCall(ISGetLocalSize(values_is, &nvalues));
  PetscCall(ISGetIndices(values_is, &values));
  for (PetscInt k = 0; k < nvalues; ++k) {
    IS              points_is;
    PetscInt        npoints;
    const PetscInt *points;
    PetscCall(DMLabelGetStratumIS(label, values[k], &points_is));
    if (!points_is) continue;
    PetscCall(ISGetLocalSize(points_is, &npoints));
    PetscCall(ISGetIndices(points_is, &points));
    for (PetscInt i = 0; i < npoints; ++i) {
      const PetscInt f = points[i];
      PetscInt       support_size;
      if (f < f_start || f >= f_end) continue;
      PetscCall(DMPlexGetSupportSize(dm, f, &support_size));
      if (support_size != 1) continue;
      BoundaryFace face;
      PetscInt    *closure = nullptr, nclosure;
      PetscCall(DMPlexGetTransitiveClosure(dm, f, PETSC_TRUE, &nclosure, &closure));
      for (PetscInt j = 0; j < nclosure; ++j)
        if (closure[2 * j] >= v_start && closure[2 * j] < v_end && face.nvert < numerics::kMaxFaceNodes) face.vertices[face.nvert++] = closure[2 * j];
      PetscCall(DMPlexRestoreTransitiveClosure(dm, f, PETSC_TRUE, &nclosure, &closure));
      double x[numerics::kMaxFaceNodes * 3];
      for (PetscInt a = 0; a < face.nvert; ++a) PetscCall(coords.Get(face.vertices[a], &x[a * dim]));
      const numerics::FaceShape shape = dim == 2 ? numerics::FaceShape::Seg2 : (face.nvert == 3 ? numerics::FaceShape::Tri3 : numerics::FaceShape::Quad4);
      const PetscInt *support;
      PetscCall(DMPlexGetSupport(dm, f, &support));
      if (spectral && spectral->degree > 1) PetscCall(mesh::SpectralFaceWeights(*spectral, coords, support[0] - c_start, face.nvert, face.vertices, face.weights));
      else numerics::faceLumpedWeights(shape, (int)dim, x, face.weights);
      numerics::faceNormal(shape, (int)dim, x, face.normal);
      // The normal points away from the cell's centroid (vertex averages, in closure order as
      // MeshPointCentroid sums them; the cell's vertices from the mesh's table).
      double         xc[3] = {0, 0, 0}, xf[3] = {0, 0, 0}, dot = 0, y[3];
      const PetscInt nc    = cell_vertices->per_cell;
      for (PetscInt a = 0; a < face.nvert; ++a)
        for (PetscInt d = 0; d < dim; ++d) xf[d] += x[a * dim + d] / face.nvert;
      for (PetscInt a = 0; a < nc; ++a) {
        PetscCall(coords.Get(cell_vertices->of(support[0] - c_start)[a], y));
        for (PetscInt d = 0; d < dim; ++d) xc[d] += y[d] / nc;
      }
      for (PetscInt d = 0; d < dim; ++d) dot += face.normal[d] * (xf[d] - xc[d]);
      if (dot < 0)
        for (PetscInt d = 0; d < dim; ++d) face.normal[d] = -face.normal[d];
      PetscCall(DMLabelGetValue(region_label, support[0], &face.region));
      faces->push_back(face);
    }
    PetscCall(ISRestoreIndices(points_is, &points));
    PetscCall(ISDestroy(&points_is));
  }
  PetscCall(ISRestoreIndices(values_is, &values));
  PetscCall(ISDestroy(&values_is));
  PetscCall(coords.Close());
  PetscFunctionReturn(0);
}

} // namespace slipwave::input

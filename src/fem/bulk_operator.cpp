#include "slipwave/fem/bulk_operator.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <unordered_map>

#include "slipwave/fem/geometry_key.hpp"
#include "slipwave/mesh/cell_vertices.hpp"
#include "slipwave/mesh/labels.hpp"
#include "slipwave/mesh/spectral_layout.hpp"
#include "slipwave/mesh/vertex_coordinates.hpp"
#include "slipwave/numerics/gll_basis.hpp"

namespace slipwave::fem {
namespace {

PetscErrorCode cellShapeOf(DM dm, PetscInt cell, CellShape *shape) {
  DMPolytopeType ct;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetCellType(dm, cell, &ct));
  switch (ct) {
  case DM_POLYTOPE_TRIANGLE: *shape = CellShape::Tri3; break;
  case DM_POLYTOPE_QUADRILATERAL: *shape = CellShape::Quad4; break;
  case DM_POLYTOPE_TETRAHEDRON: *shape = CellShape::Tet4; break;
  case DM_POLYTOPE_HEXAHEDRON: *shape = CellShape::Hex8; break;
  default: SETERRQ(PetscObjectComm((PetscObject)dm), PETSC_ERR_SUP, "unsupported cell type %s", DMPolytopeTypes[ct]);
  }
  PetscFunctionReturn(0);
}

// Vertices of a cell in element-kernel order, from its vertices in closure order
// (mesh/cell_vertices.hpp). DMPlex lists a hexahedron's second face in the opposite cyclic
// sense; the kernel wants node 4+k joined by an edge to node k, so pair them through the edges
// at node k (in a mesh of hexahedra only an edge of this cell joins two of its vertices)
// instead of relying on a fixed permutation.
PetscErrorCode cellVerticesInKernelOrder(DM dm, const PetscInt *closure_vertices, PetscInt cell, CellShape shape, PetscInt *verts) {
  const PetscInt nv = cellNodeCount(shape);
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < nv; ++k) verts[k] = closure_vertices[k];
  if (shape != CellShape::Hex8) PetscFunctionReturn(0);
  PetscInt top[4];
  for (int k = 0; k < 4; ++k) {
    const PetscInt *edges;
    PetscInt        nedges;
    top[k] = -1;
    PetscCall(DMPlexGetSupportSize(dm, verts[k], &nedges));
    PetscCall(DMPlexGetSupport(dm, verts[k], &edges));
    for (PetscInt e = 0; e < nedges; ++e) {
      const PetscInt *ends;
      PetscCall(DMPlexGetCone(dm, edges[e], &ends));
      const PetscInt other = ends[0] == verts[k] ? ends[1] : ends[0];
      for (int j = 4; j < 8; ++j)
        if (verts[j] == other) top[k] = other;
    }
    PetscCheck(top[k] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "hexahedron %" PetscInt_FMT ": no edge joins its two faces at vertex %d", cell, k);
  }
  for (int k = 0; k < 4; ++k) verts[4 + k] = top[k];
  PetscFunctionReturn(0);
}

// The hot loop of f += K u. NEN nodes of DIM dofs per cell are compile-time constants so the
// gather/scatter and the N x N product unroll completely. Runs of kBatch consecutive cells
// that share one element matrix (every cell of a box-mesh region) are done together: their
// element vectors are gathered transposed, ue[j] = (u_j of cell 0..kBatch-1), so that
// fe[r] = sum_j K[r][j] ue[j] is a SIMD operation across the cells with K[r][j] broadcast,
// and the N accumulators fe[r] are independent. The sum over j runs in the same order as in
// the per-cell product. Explicit vector types because the default tuning (-march=native on
// this compiler) vectorises loops at 128 bits only. The scatter stays scalar and in cell
// order (cells of a batch share nodes).
constexpr int kBatch = 8;
typedef double BatchVec __attribute__((vector_size(kBatch * sizeof(double))));

template <int NEN, int DIM>
inline void applyOne(const PetscInt *__restrict dofs, const double *__restrict K, const PetscScalar *__restrict u, PetscScalar *__restrict f) {
  constexpr int N = NEN * DIM;
  double        ue[N], fe[N];
  for (int a = 0; a < NEN; ++a)
    for (int i = 0; i < DIM; ++i) ue[a * DIM + i] = u[dofs[a] + i];
  for (int r = 0; r < N; ++r) {
    double s = 0;
    for (int j = 0; j < N; ++j) s += K[r * N + j] * ue[j];
    fe[r] = s;
  }
  for (int a = 0; a < NEN; ++a)
    for (int i = 0; i < DIM; ++i) f[dofs[a] + i] += fe[a * DIM + i];
}

template <int NEN, int DIM>
void applyCells(PetscInt ncell, const PetscInt *__restrict cell_dofs, const PetscInt *__restrict cell_matrix, const double *__restrict pool,
                const PetscScalar *__restrict u, PetscScalar *__restrict f) {
  constexpr int N = NEN * DIM;
  union Lanes {
    BatchVec v;
    double   d[kBatch];
  };
  Lanes    ue[N], fe[N];
  PetscInt c = 0;
  while (c < ncell) {
    const PetscInt m   = cell_matrix[c];
    PetscInt       run = 1;
    while (run < kBatch && c + run < ncell && cell_matrix[c + run] == m) ++run;
    const double *__restrict K = pool + (size_t)m * N * N;
    if (run < kBatch) {
      for (PetscInt k = 0; k < run; ++k) applyOne<NEN, DIM>(cell_dofs + (c + k) * NEN, K, u, f);
      c += run;
      continue;
    }
    const PetscInt *__restrict dofs = cell_dofs + c * NEN;
    for (int b = 0; b < kBatch; ++b)
      for (int a = 0; a < NEN; ++a) {
        const PetscScalar *__restrict ua = u + dofs[b * NEN + a];
        for (int i = 0; i < DIM; ++i) ue[a * DIM + i].d[b] = ua[i];
      }
    BatchVec acc[N];
#pragma GCC unroll 24
    for (int r = 0; r < N; ++r) acc[r] = K[r * N] * ue[0].v;
#pragma GCC unroll 24
    for (int j = 1; j < N; ++j) {
      const BatchVec uj = ue[j].v;
#pragma GCC unroll 24
      for (int r = 0; r < N; ++r) acc[r] += K[r * N + j] * uj;
    }
#pragma GCC unroll 24
    for (int r = 0; r < N; ++r) fe[r].v = acc[r];
    for (int b = 0; b < kBatch; ++b)
      for (int a = 0; a < NEN; ++a) {
        PetscScalar *__restrict fa = f + dofs[b * NEN + a];
        for (int i = 0; i < DIM; ++i) fa[i] += fe[a * DIM + i].d[b];
      }
    c += kBatch;
  }
}

} // namespace

PetscErrorCode BulkOperator::Setup(DM dm, const std::vector<RegionMaterial> &materials) {
  region_deforms_.clear();
  for (const RegionMaterial &m : materials) region_deforms_.push_back(m.deforms);
  PetscInt     c_start, c_end;
  PetscSection section;
  DMLabel      region_label;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim_));
  PetscCall(DMGetLocalSection(dm, &section));
  PetscCall(DMGetLabel(dm, mesh::kRegionLabel, &region_label));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
  ncell_ = c_end - c_start;
  if (ncell_ > 0) PetscCall(cellShapeOf(dm, c_start, &shape_));
  nen_ = cellNodeCount(shape_);
  const PetscInt ndof = nen_ * dim_;
  cell_dofs_.resize(ncell_ * nen_);
  cell_vertices_.resize(ncell_ * nen_);
  cell_region_.resize(ncell_);
  cell_matrix_.resize(ncell_);
  cell_coords_.resize(ncell_ * nen_ * dim_);

  mesh::VertexCoordinates   coords;
  const mesh::CellVertices *closure_vertices;
  PetscCall(coords.Open(dm));
  PetscCall(mesh::CellVerticesOf(dm, &closure_vertices));

  double bbox_lo[3] = {1e300, 1e300, 1e300}, bbox_hi[3] = {-1e300, -1e300, -1e300};
  for (PetscInt c = 0; c < ncell_; ++c) {
    PetscInt *verts = &cell_vertices_[c * nen_];
    PetscCall(cellVerticesInKernelOrder(dm, closure_vertices->of(c), c_start + c, shape_, verts));
    for (PetscInt a = 0; a < nen_; ++a) {
      PetscInt off;
      PetscCall(PetscSectionGetOffset(section, verts[a], &off));
      cell_dofs_[c * nen_ + a] = off;
      double *x = &cell_coords_[(c * nen_ + a) * dim_];
      PetscCall(coords.Get(verts[a], x));
      for (PetscInt i = 0; i < dim_; ++i) {
        bbox_lo[i] = std::min(bbox_lo[i], x[i]);
        bbox_hi[i] = std::max(bbox_hi[i], x[i]);
      }
    }
    PetscInt region;
    PetscCall(DMLabelGetValue(region_label, c_start + c, &region));
    PetscCheck(region >= 0 && region < (PetscInt)materials.size(), PETSC_COMM_SELF, PETSC_ERR_PLIB, "cell %" PetscInt_FMT " has no region", c_start + c);
    cell_region_[c] = region;
  }
  PetscCall(coords.Close());

  double extent = 0;
  for (PetscInt i = 0; i < dim_; ++i) extent = std::max(extent, bbox_hi[i] - bbox_lo[i]);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &extent, 1, MPI_DOUBLE, MPI_MAX, PetscObjectComm((PetscObject)dm)));
  const double quantum = 1e-12 * (extent > 0 ? extent : 1.0);

  std::unordered_map<std::string, PetscInt> seen;
  h_min_ = 1e300;
  stiffness_.clear();
  stress_op_.clear();
  lumped_.clear();
  const mesh::SpectralLayout *layout;
  PetscCall(mesh::SpectralLayoutOf(dm, &layout));
  degree_ = layout ? layout->degree : 1;
  for (PetscInt c = 0; c < ncell_ && degree_ == 1; ++c) {
    const double *x   = cellCoordinates(c);
    std::string   key = geometryKey(cell_region_[c], x, (int)nen_, (int)dim_, quantum);
    auto found = seen.find(key);
    if (found != seen.end()) {
      cell_matrix_[c] = found->second;
      continue;
    }
    const PetscInt       idx = (PetscInt)seen.size();
    const RegionMaterial &m  = materials[cell_region_[c]];
    seen.emplace(std::move(key), idx);
    cell_matrix_[c] = idx;
    stiffness_.resize((size_t)(idx + 1) * ndof * ndof);
    stress_op_.resize((size_t)(idx + 1) * kStressComponents * ndof);
    lumped_.resize((size_t)(idx + 1) * nen_);
    fem::elementStiffness(shape_, x, m.lame, &stiffness_[(size_t)idx * ndof * ndof], m.dilatation);
    elementStressOperator(shape_, x, m.lame, &stress_op_[(size_t)idx * kStressComponents * ndof], m.dilatation);
    elementLumpedMass(shape_, x, m.rho, &lumped_[(size_t)idx * nen_]);
  }
  matrix_count_ = seen.size();
  // The smallest edge/diagonal length over cells, for reports (points per wavelength), and
  // per region the largest cell's (each cell's shortest edge or diagonal).
  region_element_size_.assign(materials.size(), 0.0);
  for (PetscInt c = 0; c < ncell_; ++c) {
    const double *x    = cellCoordinates(c);
    double        size = 1e300;
    for (PetscInt a = 0; a < nen_; ++a)
      for (PetscInt b = a + 1; b < nen_; ++b) {
        double d2 = 0;
        for (PetscInt i = 0; i < dim_; ++i) d2 += (x[a * dim_ + i] - x[b * dim_ + i]) * (x[a * dim_ + i] - x[b * dim_ + i]);
        size = std::min(size, std::sqrt(d2));
      }
    h_min_ = std::min(h_min_, size);
    if (degree_ == 1) region_element_size_[cell_region_[c]] = std::max(region_element_size_[cell_region_[c]], size);
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &h_min_, 1, MPI_DOUBLE, MPI_MIN, PetscObjectComm((PetscObject)dm)));
  h_elem_min_ = h_min_;
  local_size_ = 0;
  for (PetscInt off : cell_dofs_) local_size_ = std::max(local_size_, off + dim_);
  if (degree_ > 1) PetscCall(setupSpectral(dm, *layout, materials));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, region_element_size_.data(), (int)region_element_size_.size(), MPI_DOUBLE, MPI_MAX, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

PetscErrorCode BulkOperator::setupSpectral(DM dm, const mesh::SpectralLayout &layout, const std::vector<RegionMaterial> &materials) {
  PetscSection section;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm, &section));
  const PetscInt          nq = layout.element_nodes.size() / std::max<PetscInt>(layout.nelem, 1);
  std::vector<double>     coords((size_t)layout.nelem * nq * dim_);
  std::vector<PetscInt>   offsets((size_t)layout.nelem * nq);
  mesh::VertexCoordinates vc;
  PetscCall(vc.Open(dm));
  for (size_t k = 0; k < offsets.size(); ++k) {
    PetscCall(PetscSectionGetOffset(section, layout.element_nodes[k], &offsets[k]));
    PetscCall(vc.Get(layout.element_nodes[k], &coords[k * dim_]));
  }
  PetscCall(vc.Close());
  PetscCall(spectral_.Setup(dim_, degree_, layout.nelem, coords.data(), offsets.data(), layout.element_region.data(), materials));
  cell_element_     = layout.cell_element;
  cell_position_    = layout.cell_position;
  element_vertices_ = layout.element_nodes;
  // The certified bound costs a dense Cholesky per distinct geometry: cheap on box meshes
  // (one per region) and in 2D; unstructured 3D meshes take the Collatz-Wielandt bound
  // (also rigorous, ~1.2-1.3x looser, ~7x cheaper: docs/spectral-kernels.md).
  // The choice is the same on every rank (the sum of the ranks' counts: the mesh's count
  // when geometries are unique, as on unstructured meshes), so the step does not depend on it.
  MPI_Comm comm       = PetscObjectComm((PetscObject)dm);
  PetscInt geometries = spectral_.distinctGeometries();
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &geometries, 1, MPIU_INT, MPI_SUM, comm));
  bound_kind_   = dim_ == 2 || geometries <= 256 ? EigenBoundKind::Certified : EigenBoundKind::CollatzWielandt;
  omega2_bound_ = spectral_.maxElementEigenBound(bound_kind_);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &omega2_bound_, 1, MPI_DOUBLE, MPI_MAX, comm));
  // Another rank sees a cell in another orientation, which moves its bound by round-off:
  // rounded up to 24 bits (6e-8, still an upper bound), every partition steps with the same dt.
  int          exponent = 0;
  const double mantissa = std::frexp(omega2_bound_, &exponent);
  omega2_bound_         = std::ldexp(std::ceil(std::ldexp(mantissa, 24)), exponent - 24);
  // Element size from the corners (index 0 or p along each direction).
  h_elem_min_          = 1e300;
  const PetscInt ncorner = dim_ == 2 ? 4 : 8, n1 = degree_ + 1;
  for (PetscInt e = 0; e < layout.nelem; ++e) {
    double x[8][3], size = 1e300;
    for (PetscInt k = 0; k < ncorner; ++k) {
      const PetscInt i = (k & 1) * degree_, j = ((k >> 1) & 1) * degree_, l = ((k >> 2) & 1) * degree_;
      const PetscInt a = i + n1 * (j + n1 * l);
      for (PetscInt d = 0; d < dim_; ++d) x[k][d] = coords[((size_t)e * nq + a) * dim_ + d];
    }
    for (PetscInt a = 0; a < ncorner; ++a)
      for (PetscInt b = a + 1; b < ncorner; ++b) {
        double d2 = 0;
        for (PetscInt d = 0; d < dim_; ++d) d2 += (x[a][d] - x[b][d]) * (x[a][d] - x[b][d]);
        size = std::min(size, std::sqrt(d2));
      }
    h_elem_min_         = std::min(h_elem_min_, size);
    double &region_size = region_element_size_[layout.element_region[e]];
    region_size         = std::max(region_size, size);
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &h_elem_min_, 1, MPI_DOUBLE, MPI_MIN, comm));
  PetscFunctionReturn(0);
}

namespace {

void applyAll(PetscInt nen, PetscInt dim, PetscInt ncell, const PetscInt *dofs, const PetscInt *mats, const double *pool, const PetscScalar *u, PetscScalar *f) {
  switch (nen * dim) {
  case 6: applyCells<3, 2>(ncell, dofs, mats, pool, u, f); break;  // Tri3
  case 8: applyCells<4, 2>(ncell, dofs, mats, pool, u, f); break;  // Quad4
  case 12: applyCells<4, 3>(ncell, dofs, mats, pool, u, f); break; // Tet4
  case 24: applyCells<8, 3>(ncell, dofs, mats, pool, u, f); break; // Hex8
  default: break;
  }
}

} // namespace

void BulkOperator::addStiffnessTimes(const PetscScalar *u, PetscScalar *f) const {
  if (degree_ > 1) return spectral_.addStiffnessTimes(u, f);
  applyAll(nen_, dim_, ncell_, cell_dofs_.data(), cell_matrix_.data(), stiffness_.data(), u, f);
}

BulkOperator::CellSubset BulkOperator::subset(const std::vector<PetscInt> &cells) const {
  CellSubset s;
  if (degree_ > 1) {
    std::vector<PetscInt> elements;
    for (PetscInt c : cells) elements.push_back(cell_element_[c]);
    std::sort(elements.begin(), elements.end());
    elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
    s.elements = spectral_.subset(elements);
    return s;
  }
  for (PetscInt c : cells) {
    s.dofs.insert(s.dofs.end(), cell_dofs_.begin() + c * nen_, cell_dofs_.begin() + (c + 1) * nen_);
    s.matrix.push_back(cell_matrix_[c]);
  }
  return s;
}

void BulkOperator::addStiffnessTimes(const CellSubset &cells, const PetscScalar *u, PetscScalar *f) const {
  if (degree_ > 1) return spectral_.addStiffnessTimes(cells.elements, u, f);
  applyAll(nen_, dim_, (PetscInt)cells.matrix.size(), cells.dofs.data(), cells.matrix.data(), stiffness_.data(), u, f);
}

void BulkOperator::addLumpedMass(PetscScalar *mass) const {
  if (degree_ > 1) return spectral_.addLumpedMass(mass);
  for (PetscInt c = 0; c < ncell_; ++c) {
    const double *m = &lumped_[(size_t)cell_matrix_[c] * nen_];
    for (PetscInt a = 0; a < nen_; ++a)
      for (PetscInt i = 0; i < dim_; ++i) mass[cell_dofs_[c * nen_ + a] + i] += m[a];
  }
}

void BulkOperator::addStiffnessRowBounds(PetscScalar *rowabs) const {
  if (degree_ > 1) {
    std::vector<PetscScalar> mass(local_size_, 0.0);
    spectral_.addLumpedMass(mass.data(), true);
    for (PetscInt k = 0; k < local_size_; ++k) rowabs[k] += omega2_bound_ * mass[k];
    return;
  }
  const PetscInt n = nen_ * dim_;
  for (PetscInt c = 0; c < ncell_; ++c) {
    if (!region_deforms_[cell_region_[c]]) continue;
    const double *K = &stiffness_[(size_t)cell_matrix_[c] * n * n];
    for (PetscInt a = 0; a < nen_; ++a)
      for (PetscInt i = 0; i < dim_; ++i) {
        const PetscInt r = a * dim_ + i;
        double         s = 0;
        for (PetscInt j = 0; j < n; ++j) s += std::fabs(K[r * n + j]);
        rowabs[cell_dofs_[c * nen_ + a] + i] += s;
      }
  }
}

void BulkOperator::elementStiffness(PetscInt e, double *K) const {
  if (degree_ > 1) return spectral_.elementStiffness(e, K);
  const size_t n = (size_t)nen_ * dim_;
  std::memcpy(K, &stiffness_[(size_t)cell_matrix_[e] * n * n], n * n * sizeof(double));
}

void BulkOperator::elementStiffnessTimes(PetscInt e, const double *ue, double *fe) const {
  if (degree_ > 1) return spectral_.elementForce(e, ue, fe);
  const PetscInt n = nen_ * dim_;
  const double  *K = &stiffness_[(size_t)cell_matrix_[e] * n * n];
  for (PetscInt r = 0; r < n; ++r) {
    double s = 0;
    for (PetscInt c = 0; c < n; ++c) s += K[r * n + c] * ue[c];
    fe[r] = s;
  }
}

void BulkOperator::cellStress(const PetscScalar *u, PetscScalar *stress) const {
  double sigma[kStressComponents];
  for (PetscInt c = 0; c < ncell_; ++c) {
    cellStress(c, u, sigma);
    for (int k = 0; k < kStressComponents; ++k) stress[c * kStressComponents + k] = sigma[k];
  }
}

void BulkOperator::cellStress(PetscInt c, const PetscScalar *u, double *sigma) const { cellTensor(c, u, nullptr, sigma); }

// The strain is the stress of a material with lambda = 0 and mu = 1/2 (sigma = 2 mu eps), so
// it comes from the stress's own kernels at the same point.
void BulkOperator::cellStrain(PetscInt c, const PetscScalar *u, double *eps) const {
  const LameParameters half{0.0, 0.5};
  cellTensor(c, u, &half, eps);
}

void BulkOperator::cellTensor(PetscInt c, const PetscScalar *u, const LameParameters *lame, double *out) const {
  if (degree_ > 1) {
    // The sub-cell's centre in the element's reference coordinates: the mean of its corner
    // GLL points along each direction.
    double x[numerics::kMaxSpectralDegree + 1], w[numerics::kMaxSpectralDegree + 1], xi[3];
    numerics::gllPointsWeights(degree_, x, w);
    PetscInt pos = cell_position_[c];
    for (PetscInt d = 0; d < dim_; ++d, pos /= degree_) xi[d] = 0.5 * (x[pos % degree_] + x[pos % degree_ + 1]);
    spectral_.stressAt(cell_element_[c], xi, u, out, lame);
    return;
  }
  const PetscInt n = nen_ * dim_;
  double         ue[kMaxCellDofs], own[kStressComponents * kMaxCellDofs];
  for (PetscInt a = 0; a < nen_; ++a)
    for (PetscInt i = 0; i < dim_; ++i) ue[a * dim_ + i] = PetscRealPart(u[cell_dofs_[c * nen_ + a] + i]);
  const double *S = &stress_op_[(size_t)cell_matrix_[c] * kStressComponents * n];
  if (lame) {
    elementStressOperator(shape_, cellCoordinates(c), *lame, own);
    S = own;
  }
  for (int k = 0; k < kStressComponents; ++k) {
    double s = 0;
    for (PetscInt j = 0; j < n; ++j) s += S[k * n + j] * ue[j];
    out[k] = s;
  }
}

PetscErrorCode BulkStiffnessRowBounds(DM dm, const BulkOperator &bulk, Vec rows) {
  Vec          local;
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dm, &local));
  PetscCall(VecZeroEntries(local));
  PetscCall(VecGetArray(local, &a));
  bulk.addStiffnessRowBounds(a);
  PetscCall(VecRestoreArray(local, &a));
  PetscCall(VecZeroEntries(rows));
  PetscCall(DMLocalToGlobal(dm, local, ADD_VALUES, rows));
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscFunctionReturn(0);
}

PetscErrorCode BulkRegionNodes(DM dm, const BulkOperator &bulk, PetscInt region, Vec marks, Vec coords) {
  Vec          mark_local, coord_local;
  PetscScalar *m, *x;
  const PetscInt dim = bulk.dimension(), nen = bulk.nodesPerCell();
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dm, &mark_local));
  PetscCall(DMGetLocalVector(dm, &coord_local));
  PetscCall(VecZeroEntries(mark_local));
  PetscCall(VecGetArray(mark_local, &m));
  PetscCall(VecGetArray(coord_local, &x));
  bulk.nodeCoordinates(x);
  for (PetscInt c = 0; c < bulk.cellCount(); ++c)
    if (bulk.cellRegion(c) == region)
      for (PetscInt a = 0; a < nen; ++a)
        for (PetscInt d = 0; d < dim; ++d) m[bulk.cellNodeOffset(c, a) + d] = 1;
  PetscCall(VecRestoreArray(coord_local, &x));
  PetscCall(VecRestoreArray(mark_local, &m));
  PetscCall(VecZeroEntries(marks));
  PetscCall(DMLocalToGlobal(dm, mark_local, ADD_VALUES, marks));
  PetscCall(DMLocalToGlobal(dm, coord_local, INSERT_VALUES, coords));
  PetscCall(DMRestoreLocalVector(dm, &coord_local));
  PetscCall(DMRestoreLocalVector(dm, &mark_local));
  PetscFunctionReturn(0);
}

} // namespace slipwave::fem

// The bulk internal force f = K u by our own element loop over a connectivity table built
// once (PETSc's pointwise FE residual is ~100x slower here). Element stiffness matrices are
// stored once per distinct (region, cell geometry): every cell of a box mesh region shares
// one matrix, so the loop is compute-bound; unstructured meshes store one matrix per cell.
//
// Two kinds of "cell": the DM's cells, whose vertices are the nodes (cellCount, cellVertex,
// cellCoordinates, ... describe them as linear cells, for locating points, output and
// per-cell labels), and the elements the operators integrate over. At degree 1 they are the
// same. At degree p > 1 (mesh/spectral_layout.hpp) each element is p^dim DM sub-cells on its
// GLL nodes, and the operators are the spectral element's (fem/spectral_operator.hpp): the
// force, the GLL mass, the stable-step bound and the stress come from the element, never from
// the sub-cells.
#pragma once
#include <petscdmplex.h>

#include <vector>

#include "slipwave/fem/element_kernels.hpp"
#include "slipwave/fem/region_material.hpp"
#include "slipwave/fem/spectral_operator.hpp"
#include "slipwave/mesh/spectral_layout.hpp"

namespace slipwave::fem {

class BulkOperator {
public:
  // dm must carry the "region" label and a local section with dim dofs on every vertex.
  // Collective (the spectral stable-step bound is reduced over the ranks).
  PetscErrorCode Setup(DM dm, const std::vector<RegionMaterial> &materials);

  // f_local += K u_local on the cells of this rank (local, ghosted arrays; no communication).
  void addStiffnessTimes(const PetscScalar *u_local, PetscScalar *f_local) const;
  // The same on the elements holding a subset of cells (ascending local cell numbers), through
  // the same loop.
  struct CellSubset {
    std::vector<PetscInt>      dofs, matrix; // degree 1, per cell of the subset: its node dof offsets, its matrix
    SpectralOperator::Subset   elements;     // degree > 1: the elements holding the cells
  };
  CellSubset subset(const std::vector<PetscInt> &cells) const;
  void       addStiffnessTimes(const CellSubset &cells, const PetscScalar *u_local, PetscScalar *f_local) const;
  // Adds the row-sum lumped mass (one value per dof) to a local array.
  void addLumpedMass(PetscScalar *mass_local) const;
  // Adds per dof a row bound r_i with K <= diag(r) (in the sense of quadratic forms), so that
  // max_i r_i / m_i bounds omega_max^2 and other stiffness can be added row by row.
  // Degree 1: the Gershgorin row sums sum_j |K_ij| (diagonally dominant remainder). Degree > 1:
  // r_i = omega2 m_i with omega2 the certified element bound (fem/spectral_kernels.hpp), over
  // all ranks: K <= omega2 M, and about twice the step of the row sums at p >= 4.
  // Regions that do not deform (RegionMaterial::deforms) add nothing at degree 1 and are left
  // out of omega2 at degree > 1: their nodes move as rigid bodies, bounded on their own.
  void addStiffnessRowBounds(PetscScalar *rows_local) const;
  // The elements the operators integrate over (degree 1: the cells), with their nodes and
  // stiffness in node-major order (row a*dim+i), the matrix addStiffnessTimes applies (for
  // assembling K where a static solve needs it). K: (nodesPerElement dim)^2 values.
  PetscInt elementCount() const { return degree_ == 1 ? ncell_ : spectral_.elementCount(); }
  PetscInt nodesPerElement() const { return degree_ == 1 ? nen_ : spectral_.nodesPerElement(); }
  PetscInt elementNodeOffset(PetscInt e, PetscInt a) const { return degree_ == 1 ? cellNodeOffset(e, a) : spectral_.elementNodeOffset(e, a); }
  void     elementStiffness(PetscInt e, double *K) const;
  // The element's region and node coordinates (nodesPerElement x dim; degree > 1: the GLL
  // nodes, lexicographic, x fastest), and the element a cell belongs to (degree 1: itself).
  PetscInt      elementRegion(PetscInt e) const { return degree_ == 1 ? cell_region_[e] : spectral_.elementRegion(e); }
  const double *elementCoordinates(PetscInt e) const { return degree_ == 1 ? cellCoordinates(e) : spectral_.elementCoordinates(e); }
  // DMPlex point (vertex) of node a of element e, in the order of elementNodeOffset.
  PetscInt      elementVertex(PetscInt e, PetscInt a) const { return degree_ == 1 ? cellVertex(e, a) : element_vertices_[e * spectral_.nodesPerElement() + a]; }
  // Elements with the same index share region and geometry, so any matrix built from both
  // (degree 1: cellMatrix; degree > 1: the geometry record of the spectral operator).
  PetscInt      elementMatrix(PetscInt e) const { return degree_ == 1 ? cell_matrix_[e] : spectral_.elementRecord(e); }
  // Degree > 1: the kind of element eigenvalue bound the stable step takes (certified where
  // affordable, Collatz-Wielandt on unstructured 3D meshes), for other bounds of the same
  // elements to choose alike.
  EigenBoundKind eigenBoundKind() const { return bound_kind_; }
  PetscInt      cellElement(PetscInt c) const { return degree_ == 1 ? c : cell_element_[c]; }
  // fe = K_e ue for element e alone (node-major, nodesPerElement dim values each; fe
  // overwritten), the matrix addStiffnessTimes applies: degree 1 the stored cell matrix,
  // degree > 1 the sum-factorised kernel. For element vectors that are no mesh field (the DRM
  // layer's free field on one side of the layer).
  void elementStiffnessTimes(PetscInt e, const double *ue, double *fe) const;
  // Stress (6 per cell: xx,yy,zz,xy,yz,xz) at the centroid of each of this rank's cells, in cell
  // order (degree > 1: by the element's basis at the sub-cell's centre).
  void cellStress(const PetscScalar *u_local, PetscScalar *stress) const;
  // The same for cell c alone (6 values), and the small-strain tensor there (6 tensor
  // components in the same order; 2D: zz = yz = xz = 0, plane strain).
  void cellStress(PetscInt c, const PetscScalar *u_local, double *stress) const;
  void cellStrain(PetscInt c, const PetscScalar *u_local, double *strain) const;

  PetscInt  dimension() const { return dim_; }
  PetscInt  nodesPerCell() const { return nen_; }
  PetscInt  cellCount() const { return ncell_; }
  CellShape shape() const { return shape_; }
  PetscInt  degree() const { return degree_; }
  // Distinct element matrices (degree > 1: distinct element geometries).
  PetscInt  distinctMatrices() const { return degree_ == 1 ? (PetscInt)matrix_count_ : spectral_.distinctGeometries(); }
  // Local dof offset of node a of cell c (its x component); nodes in element-kernel order.
  PetscInt  cellNodeOffset(PetscInt c, PetscInt a) const { return cell_dofs_[c * nen_ + a]; }
  // DMPlex point of node a of cell c.
  PetscInt  cellVertex(PetscInt c, PetscInt a) const { return cell_vertices_[c * nen_ + a]; }
  PetscInt  cellRegion(PetscInt c) const { return cell_region_[c]; }
  // Degree 1: index of cell c's element matrices (cells with the same index share region and
  // geometry).
  PetscInt  cellMatrix(PetscInt c) const { return cell_matrix_[c]; }
  const double *cellCoordinates(PetscInt c) const { return &cell_coords_[c * nen_ * dim_]; }
  // Writes every node's coordinates into a local vector's array of the displacement layout
  // (node at offset o: entries o .. o+dim-1), so a node's place can be read like its u.
  void nodeCoordinates(PetscScalar *local) const {
    for (PetscInt c = 0; c < cellCount(); ++c)
      for (PetscInt a = 0; a < nen_; ++a)
        for (PetscInt d = 0; d < dim_; ++d) local[cellNodeOffset(c, a) + d] = cellCoordinates(c)[a * dim_ + d];
  }
  // The shortest edge or diagonal of a cell (degree > 1: of a sub-cell, the closest GLL nodes).
  double    minCellSize() const { return h_min_; }
  // The shortest edge or diagonal of an element's corners (degree 1: minCellSize).
  double    minElementSize() const { return h_elem_min_; }
  // The largest element of a region, each element measured as above (its corners' shortest
  // edge or diagonal), over all ranks: what limits the waves the region carries. On a uniform
  // mesh it equals minElementSize; on a graded one it is the coarse part's size.
  double    regionElementSize(PetscInt region) const { return region_element_size_[region]; }

private:
  // cellStress of cell c with the region's moduli (lame null) or with *lame.
  void           cellTensor(PetscInt c, const PetscScalar *u_local, const LameParameters *lame, double *out) const;
  PetscErrorCode setupSpectral(DM dm, const mesh::SpectralLayout &layout, const std::vector<RegionMaterial> &materials);

  PetscInt              dim_ = 0, nen_ = 0, ncell_ = 0, local_size_ = 0;
  CellShape             shape_ = CellShape::Quad4;
  std::vector<PetscInt> cell_dofs_, cell_vertices_, cell_region_, cell_matrix_;
  std::vector<char>     region_deforms_; // per region: RegionMaterial::deforms
  std::vector<double>   region_element_size_; // per region: regionElementSize
  std::vector<double>   cell_coords_, stiffness_, stress_op_, lumped_;
  size_t                matrix_count_ = 0;
  double                h_min_ = 0, h_elem_min_ = 0;
  PetscInt              degree_ = 1;
  SpectralOperator      spectral_;            // degree > 1
  double                omega2_bound_ = 0;    // degree > 1: certified bound on omega_max^2, all ranks
  std::vector<PetscInt> cell_element_, cell_position_; // degree > 1: per cell, its element and place in it
  std::vector<PetscInt> element_vertices_;             // degree > 1: per element its nodes' DM vertices
  EigenBoundKind        bound_kind_ = EigenBoundKind::Certified;
};

// rows (global) = the row bounds of addStiffnessRowBounds summed over the ranks' cells:
// K <= diag(rows), what every stable-step bound of the assembled problem starts from.
PetscErrorCode BulkStiffnessRowBounds(DM dm, const BulkOperator &bulk, Vec rows);
// Global vectors in the displacement layout: marks > 0 on every dof of the nodes of the
// region's cells (each node once, whatever the partition), coords every node's coordinates.
PetscErrorCode BulkRegionNodes(DM dm, const BulkOperator &bulk, PetscInt region, Vec marks, Vec coords);

} // namespace slipwave::fem

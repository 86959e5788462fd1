// The bulk internal force f = K u by our own element loop over a connectivity table built
// once (PETSc's pointwise FE residual is ~100x slower here). Element stiffness matrices are
// stored once per distinct (region, cell geometry): every cell of a box mesh region shares
// one matrix, so the loop is compute-bound; unstructured meshes store one matrix per cell.
#pragma once
#include <petscdmplex.h>

#include <vector>

#include "slipwave/fem/element_kernels.hpp"

namespace slipwave::fem {

struct RegionMaterial {
  double        rho;
  LameParameters lame;
};

class BulkOperator {
public:
  // dm must carry the "region" label and a local section with dim dofs on every vertex.
  PetscErrorCode Setup(DM dm, const std::vector<RegionMaterial> &materials);

  // f_local += K u_local on the cells of this rank (local, ghosted arrays; no communication).
  void addStiffnessTimes(const PetscScalar *u_local, PetscScalar *f_local) const;
  // The same on a subset of cells (ascending local cell numbers), through the same loop.
  struct CellSubset {
    std::vector<PetscInt> dofs, matrix; // per cell of the subset: its node dof offsets, its matrix
  };
  CellSubset subset(const std::vector<PetscInt> &cells) const;
  void       addStiffnessTimes(const CellSubset &cells, const PetscScalar *u_local, PetscScalar *f_local) const;
  // Adds the row-sum lumped mass (one value per dof) to a local array.
  void addLumpedMass(PetscScalar *mass_local) const;
  // Adds sum_j |K_ij| per dof (Gershgorin row sums) to a local array.
  void addStiffnessRowAbsSums(PetscScalar *rowabs_local) const;
  // Element stiffness of cell c: (nen dim)^2 values, row a*dim+i (node-major), the same
  // matrix addStiffnessTimes applies (for assembling K where a static solve needs it).
  const double *cellStiffness(PetscInt c) const { return &stiffness_[(size_t)cell_matrix_[c] * nen_ * dim_ * nen_ * dim_]; }
  // Cell-centroid stress (6 per cell: xx,yy,zz,xy,yz,xz) of this rank's cells, in cell order.
  void cellStress(const PetscScalar *u_local, PetscScalar *stress) const;

  PetscInt  dimension() const { return dim_; }
  PetscInt  nodesPerCell() const { return nen_; }
  PetscInt  cellCount() const { return ncell_; }
  CellShape shape() const { return shape_; }
  PetscInt  distinctMatrices() const { return (PetscInt)matrix_count_; }
  // Local dof offset of node a of cell c (its x component); nodes in element-kernel order.
  PetscInt  cellNodeOffset(PetscInt c, PetscInt a) const { return cell_dofs_[c * nen_ + a]; }
  // DMPlex point of node a of cell c.
  PetscInt  cellVertex(PetscInt c, PetscInt a) const { return cell_vertices_[c * nen_ + a]; }
  PetscInt  cellRegion(PetscInt c) const { return cell_region_[c]; }
  // Index of cell c's element matrices: cells with the same index share region and geometry.
  PetscInt  cellMatrix(PetscInt c) const { return cell_matrix_[c]; }
  const double *cellCoordinates(PetscInt c) const { return &cell_coords_[c * nen_ * dim_]; }
  // Writes every node's coordinates into a local vector's array of the displacement layout
  // (node at offset o: entries o .. o+dim-1), so a node's place can be read like its u.
  void nodeCoordinates(PetscScalar *local) const {
    for (PetscInt c = 0; c < cellCount(); ++c)
      for (PetscInt a = 0; a < nen_; ++a)
        for (PetscInt d = 0; d < dim_; ++d) local[cellNodeOffset(c, a) + d] = cellCoordinates(c)[a * dim_ + d];
  }
  double    minCellSize() const { return h_min_; }

private:
  PetscInt              dim_ = 0, nen_ = 0, ncell_ = 0;
  CellShape             shape_ = CellShape::Quad4;
  std::vector<PetscInt> cell_dofs_, cell_vertices_, cell_region_, cell_matrix_;
  std::vector<double>   cell_coords_, stiffness_, stress_op_, lumped_;
  size_t                matrix_count_ = 0;
  double                h_min_ = 0;
};

} // namespace slipwave::fem

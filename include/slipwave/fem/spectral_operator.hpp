// The bulk internal force, lumped mass, stable-step inputs and stress of spectral elements of
// degree p (fem/spectral_kernels), over a rank's elements given as arrays (the mesh side
// groups the GLL sub-cells into elements; no DM here). Elements of one region whose node
// coordinates relative to their first node agree (to 1e-12 of the extent: every element of
// a box-mesh region) share one record of geometric factors. The force runs in batches of 8
// consecutive elements, one SIMD lane per element: with the record's factors broadcast when
// all 8 share it, with lane-interleaved copies of their factors (built once per element set)
// when they only share the region (unstructured meshes); elements left over take the
// per-element path of the same kernel.
#pragma once
#include <petscsys.h>

#include <vector>

#include "slipwave/fem/region_material.hpp"
#include "slipwave/fem/spectral_kernels.hpp"

namespace slipwave::fem {

class SpectralOperator {
public:
  // coords: nelem * (p+1)^dim * dim node coordinates (lexicographic nodes, x fastest);
  // node_offset: nelem * (p+1)^dim local dof offsets of each node's x component (the node's
  // components are offset .. offset+dim-1); region: nelem indices into materials.
  // Fails (PETSC_ERR_USER_INPUT, naming the element) on a folded or degenerate element.
  PetscErrorCode Setup(PetscInt dim, PetscInt degree, PetscInt nelem, const double *coords, const PetscInt *node_offset, const PetscInt *region,
                       const std::vector<RegionMaterial> &materials);

  // f_local += K u_local over all elements (local, ghosted arrays; no communication).
  void addStiffnessTimes(const PetscScalar *u_local, PetscScalar *f_local) const;
  // One geometric factor of the 8 elements of a lane batch (one SIMD vector).
  struct alignas(64) FactorLanes {
    double lane[8];
  };
  // A list of elements (local numbers, any order; runs of consecutive elements of one region
  // batch best) with its batching plan, for the same loop on a subset.
  struct Subset {
    std::vector<PetscInt>    elements;
    std::vector<PetscInt>    groups;       // per group: kind, first position in elements, record or lane-factor offset
    std::vector<FactorLanes> lane_factors; // interleaved factors of the lane batches
  };
  Subset subset(const std::vector<PetscInt> &elements) const;
  void   addStiffnessTimes(const Subset &elements, const PetscScalar *u_local, PetscScalar *f_local) const;
  // Adds the GLL lumped mass rho w_q |det J_q| to every component of every node (of the
  // elements of deforming regions only, with deforming_only: RegionMaterial::deforms).
  void addLumpedMass(PetscScalar *mass_local, bool deforming_only = false) const;
  // Adds sum_j |K_e,ij| per dof (element Gershgorin row sums; their assembly bounds the row
  // sums of K, so max_i rowabs_i / m_i >= omega_max^2 as for the Q1 operator).
  void addStiffnessRowAbsSums(PetscScalar *rowabs_local) const;
  // max over this rank's geometry records of spectralElementEigenBound(kind): a rigorous
  // bound on omega_max^2 of the assembled bulk (reduce with MPI_MAX across ranks). Records of
  // regions that do not deform (RegionMaterial::deforms) are left out.
  double maxElementEigenBound(EigenBoundKind kind) const;
  // Element matrix of element e: (dim (p+1)^dim)^2 values row-major, row a*dim+i (node-major),
  // the operator addStiffnessTimes applies (for assembling K where a static solve needs it).
  void elementStiffness(PetscInt e, double *K) const;
  // fe = K_e ue for element e alone, by the same sum-factorised kernel (ue, fe node-major,
  // dim (p+1)^dim values; fe overwritten): for element vectors that are no mesh field, such as
  // the DRM layer's free field on one side of the layer (input/drm).
  void elementForce(PetscInt e, const double *ue, double *fe) const;
  // Stress (xx, yy, zz, xy, yz, xz) in element e at the reference point xi; lame: other
  // moduli than the element's (null: the element's).
  void stressAt(PetscInt e, const double *xi, const PetscScalar *u_local, double *sigma, const LameParameters *lame = nullptr) const;

  PetscInt dimension() const { return dim_; }
  PetscInt degree() const { return degree_; }
  PetscInt elementCount() const { return nelem_; }
  PetscInt nodesPerElement() const { return nq_; }
  PetscInt distinctGeometries() const { return (PetscInt)record_material_.size(); }
  PetscInt elementRegion(PetscInt e) const { return region_[e]; }
  // Index of element e's geometry record: elements with the same index share region and shape.
  PetscInt elementRecord(PetscInt e) const { return record_[e]; }
  PetscInt elementNodeOffset(PetscInt e, PetscInt a) const { return node_offset_[e * nq_ + a]; }
  const double *elementCoordinates(PetscInt e) const { return &coords_[(size_t)e * nq_ * dim_]; }

private:
  PetscInt                    dim_ = 0, degree_ = 1, nelem_ = 0, nq_ = 0;
  std::vector<PetscInt>       node_offset_, region_, record_; // record_: per element, its geometry record
  std::vector<double>         coords_, wdet_, jinv_, D_;      // wdet_, jinv_: per record
  std::vector<RegionMaterial> materials_, record_material_;
  Subset                      all_;
};

} // namespace slipwave::fem

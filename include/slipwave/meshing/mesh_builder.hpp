// Builds the computational mesh: a built-in box (quads/hexes) whose regions are chosen by
// axis-aligned boxes, or a Gmsh file whose physical group names are the region and boundary
// names. The mesh is created and labelled serially, then distributed (labels survive), or,
// for a box without interfaces, built by every rank for its part (box_lattice.hpp).
// Labels on the result:
//   "region"          (kRegionLabel, mesh/labels.hpp) every cell, value = index of its region in MeshDescription::regions
//   <boundary name>   faces (height 1), value 1: box sides left/right/bottom/top(/front/back),
//                     or the Gmsh physical groups of dimension dim-1
//   spectral_position (degree > 1, labels.hpp) every GLL sub-cell: its place in its element
// At -element_degree p > 1 the cells are spectral elements subdivided into GLL sub-cells
// (spectral_subdivision.hpp; SpectralLayoutOf groups them back), partitioned whole, and
// serial_cell numbers the sub-cells (element e's sub-cells are e p^dim .. e p^dim + p^dim - 1);
// boxes get the same sub-cells from every rank's part of the lattice (box_lattice.hpp) or, with
// interfaces at p = 2, 4, 8, by refinement on the distributed mesh (box_refinement.hpp).
// -mesh_refine k refines a Gmsh file's mesh k times (mesh_refinement.hpp): on the distributed
// mesh at degree 1 unless -mesh_build serial (or its interfaces do not allow it), else on
// rank 0 after the split (degree 1) or before the subdivision (degree > 1). Either way the
// result is the same mesh up to point numbers, pair ids and serial_cell included.
// The vertical axis is the last coordinate (y in 2D, z in 3D).
#pragma once
#include <petscdmplex.h>

#include <string>
#include <vector>

#include "slipwave/mesh/labels.hpp"
#include "slipwave/meshing/interface_split.hpp"

namespace slipwave::meshing {

struct MeshDescription {
  PetscInt                 dim = 2;
  PetscInt                 degree = 1; // -element_degree: each cell p^dim GLL sub-cells (spectral_subdivision.hpp)
  std::vector<std::string> regions;    // region names, in label-value order
  std::vector<std::string> boundaries; // boundary label names
  std::string              source;     // "box NxM" or the file name, for the report
  std::string              partitioner; // the PetscPartitioner type that distributed the mesh
  std::vector<InterfaceSpec> interfaces; // split along these before distribution
  // Per local cell: its number in the serial mesh (the file's order of cells, or the box's),
  // so messages name a cell the same way on any number of ranks. With -mesh_refine k: the
  // children of file cell s are s 2^dim + r (r = 0 .. 2^dim - 1, PETSc's regular refinement's
  // order), level by level: cell s's descendants are s 2^(dim k) .. (s + 1) 2^(dim k) - 1.
  std::vector<PetscInt> serial_cell;
  double                build_seconds = 0; // wall time of MeshCreate, for the report
};

// Reads the -mesh_* and -regions options, creates, labels and distributes the mesh.
PetscErrorCode MeshCreate(MPI_Comm comm, DM *dm, MeshDescription *desc);

} // namespace slipwave::meshing

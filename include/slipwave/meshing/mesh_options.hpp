// The options that describe the mesh, read in one place before the mesh is built (see
// mesh_builder.hpp for what is built from them):
//   -mesh_file <Gmsh .msh>, -mesh_dim 2|3, -regions a,b,... (1 to kMaxRegions names);
//   box meshes only: -mesh_box_faces/_lower/_upper, -region_<r>_box, -void_regions;
//   -mesh_build auto|serial|distributed (box_refinement.hpp; with -mesh_refine, mesh_refinement.hpp);
//   Gmsh files only: -mesh_refine k (uniform refinements, mesh_refinement.hpp);
//   -element_degree 1..8 (spectral elements on quadrilaterals / hexahedra, spectral_subdivision.hpp);
//   -interfaces n,... with -interface_<n>_regions soil,structure and -interface_<n>_faces.
// The law of each interface is the interface layer's (interface/interface_options.hpp).
#pragma once
#include <petscsys.h>

#include <string>
#include <vector>

#include "slipwave/meshing/interface_split.hpp"

namespace slipwave::meshing {

inline constexpr PetscInt kMaxRegions = 64;
// -mesh_refine: each level multiplies the cells by 2^dim (4096^k in 3D at k = 6 is past any
// machine this runs on).
inline constexpr PetscInt kMaxMeshRefine = 6;

struct BoxSpec {
  PetscInt  faces[3] = {40, 20, 10};
  PetscReal lower[3] = {0, 0, 0};
  PetscReal upper[3] = {100, 50, 25};
};

struct MeshOptions {
  std::string                         file; // Gmsh file; empty: the built-in box
  BoxSpec                             box;
  std::vector<std::string>            regions{"soil"};
  std::vector<std::vector<PetscReal>> region_boxes; // per region; empty: it takes the cells no box claims
  std::vector<std::string>            voids;
  std::vector<InterfaceSpec>          interfaces;
  PetscInt                            build = 0; // -mesh_build: MeshBuild (box_refinement.hpp)
  PetscInt                            refine = 0; // -mesh_refine: uniform refinements of the Gmsh mesh (mesh_refinement.hpp)
  PetscInt                            degree = 1; // -element_degree: spectral elements of this degree (spectral_subdivision.hpp)
};

// Reads and checks the options above; *dim holds the default dimension on entry and the one
// of -mesh_dim on return (a Gmsh file has its own).
PetscErrorCode MeshOptionsRead(MPI_Comm comm, PetscInt *dim, MeshOptions *o);

} // namespace slipwave::meshing

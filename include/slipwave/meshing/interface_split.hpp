// Zero-thickness interfaces in the mesh. On the serial mesh, before distribution, every
// vertex of an interface face is duplicated for the cells on the structure side, so each
// interface node becomes a pair (soil node, structure node) that starts coincident and is
// joined only through the interface law. The end vertices of an interface are split too:
// a footing on the soil surface becomes a separate body.
//
// Labels left on the split mesh (they survive distribution):
//   interface_<name>_pair   vertex, value = pair id (0 .. npairs-1) on both copies; ids follow
//                           the original vertex numbers (deterministic for a given mesh)
//   interface_<name>_side   vertex, value 0 on the soil copy, 1 on the structure copy
//   interface_<name>        the soil-side faces of the interface (value 1)
// Region and boundary labels of the input mesh are carried over (faces of the structure
// side that lie on a named boundary keep that name), and the spectral sub-cell labels
// (labels.hpp) where the mesh has them. Only those: other labels of the input
// (PETSc's "Cell Sets", "Face Sets", ...) are not. Boundary labels are carried on faces only
// (height 1), with their values; a labelled face that the split cuts in two (an interior
// Gmsh group along the interface) is labelled on both sides.
// Numbering: cells keep their numbers and closure vertex order (the cell-vertex lists given to
// DMPlexCreateFromCellList are the original closure orders); original vertices keep theirs,
// the structure copies follow, interface by interface in pair order.
// Where the interface ends inside the mesh (a face_label covering part of the contact, say a
// footing base but not its embedded sides), the end vertices are split too, and the faces
// beyond the end that touch them become two coincident boundary faces of no label.
#pragma once
#include <petscdmplex.h>

#include <string>
#include <vector>

namespace slipwave::meshing {

struct InterfaceSpec {
  std::string name;             // option prefix -interface_<name>_..., output grid name
  std::string soil_region;      // the cells on the soil side
  std::string structure_region; // the cells on the structure side
  std::string face_label;       // optional (Gmsh): restrict to the faces of this label;
                                // empty: every face between the two regions
};

// Serial mesh (all cells on rank 0, as before DMPlexDistribute; interpolated) with the
// "region" label and the boundary labels named in `boundaries`; returns a new split DM on the
// same communicator with the same labels plus the interface labels. Collective. User-input
// errors (PETSC_ERR_USER_INPUT): a spec whose regions share no face (within face_label, if
// given), an unknown region or face label, two specs with one name, and (not supported yet)
// two interfaces with a common vertex. face_label: any face with a value >= 0 counts.
PetscErrorCode InterfaceSplitSerialMesh(DM serial, const std::vector<std::string> &regions, const std::vector<std::string> &boundaries,
                                        const std::vector<InterfaceSpec> &specs, DM *split);

// The pairs of one interface on the distributed mesh (local section with dim dofs per vertex
// set). Each pair is owned by exactly one rank (the owner of its soil vertex); the tables list
// this rank's pairs. Geometry is consistent with the element's lumped face integration:
// area = sum over the soil-side faces around the pair of ∫ N_a dA (a length per unit
// thickness in 2D; spectral elements: the GLL face weights, spectral_face_weights.hpp), normal = the normalised sum of those weights times the outward normal of
// the soil cells (from the soil into the structure).
struct InterfacePairs {
  PetscInt              n_global = 0;
  std::vector<PetscInt> id;            // global pair id
  std::vector<PetscInt> soil_dof;      // global index of the x component of the soil node
  std::vector<PetscInt> structure_dof; // same, structure node
  std::vector<double>   normal;        // dim per pair
  std::vector<double>   area;
  std::vector<double>   coords;        // dim per pair
  // Faces of the interface on this rank (the soil-side faces, each on the rank of its soil
  // cell), as pair ids in the face's closure order (cyclic for quadrilaterals) for the output
  // grid: 2 per face in 2D, 3 or 4 in 3D (one face type per mesh). nodes_per_face is the same
  // on every rank, also where this rank has no face.
  PetscInt              nodes_per_face = 0;
  std::vector<PetscInt> face_pairs;
};

// Collective; needs overlap 0 (each soil-side face on one rank) and DMGetGlobalSection. The
// tables list this rank's pairs in increasing id. Where the interface bends (the corner of an
// embedded footing), the normal is the weighted mean of the faces' normals there.
PetscErrorCode InterfacePairsBuild(DM dm, const InterfaceSpec &spec, InterfacePairs *pairs);

} // namespace slipwave::meshing

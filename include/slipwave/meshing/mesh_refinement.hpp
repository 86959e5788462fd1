// Uniform refinement of a labelled (and split) mesh, serial or distributed (issue 11): each
// level is PETSc's regular refinement (DMPLEXREFINEREGULAR: every edge halved, straight-sided,
// 2^dim children per cell), and the labels are put back as a mesh built at the fine size has
// them (mesh_builder.hpp, interface_split.hpp). Used by box meshes built distributed
// (box_refinement.hpp) and by -mesh_refine k on a Gmsh file, in the way PyLith refines: the
// coarse file is read, labelled, split and partitioned on rank 0, and refined where it lies.
//
// When does splitting the coarse mesh then refining give the split of the fine mesh? The
// coarse split duplicates the children of every coarse point whose vertices are all split; the
// fine split duplicates only the vertices of interface faces. The two agree unless (3D) a soil
// and a structure cell share an edge that lies on no interface face, or the interface is
// restricted to a face label, whose ends the fine split would place differently
// (InterfacesRefinable).
#pragma once
#include <petscdmplex.h>
#include <petscdmplextransform.h>

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "slipwave/meshing/interface_split.hpp"

namespace slipwave::meshing {

// On the coarse, unsplit, serial mesh (regions labelled): whether splitting it before
// refinement gives the fine split (see above). Collective; rank 0 decides.
PetscErrorCode InterfacesRefinable(DM coarse, const std::vector<std::string> &regions, const std::vector<InterfaceSpec> &specs, PetscBool *refinable);

// Refines *dm `levels` times in place. `each_level`, if given, sees every level's transform
// with its coarse and fine mesh (DMPlexTransformGetSourcePoint maps a fine point to the coarse
// point it comes from) before the coarse mesh is destroyed. Collective.
using RefinementLevelHook = std::function<PetscErrorCode(DMPlexTransform, DM coarse, DM fine)>;
PetscErrorCode RefineRegularly(DM *dm, PetscInt levels, const RefinementLevelHook &each_level = nullptr);

// Refinement gives a point's label values to all its children (a face's to the edges and
// vertices inside it): after it, keep the region label on cells only, and each boundary label
// and interface_<name> on faces only.
PetscErrorCode KeepRefinedLabels(DM dm, const std::vector<std::string> &boundaries, const std::vector<InterfaceSpec> &specs);

// What identifies a split vertex on the fine mesh: the same for its soil and structure copy,
// on every rank and in every build of the same mesh; keys order the pair ids.
using PairKey = std::array<int64_t, 8>;
// Sets *known false for a vertex that is on no interface of the kind asked for.
using PairKeyOf = std::function<PetscErrorCode(PetscInt vertex, PairKey *key, bool *known)>;

// Calls `visit` for each vertex in the closure of a face of interface_<name> (the soil-side
// faces), once per face that holds it. Not collective.
PetscErrorCode ForEachInterfaceFaceVertex(DM dm, const InterfaceSpec &spec, const std::function<PetscErrorCode(PetscInt vertex)> &visit);

// Puts interface_<name>_pair/_side back on the refined mesh (interface_<name> already on its
// faces only): the split vertices are the closure vertices of the soil-side faces and their
// structure copies, which share a key; a pair's id is the rank of its key among all of the
// interface's keys. side: 1 on the copy that touches a cell of `structure_region`. Checks
// that each key has exactly one soil and one structure copy. Collective.
PetscErrorCode LabelRefinedPairs(DM dm, const InterfaceSpec &spec, PetscInt structure_region, const PairKeyOf &key_of);

// -mesh_refine on a labelled mesh of one cell type, serial (all on rank 0, split or not) or
// distributed (split before distribution; `specs` then name its interfaces): refines `levels`
// times and puts back the labels (region, `boundaries`, interface_<name> and its _pair/_side);
// other labels (the Gmsh reader's) are dropped first, so that refinement does not copy them.
// serial_cell holds the local coarse cells' serial numbers on entry and the fine cells' on
// return: the children of cell s are s 2^dim + r, r the child's replica in PETSc's regular
// refinement, level by level, so the numbers depend on the coarse numbering only (on one rank
// they are PETSc's own numbering of the refined serial mesh: its children of cell p are
// p 2^dim + r). Pair ids: see the comment at pairKeys in mesh_refinement.cpp. Collective.
PetscErrorCode MeshRefineUniformly(DM *dm, PetscInt levels, const std::vector<std::string> &regions, const std::vector<std::string> &boundaries,
                                   const std::vector<InterfaceSpec> &specs, std::vector<PetscInt> *serial_cell);

} // namespace slipwave::meshing

#include "slipwave/meshing/mesh_builder.hpp"

#include <petscsf.h>

#include "slipwave/core/log_events.hpp"
#include "slipwave/core/option_rules.hpp"
#include "slipwave/mesh/cell_quality_check.hpp"
#include "slipwave/mesh/partition_metis.hpp"
#include "slipwave/mesh/point_centroid.hpp"
#include "slipwave/meshing/box_lattice.hpp"
#include "slipwave/meshing/box_refinement.hpp"
#include "slipwave/meshing/memory_estimate.hpp"
#include "slipwave/meshing/mesh_options.hpp"
#include "slipwave/meshing/mesh_refinement.hpp"
#include "slipwave/meshing/spectral_subdivision.hpp"
#include "slipwave/numerics/gll_basis.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <sstream>

namespace slipwave::meshing {
namespace {

std::vector<std::string> splitNames(const char *list) {
  std::vector<std::string> out;
  std::stringstream        ss(list);
  std::string              item;
  while (std::getline(ss, item, ',')) {
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

PetscErrorCode broadcastFromRoot(MPI_Comm comm, std::string *text) {
  int len = (int)text->size();
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Bcast(&len, 1, MPI_INT, 0, comm));
  text->resize(len);
  if (len) PetscCallMPI(MPI_Bcast(&(*text)[0], len, MPI_CHAR, 0, comm));
  PetscFunctionReturn(0);
}

// Box meshes: each cell goes to the last listed region whose box holds its centroid; a region
// given without a box (bounds[r] empty) takes every cell no other box claims.
PetscErrorCode labelBoxRegions(MPI_Comm comm, DM dm, const std::vector<std::string> &regions, const std::vector<std::vector<PetscReal>> &bounds, const BoxSpec &box) {
  PetscInt dim, c_start, c_end;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscInt fill_region = -1;
  for (size_t r = 0; r < regions.size(); ++r)
    if (bounds[r].empty()) fill_region = (PetscInt)r;
  PetscCall(DMCreateLabel(dm, mesh::kRegionLabel));
  DMLabel label;
  PetscCall(DMGetLabel(dm, mesh::kRegionLabel, &label));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
  std::vector<PetscInt> count(regions.size(), 0);
  std::string           problem;
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscReal x[3];
    PetscCall(mesh::MeshPointCentroid(dm, c, x));
    PetscInt region = fill_region;
    for (size_t r = 0; r < regions.size(); ++r) {
      if (bounds[r].empty()) continue;
      bool inside = true;
      for (PetscInt d = 0; d < dim; ++d) inside = inside && x[d] >= bounds[r][2 * d] && x[d] <= bounds[r][2 * d + 1];
      if (inside) region = (PetscInt)r;
    }
    if (region < 0) {
      char msg[256];
      std::snprintf(msg, sizeof msg,
                    "the cell with centroid (%g, %g%s) lies in no region box; allowed: region boxes that cover the mesh, or one region without -region_<name>_box",
                    (double)x[0], (double)x[1], dim == 3 ? ", ..." : "");
      problem = msg;
      break;
    }
    PetscCall(DMLabelSetValue(label, c, region));
    ++count[region];
  }
  if (c_end > c_start && problem.empty()) {
    for (size_t r = 0; r < regions.size() && problem.empty(); ++r) {
      std::string given = "not given, so it only takes cells no box claims";
      if (!bounds[r].empty()) {
        given = "=";
        for (size_t k = 0; k < bounds[r].size(); ++k) {
          char v[32];
          std::snprintf(v, sizeof v, "%s%g", k ? "," : " ", (double)bounds[r][k]);
          given += v;
        }
      }
      if (count[r] == 0) {
        char msg[512];
        std::snprintf(msg, sizeof msg,
                      "region '%s' contains no cell of the mesh (-region_%s_box %s); allowed: a box holding at least one cell centroid (the mesh spans [%g, %g] x [%g, %g]%s)",
                      regions[r].c_str(), regions[r].c_str(), given.c_str(), (double)box.lower[0], (double)box.upper[0], (double)box.lower[1],
                      (double)box.upper[1], dim == 3 ? " x ..." : "");
        problem = msg;
      }
    }
  }
  // Only rank 0 holds the serial mesh: it decides, and every rank raises the same error.
  PetscCall(broadcastFromRoot(comm, &problem));
  PetscCheck(problem.empty(), comm, PETSC_ERR_USER_INPUT, "%s", problem.c_str());
  PetscFunctionReturn(0);
}

// Marks the box faces on each side by their centroid, so the names do not depend on PETSc's
// internal face numbering.
PetscErrorCode labelBoxSides(DM dm, const BoxSpec &box, std::vector<std::string> *names) {
  PetscInt dim, f_start, f_end;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  const char *names2[4] = {"left", "right", "bottom", "top"};
  const char *names3[6] = {"left", "right", "front", "back", "bottom", "top"};
  const char *const *side_names = dim == 2 ? names2 : names3;
  std::vector<DMLabel> labels(2 * dim);
  for (PetscInt s = 0; s < 2 * dim; ++s) {
    PetscCall(DMCreateLabel(dm, side_names[s]));
    PetscCall(DMGetLabel(dm, side_names[s], &labels[s]));
    names->push_back(side_names[s]);
  }
  PetscCall(DMPlexGetHeightStratum(dm, 1, &f_start, &f_end));
  for (PetscInt f = f_start; f < f_end; ++f) {
    PetscInt support_size;
    PetscCall(DMPlexGetSupportSize(dm, f, &support_size));
    if (support_size != 1) continue;
    PetscReal x[3];
    PetscCall(mesh::MeshPointCentroid(dm, f, x));
    for (PetscInt d = 0; d < dim; ++d) {
      const PetscReal tol = 1e-9 * (box.upper[d] - box.lower[d]);
      if (PetscAbsReal(x[d] - box.lower[d]) < tol) PetscCall(DMLabelSetValue(labels[2 * d], f, 1));
      if (PetscAbsReal(x[d] - box.upper[d]) < tol) PetscCall(DMLabelSetValue(labels[2 * d + 1], f, 1));
    }
  }
  PetscFunctionReturn(0);
}

// Builds `built` (the requested box, or its coarse version when refined later); the memory
// check and the description are those of the requested box (whole: rank 0 will hold all of it).
PetscErrorCode createBox(MPI_Comm comm, PetscInt dim, PetscInt degree, bool whole, DM *dm, const BoxSpec &built, const BoxSpec &requested, std::string *source) {
  double      vertices = 1;
  std::string faces    = "-mesh_box_faces = ";
  PetscFunctionBeginUser;
  for (PetscInt d = 0; d < dim; ++d) {
    vertices *= requested.faces[d] * (double)degree + 1.0; // GLL nodes
    faces += (d ? "," : "") + std::to_string(requested.faces[d]);
  }
  PetscCall(MemoryCheck(comm, vertices, dim, faces.c_str(), whole));
  PetscCall(DMPlexCreateBoxMesh(comm, dim, PETSC_FALSE, built.faces, built.lower, built.upper, nullptr, PETSC_TRUE, dm));
  char buf[128];
  if (dim == 2) std::snprintf(buf, sizeof buf, "box %" PetscInt_FMT " x %" PetscInt_FMT " quadrilaterals", requested.faces[0], requested.faces[1]);
  else std::snprintf(buf, sizeof buf, "box %" PetscInt_FMT " x %" PetscInt_FMT " x %" PetscInt_FMT " hexahedra", requested.faces[0], requested.faces[1], requested.faces[2]);
  *source = buf;
  PetscFunctionReturn(0);
}

// Gmsh: with -dm_plex_gmsh_use_regions PETSc makes one label per physical name. Cell labels
// become regions; face labels become boundaries. refine, whole_on_rank0: for the memory check
// from the file's header (MemoryCheckGmshFile).
PetscErrorCode createFromGmsh(MPI_Comm comm, const char *file, DM *dm, const std::vector<std::string> &regions, std::vector<std::string> *boundaries, PetscInt refine,
                              bool whole_on_rank0) {
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  int  readable = 1;
  char version[32] = ""; // the format of a file PETSc's reader does not take: "1.0", "3.0"
  if (rank == 0) {
    FILE *fp = std::fopen(file, "r");
    readable = fp != nullptr;
    char first[64] = "", second[64] = "";
    if (fp && std::fscanf(fp, "%63s %63s", first, second) == 2) {
      if (!std::strcmp(first, "$NOD")) std::snprintf(version, sizeof version, "1.0");
      else if (!std::strcmp(first, "$MeshFormat") && second[0] != '2' && second[0] != '4') std::snprintf(version, sizeof version, "%.20s", second);
    }
    if (fp) std::fclose(fp);
  }
  PetscCallMPI(MPI_Bcast(&readable, 1, MPI_INT, 0, comm));
  PetscCheck(readable, comm, PETSC_ERR_FILE_OPEN, "-mesh_file = %s: cannot open the file; allowed: a readable Gmsh .msh file (format 2.2 or 4.1)", file);
  PetscCallMPI(MPI_Bcast(version, sizeof version, MPI_CHAR, 0, comm));
  PetscCheck(!version[0], comm, PETSC_ERR_USER_INPUT,
             "-mesh_file = %s is in Gmsh format %s, which is not read; allowed: Gmsh format 2.2 or 4.1 (convert it: gmsh %s -save -format msh41 -o new.msh)", file, version,
             file);
  PetscCall(MemoryCheckGmshFile(comm, file, refine, whole_on_rank0));
  PetscBool has;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-dm_plex_gmsh_use_regions", &has));
  if (!has) PetscCall(PetscOptionsSetValue(nullptr, "-dm_plex_gmsh_use_regions", "true"));
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  PetscErrorCode read_error = DMPlexCreateFromFile(comm, file, "slipwave", PETSC_TRUE, dm);
  PetscCall(PetscPopErrorHandler());
  if (read_error) {
    const char *text = nullptr;
    char       *specific = nullptr;
    PetscErrorMessage(read_error, &text, &specific);
    SETERRQ(comm, PETSC_ERR_USER_INPUT, "-mesh_file = %s: not a valid Gmsh mesh (%s); allowed: a Gmsh .msh file (format 2.2 or 4.1) with physical groups", file,
            specific && specific[0] ? specific : (text ? text : "unreadable"));
  }
  // The reader puts the whole mesh on rank 0; the other ranks hold no points and may lack
  // the physical-name labels. Decide on rank 0 and broadcast, so every rank raises the same
  // error and lists the same boundaries (a check failing on one rank only would hang).
  PetscInt dim, c_start, c_end, f_start, f_end, nlabels;
  PetscCall(DMGetDimension(*dm, &dim));
  PetscCall(DMPlexGetHeightStratum(*dm, 0, &c_start, &c_end));
  PetscCall(DMPlexGetHeightStratum(*dm, 1, &f_start, &f_end));
  PetscCall(DMCreateLabel(*dm, mesh::kRegionLabel));
  DMLabel region_label;
  PetscCall(DMGetLabel(*dm, mesh::kRegionLabel, &region_label));
  for (size_t r = 0; r < regions.size(); ++r) {
    DMLabel label;
    PetscCall(DMGetLabel(*dm, regions[r].c_str(), &label));
    int found = label != nullptr;
    PetscCallMPI(MPI_Bcast(&found, 1, MPI_INT, 0, comm));
    PetscCheck(found, comm, PETSC_ERR_USER_INPUT, "-regions names '%s', but %s has no physical group of that name; allowed: the names of its physical groups",
               regions[r].c_str(), file);
    if (!label) continue;
    for (PetscInt c = c_start; c < c_end; ++c) {
      PetscInt value;
      PetscCall(DMLabelGetValue(label, c, &value));
      if (value >= 0) PetscCall(DMLabelSetValue(region_label, c, (PetscInt)r));
    }
  }
  PetscInt orphan = -1;
  for (PetscInt c = c_start; c < c_end && orphan < 0; ++c) {
    PetscInt value;
    PetscCall(DMLabelGetValue(region_label, c, &value));
    if (value < 0) orphan = c;
  }
  PetscCallMPI(MPI_Bcast(&orphan, 1, MPIU_INT, 0, comm));
  PetscCheck(orphan < 0, comm, PETSC_ERR_USER_INPUT, "cell %" PetscInt_FMT " of %s belongs to none of the regions listed in -regions; allowed: every cell in a listed region", orphan,
             file);
  std::string names; // rank 0's face labels, comma-separated
  PetscCall(DMGetNumLabels(*dm, &nlabels));
  for (PetscInt l = 0; l < nlabels; ++l) {
    const char *name;
    DMLabel     label;
    PetscCall(DMGetLabelName(*dm, l, &name));
    PetscCall(DMGetLabelByNum(*dm, l, &label));
    bool on_faces = false;
    for (PetscInt f = f_start; f < f_end && !on_faces; ++f) {
      PetscInt value;
      PetscCall(DMLabelGetValue(label, f, &value));
      on_faces = value >= 0;
    }
    // PETSc's own labels ("depth" and "celltype" hold every point; the "* Sets" labels hold
    // the physical group numbers) are not boundaries.
    bool internal = false;
    for (const char *own : {"depth", "celltype", "Face Sets", "Cell Sets", "Vertex Sets", "Edge Sets", mesh::kRegionLabel}) internal = internal || std::strcmp(name, own) == 0;
    if (on_faces && !internal) names += (names.empty() ? "" : ",") + std::string(name);
  }
  PetscCall(broadcastFromRoot(comm, &names));
  for (const std::string &name : splitNames(names.c_str())) {
    PetscCall(DMCreateLabel(*dm, name.c_str())); // no-op where it exists
    boundaries->push_back(name);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode checkCellTypes(MPI_Comm comm, DM dm) {
  PetscInt c_start, c_end;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
  DMPolytopeType first = DM_POLYTOPE_UNKNOWN;
  for (PetscInt c = c_start; c < c_end; ++c) {
    DMPolytopeType ct;
    PetscCall(DMPlexGetCellType(dm, c, &ct));
    PetscCheck(ct == DM_POLYTOPE_TRIANGLE || ct == DM_POLYTOPE_QUADRILATERAL || ct == DM_POLYTOPE_TETRAHEDRON || ct == DM_POLYTOPE_HEXAHEDRON, comm,
               PETSC_ERR_USER_INPUT, "cell %" PetscInt_FMT " is a %s; allowed cells: linear triangles, quadrilaterals, tetrahedra, hexahedra", c, DMPolytopeTypes[ct]);
    if (first == DM_POLYTOPE_UNKNOWN) first = ct;
    PetscCheck(ct == first, comm, PETSC_ERR_USER_INPUT, "the mesh mixes %s and %s cells; allowed: one cell type per mesh", DMPolytopeTypes[first], DMPolytopeTypes[ct]);
  }
  PetscFunctionReturn(0);
}

// -void_regions: box regions whose cells are removed, so that a footing can rest on the soil
// surface of a box mesh (the box would otherwise fill the space beside it). The rest is
// labelled again by the same rule; a void region needs no material.
PetscErrorCode removeVoidRegions(MPI_Comm comm, DM *dm, const std::vector<std::string> &voids, std::vector<std::string> *regions,
                                 std::vector<std::vector<PetscReal>> *bounds, const BoxSpec &box) {
  PetscFunctionBeginUser;
  if (voids.empty()) PetscFunctionReturn(0);
  std::vector<std::string>            kept;
  std::vector<std::vector<PetscReal>> kept_bounds;
  for (size_t r = 0; r < regions->size(); ++r)
    if (std::find(voids.begin(), voids.end(), (*regions)[r]) == voids.end()) {
      kept.push_back((*regions)[r]);
      kept_bounds.push_back((*bounds)[r]);
    }
  DMLabel region_label, keep;
  PetscInt c_start, c_end;
  PetscCall(DMGetLabel(*dm, mesh::kRegionLabel, &region_label));
  PetscCall(DMLabelCreate(PETSC_COMM_SELF, "keep", &keep));
  PetscCall(DMPlexGetHeightStratum(*dm, 0, &c_start, &c_end));
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscInt r;
    PetscCall(DMLabelGetValue(region_label, c, &r));
    if (std::find(voids.begin(), voids.end(), (*regions)[r]) == voids.end()) PetscCall(DMLabelSetValue(keep, c, 1));
  }
  DM sub;
  PetscCall(DMPlexFilter(*dm, keep, 1, &sub));
  PetscCall(DMLabelDestroy(&keep));
  PetscCall(DMDestroy(dm));
  *dm     = sub;
  *regions = kept;
  *bounds  = kept_bounds;
  PetscCall(DMRemoveLabel(*dm, mesh::kRegionLabel, nullptr));
  PetscCall(labelBoxRegions(comm, *dm, *regions, *bounds, box));
  PetscFunctionReturn(0);
}

// The box of the serial build, labelled (regions, voids removed, sides): the requested one, or
// with `levels` > 0 its coarse version (2^levels fewer cells per axis); refined: to be refined
// on the distributed mesh (box_refinement.hpp).
PetscErrorCode createLabelledBox(MPI_Comm comm, PetscInt levels, bool refined, MeshOptions *o, DM *dm, MeshDescription *desc) {
  BoxSpec built = o->box;
  PetscFunctionBeginUser;
  for (PetscInt d = 0; d < desc->dim; ++d) built.faces[d] >>= levels;
  desc->regions = o->regions;
  desc->boundaries.clear();
  std::vector<std::vector<PetscReal>> bounds = o->region_boxes;
  PetscCall(createBox(comm, desc->dim, o->degree, !refined, dm, built, o->box, &desc->source));
  PetscCall(labelBoxRegions(comm, *dm, desc->regions, bounds, built));
  PetscCall(removeVoidRegions(comm, dm, o->voids, &desc->regions, &bounds, built));
  PetscCall(labelBoxSides(*dm, built, &desc->boundaries));
  PetscFunctionReturn(0);
}

// -mesh_build: how a box is built. Without interfaces, distributed where it can be
// (box_lattice.hpp: *lattice, on rank 0 `serial` receives the coarse box of `levels`, whose
// partition makes the parts; at degree 1 levels must be > 0, or rank 0 would hold the whole box
// anyway). With interfaces, refined on the distributed mesh (box_refinement.hpp: *levels
// refinements, at degree p = 2, 4, 8 log2(p) of them making the GLL sub-cells, where the coarse
// split refines into the fine split; `serial` receives the box to split and distribute, coarse
// or whole) or else serially (levels 0: the elements, subdivided on rank 0).
PetscErrorCode createBoxForBuild(MPI_Comm comm, MeshOptions *o, DM *serial, MeshDescription *desc, PetscInt *levels, bool *lattice) {
  PetscMPIInt size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<std::vector<PetscReal>> cuts = o->region_boxes; // voids are among the regions
  *levels  = BoxRefinementLevels(desc->dim, o->box, cuts, size, o->build);
  *lattice = o->interfaces.empty() && o->build != kMeshBuildSerial && (*levels > 0 || o->degree > 1);
  if (o->interfaces.empty()) {
    PetscCheck(*lattice || o->build != kMeshBuildDistributed, comm, PETSC_ERR_USER_INPUT,
               "-mesh_build = distributed, but the box has no coarser box to partition it by (every -mesh_box_faces entry even, region box bounds on the coarse grid, at "
               "least one coarse cell per rank); allowed: auto or serial, or -element_degree above 1");
    if (!*lattice) *levels = 0;
    PetscCall(createLabelledBox(comm, *levels, *lattice, o, serial, desc));
    PetscFunctionReturn(0);
  }
  const PetscInt spectral = BoxSpectralRefinements(o->degree);
  PetscCheck(spectral >= 0 || o->build != kMeshBuildDistributed, comm, PETSC_ERR_USER_INPUT,
             "-mesh_build = distributed with -element_degree = %" PetscInt_FMT " and interfaces; allowed: -element_degree 1, 2, 4 or 8 (GLL sub-cells made by refinement), or -mesh_build auto or serial",
             o->degree);
  // Degrees that are no power of 2 are subdivided on the serial mesh: auto builds serially.
  if (spectral < 0) *levels = 0;
  PetscCheck(*levels > 0 || spectral > 0 || o->build != kMeshBuildDistributed, comm, PETSC_ERR_USER_INPUT,
             "-mesh_build = distributed, but the box cannot be refined from a coarser one (every -mesh_box_faces entry even, region box bounds on the coarse grid, at "
             "least one coarse cell per rank); allowed: auto or serial");
  const bool refined = *levels > 0 || (spectral > 0 && o->build != kMeshBuildSerial);
  PetscCall(createLabelledBox(comm, *levels, refined, o, serial, desc));
  if (refined) *levels += spectral;
  if (!refined) PetscFunctionReturn(0);
  PetscBool refinable;
  PetscCall(InterfacesRefinable(*serial, desc->regions, o->interfaces, &refinable));
  PetscCheck(refinable || o->build != kMeshBuildDistributed, comm, PETSC_ERR_USER_INPUT,
             "-mesh_build = distributed, but an interface is restricted to a face label or its regions meet along an edge outside it; allowed: auto or serial");
  if (refinable) PetscFunctionReturn(0);
  PetscCall(DMDestroy(serial));
  *levels = 0;
  PetscCall(createLabelledBox(comm, 0, false, o, serial, desc));
  PetscFunctionReturn(0);
}

// PETSc stops an unknown -petscpartitioner_type with a traceback, and this PETSc registers
// parmetis and chaco without having them; refuse all but the partitioners that work here.
PetscErrorCode checkPartitionerType(MPI_Comm comm) {
  const char *const working[] = {mesh::kPartitionerMetis, "ptscotch", "simple", "gather"};
  char              type[256] = "";
  PetscBool         set       = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-petscpartitioner_type", type, sizeof type, &set));
  std::string allowed;
  bool        known = !set;
  for (const char *name : working) {
    known = known || std::strcmp(name, type) == 0;
    allowed += (allowed.empty() ? "" : ", ") + std::string(name);
  }
  PetscCheck(known, comm, PETSC_ERR_USER_INPUT, "-petscpartitioner_type = %s; allowed: %s", type, allowed.c_str());
  PetscFunctionReturn(0);
}

// The migration SF's leaves are the distributed points, its roots the serial points (cells
// first, in the serial mesh's cell order); without it (one rank) the numbers are unchanged.
PetscErrorCode recordSerialCells(DM dm, PetscSF migration, std::vector<PetscInt> *serial_cell) {
  PetscInt c_start, c_end;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
  serial_cell->resize(c_end - c_start);
  for (PetscInt c = c_start; c < c_end; ++c) (*serial_cell)[c - c_start] = c;
  if (!migration) PetscFunctionReturn(0);
  PetscInt           nleaves;
  const PetscInt    *local;
  const PetscSFNode *remote;
  PetscCall(PetscSFGetGraph(migration, nullptr, &nleaves, &local, &remote));
  for (PetscInt i = 0; i < nleaves; ++i) {
    const PetscInt point = local ? local[i] : i;
    if (point >= c_start && point < c_end) (*serial_cell)[point - c_start] = remote[i].index;
  }
  PetscFunctionReturn(0);
}

// Spectral elements of degree p > 1 need the tensor-product cells (rank 0 holds them all).
PetscErrorCode checkSpectralCells(MPI_Comm comm, DM serial, PetscInt degree) {
  PetscInt c_start, c_end;
  PetscInt linear_only = -1; // the cell type of rank 0's mesh where it is a simplex
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(serial, 0, &c_start, &c_end));
  if (c_end > c_start) {
    DMPolytopeType ct;
    PetscCall(DMPlexGetCellType(serial, c_start, &ct));
    if (ct == DM_POLYTOPE_TRIANGLE || ct == DM_POLYTOPE_TETRAHEDRON) linear_only = (PetscInt)ct;
  }
  PetscCallMPI(MPI_Bcast(&linear_only, 1, MPIU_INT, 0, comm));
  PetscCheck(linear_only < 0, comm, PETSC_ERR_USER_INPUT,
             "-element_degree = %" PetscInt_FMT " with a mesh of %s cells; allowed: 1 (triangles and tetrahedra are linear only), or 1 to %d with quadrilaterals or hexahedra", degree,
             DMPolytopeTypes[linear_only < 0 ? 0 : linear_only], numerics::kMaxSpectralDegree);
  PetscFunctionReturn(0);
}

// The reader holds the whole mesh on rank 0; what follows (subdivision, split, distribution,
// operators) needs the estimate's memory. Degree p: the GLL nodes, (p-1)^d inside each point
// of depth d (V + (p-1) E + (p-1)^2 F + (p-1)^3 C; the file's vertices at p = 1), of the mesh
// refined `refine` times (RefinedPointFactor); whole_on_rank0 false: refined distributed.
PetscErrorCode checkMemoryOfFile(MPI_Comm comm, DM serial, PetscInt dim, PetscInt degree, const std::string &file, PetscInt refine, bool whole_on_rank0) {
  double nodes = 0, inside = 1; // inside: GLL nodes inside one point of the depth
  PetscFunctionBeginUser;
  for (PetscInt depth = 0; depth <= dim; ++depth, inside *= (double)(degree - 1)) {
    PetscInt start, end;
    PetscCall(DMPlexGetDepthStratum(serial, depth, &start, &end));
    nodes += inside * (double)(end - start);
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &nodes, 1, MPI_DOUBLE, MPI_SUM, comm));
  const std::string what = MeshFileDescription(file.c_str(), refine) + (degree > 1 ? " at -element_degree " + std::to_string(degree) : "");
  PetscCall(MemoryCheck(comm, nodes * RefinedPointFactor(dim, refine), dim, what.c_str(), whole_on_rank0));
  PetscFunctionReturn(0);
}

// A Gmsh file (with -mesh_refine k, mesh_refinement.hpp): at -element_degree 1 and unless
// -mesh_build serial, rank 0 reads, labels and (later) splits the coarse file and the
// distributed mesh is refined k times (*levels = k), where the coarse split refines into the
// fine one and every rank gets a coarse cell; otherwise rank 0 refines (refineOnRank0).
PetscErrorCode createGmshForBuild(MPI_Comm comm, const MeshOptions &o, DM *serial, MeshDescription *desc, PetscInt *levels) {
  PetscMPIInt size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCheck(o.degree == 1 || o.refine == 0 || o.build != kMeshBuildDistributed, comm, PETSC_ERR_USER_INPUT,
             "-mesh_build = distributed with -mesh_refine = %" PetscInt_FMT " and -element_degree = %" PetscInt_FMT
             "; allowed: auto or serial (spectral elements are refined and subdivided on the serial mesh)",
             o.refine, o.degree);
  bool distributed = o.refine > 0 && o.degree == 1 && o.build != kMeshBuildSerial;
  PetscCall(createFromGmsh(comm, o.file.c_str(), serial, desc->regions, &desc->boundaries, o.refine, !distributed));
  PetscCall(DMGetDimension(*serial, &desc->dim));
  PetscCall(core::OptionsValidateForDimension(comm, desc->dim, false));
  if (distributed) {
    PetscInt  c_start, c_end, cells;
    PetscBool refinable = PETSC_TRUE;
    PetscCall(DMPlexGetHeightStratum(*serial, 0, &c_start, &c_end));
    cells = c_end - c_start;
    PetscCallMPI(MPI_Bcast(&cells, 1, MPIU_INT, 0, comm));
    if (!o.interfaces.empty()) PetscCall(InterfacesRefinable(*serial, desc->regions, o.interfaces, &refinable));
    PetscCheck((refinable && cells >= size) || o.build != kMeshBuildDistributed, comm, PETSC_ERR_USER_INPUT,
               "-mesh_build = distributed with -mesh_file = %s, but %s; allowed: auto or serial", o.file.c_str(),
               refinable ? "the file has fewer cells than there are ranks" : "an interface is restricted to a face label or its regions meet along an edge outside it");
    distributed = refinable && cells >= size;
  }
  PetscCall(checkMemoryOfFile(comm, *serial, desc->dim, o.degree, o.file, o.refine, !distributed));
  *levels      = distributed ? o.refine : 0;
  desc->source = o.file;
  if (o.refine > 0) desc->source += (distributed ? ", built distributed: refined " : ", refined ") + std::to_string(o.refine) + (distributed ? " times" : " times on rank 0");
  PetscFunctionReturn(0);
}

// -mesh_refine on the serial mesh. MeshRefineUniformly's numbering of the fine cells is PETSc's
// own order of the refined serial mesh (one cell type per mesh), so the cells keep their
// numbers as serial numbers (recordSerialCells, spectral sub-cells); checked.
PetscErrorCode refineOnRank0(DM *serial, PetscInt levels, const MeshDescription &desc, const std::vector<InterfaceSpec> &specs) {
  PetscInt c_start, c_end;
  PetscFunctionBeginUser;
  if (levels == 0) PetscFunctionReturn(0);
  PetscCall(DMPlexGetHeightStratum(*serial, 0, &c_start, &c_end));
  std::vector<PetscInt> numbers(c_end - c_start);
  std::iota(numbers.begin(), numbers.end(), c_start);
  PetscCall(MeshRefineUniformly(serial, levels, desc.regions, desc.boundaries, specs, &numbers));
  PetscCall(DMPlexGetHeightStratum(*serial, 0, &c_start, &c_end));
  PetscInt wrong[2] = {-1, -1}; // the first cell whose number differs, and that number
  for (PetscInt c = c_start; c < c_end && wrong[0] < 0; ++c)
    if (numbers[c - c_start] != c) wrong[0] = c, wrong[1] = numbers[c - c_start];
  // Only rank 0 holds cells: it decides, and every rank stops alike (no rank left waiting).
  PetscCallMPI(MPI_Bcast(wrong, 2, MPIU_INT, 0, PetscObjectComm((PetscObject)*serial)));
  PetscCheck(wrong[0] < 0, PetscObjectComm((PetscObject)*serial), PETSC_ERR_PLIB, "refined cell %" PetscInt_FMT " numbered %" PetscInt_FMT " by its coarse cell", wrong[0],
             wrong[1]);
  PetscFunctionReturn(0);
}

// The partitioner of `serial`: METIS by default (this PETSc has none of its own; slipwave
// registers it, here, so every program that builds a mesh has it); the user can still pick
// another with -petscpartitioner_type.
PetscErrorCode configurePartitioner(MPI_Comm comm, DM serial, MeshDescription *desc, PetscPartitioner *part) {
  PetscPartitionerType part_type;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetPartitioner(serial, part));
  PetscCall(mesh::PartitionerRegisterMetis());
  PetscCall(checkPartitionerType(comm));
  PetscCall(PetscPartitionerSetType(*part, mesh::kPartitionerMetis));
  PetscCall(PetscPartitionerSetFromOptions(*part));
  PetscCall(PetscPartitionerGetType(*part, &part_type));
  desc->partitioner = part_type;
  PetscFunctionReturn(0);
}

// Every mesh but a box built on the lattice: the serial mesh (elements subdivided into their
// GLL sub-cells at p > 1 unless refined later, split along the interfaces, refined on rank 0
// at -mesh_refine without a distributed build) distributed, then refined `levels` times.
PetscErrorCode createSerialAndDistribute(MPI_Comm comm, const MeshOptions &o, PetscInt levels, PetscInt serial_levels, DM serial, DM *dm, MeshDescription *desc) {
  DM parent = nullptr; // spectral elements: the mesh of whole elements, partitioned for the sub-cells
  PetscFunctionBeginUser;
  if (o.degree > 1 && levels == 0) {
    parent = serial;
    PetscCall(SpectralSubdivideSerialMesh(parent, o.degree, desc->boundaries, &serial));
  }
  if (!desc->interfaces.empty()) {
    DM split;
    PetscCall(InterfaceSplitSerialMesh(serial, desc->regions, desc->boundaries, desc->interfaces, &split));
    PetscCall(DMDestroy(&serial));
    serial = split;
  }
  if (o.degree == 1) PetscCall(refineOnRank0(&serial, serial_levels, *desc, desc->interfaces));
  PetscPartitioner part;
  DM               dist = nullptr;
  PetscCall(configurePartitioner(comm, parent ? parent : serial, desc, &part));
  if (parent) {
    PetscCall(SpectralPartitionWholeElements(parent, part, o.degree, serial));
    PetscCall(DMDestroy(&parent));
  }
  PetscSF migration = nullptr;
  PetscCall(DMPlexDistribute(serial, 0, &migration, &dist));
  if (dist) {
    PetscCall(DMDestroy(&serial));
    *dm = dist;
  } else {
    *dm = serial;
  }
  const bool box_refined = levels > 0 && o.file.empty(); // BoxRefineDistributed numbers the cells itself
  if (!box_refined) PetscCall(recordSerialCells(*dm, migration, &desc->serial_cell));
  PetscCall(PetscSFDestroy(&migration));
  if (box_refined) {
    PetscCall(BoxRefineDistributed(dm, levels, o.degree, o.box, desc->regions, desc->boundaries, desc->interfaces, &desc->serial_cell));
    desc->source += ", built distributed: refined " + std::to_string(levels) + " times";
    if (o.degree > 1) desc->source += " (" + std::to_string(BoxSpectralRefinements(o.degree)) + " into the GLL sub-cells)";
  } else if (levels > 0) {
    PetscCall(MeshRefineUniformly(dm, levels, desc->regions, desc->boundaries, desc->interfaces, &desc->serial_cell));
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode MeshCreate(MPI_Comm comm, DM *dm, MeshDescription *desc) {
  MeshOptions o;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(core::event_mesh, 0, 0, 0, 0));
  PetscCall(MeshOptionsRead(comm, &desc->dim, &o));
  desc->regions    = o.regions;
  desc->interfaces = o.interfaces;
  PetscLogDouble start;
  PetscCall(PetscTime(&start));

  DM       serial;
  PetscInt levels  = 0;     // refinements on the distributed mesh (box_refinement.hpp, mesh_refinement.hpp), or the coarse box's level (box_lattice.hpp)
  bool     lattice = false; // a box built on the lattice by every rank (box_lattice.hpp)
  if (!o.file.empty()) {
    PetscCall(createGmshForBuild(comm, o, &serial, desc, &levels));
  } else {
    PetscCall(core::OptionsValidateForDimension(comm, desc->dim, true));
    PetscCall(createBoxForBuild(comm, &o, &serial, desc, &levels, &lattice));
  }
  PetscCall(checkCellTypes(comm, serial));
  desc->degree = o.degree;
  const PetscInt serial_levels = o.file.empty() ? 0 : o.refine - levels; // -mesh_refine on rank 0
  if (o.degree > 1) {
    PetscCall(checkSpectralCells(comm, serial, o.degree));
    PetscCall(refineOnRank0(&serial, serial_levels, *desc, {}));
    // The elements' shape, not their GLL sub-cells' (whose aspect comes from the GLL spacing);
    // a box built distributed has its coarse cells here, its elements scaled by 2^k on every
    // axis: the same aspect and Jacobian ratio.
    PetscCall(mesh::CellQualityCheckSerialMesh(serial));
  }
  if (lattice) {
    PetscPartitioner part;
    PetscCall(configurePartitioner(comm, serial, desc, &part));
    PetscCall(BoxLatticeBuild(serial, part, levels, o.degree, o.box, desc->boundaries, dm, &desc->serial_cell));
    PetscCall(DMDestroy(&serial));
    std::string coarse;
    for (PetscInt d = 0; d < desc->dim; ++d) coarse += (d ? " x " : "") + std::to_string(o.box.faces[d] >> levels);
    desc->source += ", built distributed: every rank builds its part (partitioned as " + coarse + " coarse cells)";
  } else {
    PetscCall(createSerialAndDistribute(comm, o, levels, serial_levels, serial, dm, desc));
  }
  PetscLogDouble end;
  PetscCall(PetscTime(&end));
  desc->build_seconds = end - start;
  PetscCall(PetscObjectSetName((PetscObject)*dm, "mesh"));
  PetscCall(PetscLogEventEnd(core::event_mesh, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

} // namespace slipwave::meshing

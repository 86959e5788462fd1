#include "slipwave/mesh/mesh_builder.hpp"
#include "slipwave/mesh/point_centroid.hpp"
#include "slipwave/mesh/partition_metis.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <sstream>

namespace slipwave::mesh {
namespace {

constexpr PetscInt kMaxRegions = 64;

struct BoxSpec {
  PetscInt  faces[3] = {40, 20, 10};
  PetscReal lower[3] = {0, 0, 0};
  PetscReal upper[3] = {100, 50, 25};
};

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
  PetscCall(DMCreateLabel(dm, kRegionLabel));
  DMLabel label;
  PetscCall(DMGetLabel(dm, kRegionLabel, &label));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
  std::vector<PetscInt> count(regions.size(), 0);
  std::string           problem;
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscReal x[3];
    PetscCall(MeshPointCentroid(dm, c, x));
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
    PetscCall(MeshPointCentroid(dm, f, x));
    for (PetscInt d = 0; d < dim; ++d) {
      const PetscReal tol = 1e-9 * (box.upper[d] - box.lower[d]);
      if (PetscAbsReal(x[d] - box.lower[d]) < tol) PetscCall(DMLabelSetValue(labels[2 * d], f, 1));
      if (PetscAbsReal(x[d] - box.upper[d]) < tol) PetscCall(DMLabelSetValue(labels[2 * d + 1], f, 1));
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode createBox(MPI_Comm comm, PetscInt dim, DM *dm, const BoxSpec *box, std::string *source) {
  PetscFunctionBeginUser;
  PetscCall(DMPlexCreateBoxMesh(comm, dim, PETSC_FALSE, box->faces, box->lower, box->upper, nullptr, PETSC_TRUE, dm));
  char buf[128];
  if (dim == 2) std::snprintf(buf, sizeof buf, "box %" PetscInt_FMT " x %" PetscInt_FMT " quadrilaterals", box->faces[0], box->faces[1]);
  else std::snprintf(buf, sizeof buf, "box %" PetscInt_FMT " x %" PetscInt_FMT " x %" PetscInt_FMT " hexahedra", box->faces[0], box->faces[1], box->faces[2]);
  *source = buf;
  PetscFunctionReturn(0);
}

// Gmsh: with -dm_plex_gmsh_use_regions PETSc makes one label per physical name. Cell labels
// become regions; face labels become boundaries.
PetscErrorCode createFromGmsh(MPI_Comm comm, const char *file, DM *dm, const std::vector<std::string> &regions, std::vector<std::string> *boundaries) {
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  int readable = 1;
  if (rank == 0) {
    FILE *fp = std::fopen(file, "r");
    readable = fp != nullptr;
    if (fp) std::fclose(fp);
  }
  PetscCallMPI(MPI_Bcast(&readable, 1, MPI_INT, 0, comm));
  PetscCheck(readable, comm, PETSC_ERR_FILE_OPEN, "-mesh_file = %s: cannot open the file; allowed: a readable Gmsh .msh file (format 2.2 or 4.1)", file);
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
  PetscCall(DMCreateLabel(*dm, kRegionLabel));
  DMLabel region_label;
  PetscCall(DMGetLabel(*dm, kRegionLabel, &region_label));
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
    for (const char *own : {"depth", "celltype", "Face Sets", "Cell Sets", "Vertex Sets", "Edge Sets", kRegionLabel}) internal = internal || std::strcmp(name, own) == 0;
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
  PetscCall(DMGetLabel(*dm, kRegionLabel, &region_label));
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
  PetscCall(DMRemoveLabel(*dm, kRegionLabel, nullptr));
  PetscCall(labelBoxRegions(comm, *dm, *regions, *bounds, box));
  PetscFunctionReturn(0);
}

// A comma-separated list of names (blanks around a name ignored) read with
// PetscOptionsStringArray; *names keeps its default when the option is not given. At most
// max_names are read; *count says how many were given (max_names + 1: too many).
PetscErrorCode readNameList(PetscOptionItems *PetscOptionsObject, const char *name, const char *help, PetscInt max_names, std::vector<std::string> *names,
                            PetscInt *count, PetscBool *set) {
  std::vector<char *> items(max_names + 1, nullptr);
  PetscInt            n = max_names + 1;
  PetscBool           given = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsStringArray(name, help, "MeshCreate", items.data(), &n, &given));
  if (given) {
    names->clear();
    for (PetscInt i = 0; i < n; ++i) {
      std::string item = items[i];
      item.erase(0, item.find_first_not_of(" \t"));
      item.erase(item.find_last_not_of(" \t") + 1);
      if (!item.empty()) names->push_back(item);
      PetscCall(PetscFree(items[i]));
    }
  }
  if (count) *count = given ? n : (PetscInt)names->size();
  if (set) *set = given;
  PetscFunctionReturn(0);
}

std::string joinNames(const std::vector<std::string> &names) {
  std::string s;
  for (size_t i = 0; i < names.size(); ++i) s += (i ? "," : "") + names[i];
  return s;
}

// Everything the mesh options say, read in one place before the mesh is built:
//   -mesh_file, -mesh_dim, -regions; box meshes: -mesh_box_faces/_lower/_upper,
//   -region_<r>_box, -void_regions; -interfaces with -interface_<n>_regions, _faces.
struct MeshOptions {
  std::string                         file; // Gmsh file; empty: the built-in box
  BoxSpec                             box;
  std::vector<std::string>            regions{"soil"};
  std::vector<std::vector<PetscReal>> region_boxes; // per region; empty: it takes the cells no box claims
  std::vector<std::string>            voids;
  std::vector<InterfaceSpec>          interfaces;
};

PetscErrorCode readBoxOptions(MPI_Comm comm, PetscInt dim, BoxSpec *box) {
  PetscInt  n = dim;
  PetscBool set;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "mesh_box_", "Built-in box mesh (quadrilaterals in 2D, hexahedra in 3D)", "slipwave");
  PetscCall(PetscOptionsIntArray("-faces", "number of cells along x,y[,z], >= 1", "MeshCreate", box->faces, &n, &set));
  PetscCheck(!set || n == dim, comm, PETSC_ERR_USER_INPUT, "-mesh_box_faces has %" PetscInt_FMT " values; allowed: %" PetscInt_FMT " positive integers", n, dim);
  n = dim;
  PetscCall(PetscOptionsRealArray("-lower", "lower corner x,y[,z] [m]", "MeshCreate", box->lower, &n, &set));
  PetscCheck(!set || n == dim, comm, PETSC_ERR_USER_INPUT, "-mesh_box_lower has %" PetscInt_FMT " values; allowed: %" PetscInt_FMT " coordinates", n, dim);
  n = dim;
  PetscCall(PetscOptionsRealArray("-upper", "upper corner x,y[,z] [m], > lower", "MeshCreate", box->upper, &n, &set));
  PetscCheck(!set || n == dim, comm, PETSC_ERR_USER_INPUT, "-mesh_box_upper has %" PetscInt_FMT " values; allowed: %" PetscInt_FMT " coordinates", n, dim);
  PetscOptionsEnd();
  for (PetscInt d = 0; d < dim; ++d) {
    PetscCheck(box->faces[d] > 0, comm, PETSC_ERR_USER_INPUT, "-mesh_box_faces: %" PetscInt_FMT " cells on axis %" PetscInt_FMT "; allowed: >= 1", box->faces[d], d);
    PetscCheck(box->upper[d] > box->lower[d], comm, PETSC_ERR_USER_INPUT, "-mesh_box_upper (%g) <= -mesh_box_lower (%g) on axis %" PetscInt_FMT "; allowed: upper > lower",
               (double)box->upper[d], (double)box->lower[d], d);
  }
  PetscFunctionReturn(0);
}

// -region_<r>_box for every region, each in its block "Region <r>" (so -help lists it).
PetscErrorCode readRegionBoxes(MPI_Comm comm, PetscInt dim, const std::vector<std::string> &regions, std::vector<std::vector<PetscReal>> *bounds) {
  PetscInt fill_region = -1;
  PetscFunctionBeginUser;
  bounds->assign(regions.size(), {});
  for (size_t r = 0; r < regions.size(); ++r) {
    const std::string prefix = "region_" + regions[r] + "_", title = "Region " + regions[r];
    const std::string opt    = "-" + prefix + "box";
    PetscReal         b[6]   = {0, 0, 0, 0, 0, 0};
    PetscInt          n      = 2 * dim;
    PetscBool         set    = PETSC_FALSE;
    PetscOptionsBegin(comm, prefix.c_str(), title.c_str(), "slipwave");
    PetscCall(PetscOptionsRealArray("-box", "xmin,xmax,ymin,ymax[,zmin,zmax] [m], min < max: the cells whose centroid lies inside belong to the region (the last "
                                    "listed wins; one region without a box takes the rest)",
                                    "MeshCreate", b, &n, &set));
    PetscOptionsEnd();
    if (set) {
      PetscCheck(n == 2 * dim, comm, PETSC_ERR_USER_INPUT, "%s has %" PetscInt_FMT " values; allowed: %" PetscInt_FMT " values xmin,xmax,ymin,ymax%s", opt.c_str(), n,
                 2 * dim, dim == 3 ? ",zmin,zmax" : "");
      for (PetscInt d = 0; d < dim; ++d)
        PetscCheck(b[2 * d] < b[2 * d + 1], comm, PETSC_ERR_USER_INPUT, "%s: min %g >= max %g on axis %" PetscInt_FMT "; allowed: min < max", opt.c_str(),
                   (double)b[2 * d], (double)b[2 * d + 1], d);
      (*bounds)[r].assign(b, b + 2 * dim);
    } else {
      PetscCheck(fill_region < 0, comm, PETSC_ERR_USER_INPUT,
                 "regions '%s' and '%s' both have no -region_<name>_box; allowed: at most one region without a box (it takes the remaining cells)",
                 regions[fill_region].c_str(), regions[r].c_str());
      fill_region = (PetscInt)r;
    }
  }
  PetscFunctionReturn(0);
}

// -interfaces a,b with -interface_<name>_regions soil_region,structure_region and an
// optional -interface_<name>_faces <face label> (Gmsh physical group). `regions`: the
// regions left once the void ones are removed.
PetscErrorCode readInterfaceSpecs(MPI_Comm comm, const std::vector<std::string> &regions, std::vector<InterfaceSpec> *specs) {
  std::vector<std::string> names;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "Interfaces (split nodes)", "slipwave");
  PetscCall(readNameList(PetscOptionsObject, "-interfaces", "comma-separated names of soil-structure interfaces (each with -interface_<name>_regions)", kMaxRegions, &names,
                         nullptr, nullptr));
  PetscOptionsEnd();
  for (const std::string &name : names) {
    const std::string        prefix = "interface_" + name + "_";
    const std::string        title  = "Interface " + name + " (geometry)";
    char                     faces[256] = "";
    std::vector<std::string> two;
    PetscInt                 ntwo = 0;
    PetscBool                has_pair = PETSC_FALSE;
    PetscOptionsBegin(comm, prefix.c_str(), title.c_str(), "slipwave");
    PetscCall(readNameList(PetscOptionsObject, "-regions", "soil_region,structure_region: the interface is every face between them", 2, &two, &ntwo, &has_pair));
    PetscCall(PetscOptionsString("-faces", "restrict the interface to the faces of this label (Gmsh physical group)", "MeshCreate", faces, faces, sizeof faces, nullptr));
    PetscOptionsEnd();
    const std::string pair = joinNames(two);
    PetscCheck(has_pair && ntwo == 2 && two.size() == 2, comm, PETSC_ERR_USER_INPUT, "-interface_%s_regions = '%s'; allowed: two region names soil_region,structure_region",
               name.c_str(), pair.c_str());
    for (const std::string &r : two)
      PetscCheck(std::find(regions.begin(), regions.end(), r) != regions.end(), comm, PETSC_ERR_USER_INPUT,
                 "-interface_%s_regions names '%s', which is not a region; allowed: names listed in -regions", name.c_str(), r.c_str());
    PetscCheck(two[0] != two[1], comm, PETSC_ERR_USER_INPUT, "-interface_%s_regions = '%s'; allowed: two different regions", name.c_str(), pair.c_str());
    specs->push_back(InterfaceSpec{name, two[0], two[1], faces});
  }
  PetscFunctionReturn(0);
}

PetscErrorCode readMeshOptions(MPI_Comm comm, PetscInt *dim, MeshOptions *o) {
  char      file[PETSC_MAX_PATH_LEN] = "";
  PetscBool from_file = PETSC_FALSE;
  PetscInt  nregions  = 0;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "Mesh and regions", "slipwave");
  PetscCall(PetscOptionsString("-mesh_file", "Gmsh .msh file; without it a built-in box mesh is used", "MeshCreate", file, file, sizeof file, &from_file));
  PetscCall(PetscOptionsRangeInt("-mesh_dim", "dimension of the built-in box mesh (2 = plane strain, 3)", "MeshCreate", *dim, dim, nullptr, 2, 3));
  PetscCall(readNameList(PetscOptionsObject, "-regions", "comma-separated region names, 1 to 64 (box: each with -region_<name>_box; Gmsh: physical group names)",
                         kMaxRegions, &o->regions, &nregions, nullptr));
  from_file = (PetscBool)(from_file && file[0]);
  if (!from_file)
    PetscCall(readNameList(PetscOptionsObject, "-void_regions", "box regions (from -regions) whose cells are removed from the mesh, e.g. the space beside a footing",
                           kMaxRegions, &o->voids, nullptr, nullptr));
  PetscOptionsEnd();
  PetscCheck(!o->regions.empty() && nregions <= kMaxRegions, comm, PETSC_ERR_USER_INPUT, "-regions = '%s'; allowed: 1 to %" PetscInt_FMT " comma-separated names",
             joinNames(o->regions).c_str(), kMaxRegions);
  o->file = from_file ? file : "";
  std::vector<std::string> kept = o->regions;
  if (!from_file) {
    PetscCall(readBoxOptions(comm, *dim, &o->box));
    PetscCall(readRegionBoxes(comm, *dim, o->regions, &o->region_boxes));
    for (const std::string &v : o->voids)
      PetscCheck(std::find(o->regions.begin(), o->regions.end(), v) != o->regions.end(), comm, PETSC_ERR_USER_INPUT,
                 "-void_regions names '%s', which is not in -regions; allowed: region names listed in -regions", v.c_str());
    kept.clear();
    for (const std::string &r : o->regions)
      if (std::find(o->voids.begin(), o->voids.end(), r) == o->voids.end()) kept.push_back(r);
    PetscCheck(!kept.empty(), comm, PETSC_ERR_USER_INPUT, "-void_regions removes every region; allowed: at least one region that is not void");
  }
  PetscCall(readInterfaceSpecs(comm, kept, &o->interfaces));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode MeshCreate(MPI_Comm comm, DM *dm, MeshDescription *desc) {
  MeshOptions o;
  PetscFunctionBeginUser;
  PetscCall(readMeshOptions(comm, &desc->dim, &o));
  desc->regions    = o.regions;
  desc->interfaces = o.interfaces;

  DM serial;
  if (!o.file.empty()) {
    PetscCall(createFromGmsh(comm, o.file.c_str(), &serial, desc->regions, &desc->boundaries));
    PetscCall(DMGetDimension(serial, &desc->dim));
    desc->source = o.file;
  } else {
    PetscCall(createBox(comm, desc->dim, &serial, &o.box, &desc->source));
    PetscCall(labelBoxRegions(comm, serial, desc->regions, o.region_boxes, o.box));
    PetscCall(removeVoidRegions(comm, &serial, o.voids, &desc->regions, &o.region_boxes, o.box));
    PetscCall(labelBoxSides(serial, o.box, &desc->boundaries));
  }
  PetscCall(checkCellTypes(comm, serial));
  if (!desc->interfaces.empty()) {
    DM split;
    PetscCall(InterfaceSplitSerialMesh(serial, desc->regions, desc->boundaries, desc->interfaces, &split));
    PetscCall(DMDestroy(&serial));
    serial = split;
  }

  PetscPartitioner part;
  DM               dist = nullptr;
  PetscCall(DMPlexGetPartitioner(serial, &part));
  // METIS is the default (this PETSc has none of its own; slipwave registers it, here, so every
  // program that builds a mesh has it); the user can still pick another with
  // -petscpartitioner_type.
  PetscCall(PartitionerRegisterMetis());
  PetscCall(PetscPartitionerSetType(part, kPartitionerMetis));
  PetscCall(PetscPartitionerSetFromOptions(part));
  PetscPartitionerType part_type;
  PetscCall(PetscPartitionerGetType(part, &part_type));
  desc->partitioner = part_type;
  PetscCall(DMPlexDistribute(serial, 0, nullptr, &dist));
  if (dist) {
    PetscCall(DMDestroy(&serial));
    *dm = dist;
  } else {
    *dm = serial;
  }
  PetscCall(PetscObjectSetName((PetscObject)*dm, "mesh"));
  PetscFunctionReturn(0);
}

} // namespace slipwave::mesh

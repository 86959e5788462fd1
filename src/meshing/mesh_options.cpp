#include "slipwave/meshing/mesh_options.hpp"

#include "slipwave/meshing/box_refinement.hpp"
#include "slipwave/meshing/region_box_fit.hpp"
#include "slipwave/numerics/gll_basis.hpp"

#include <algorithm>
#include <cstdio>

namespace slipwave::meshing {
namespace {

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

std::string joinBounds(const std::vector<double> &b) {
  std::string out;
  for (size_t k = 0; k < b.size(); ++k) {
    char v[32];
    std::snprintf(v, sizeof v, "%s%.6g", k ? "," : "", b[k]);
    out += v;
  }
  return out;
}

// Each region box must be one the box mesh can represent (region_box_fit.hpp): refused before
// the mesh is built, naming the box the cells would give.
PetscErrorCode checkRegionBoxesFit(MPI_Comm comm, PetscInt dim, const BoxSpec &box, const std::vector<std::string> &regions,
                                   const std::vector<std::vector<PetscReal>> &bounds) {
  PetscFunctionBeginUser;
  for (size_t r = 0; r < regions.size(); ++r) {
    if (bounds[r].empty()) continue;
    const std::vector<double> given(bounds[r].begin(), bounds[r].end());
    const RegionBoxFit        fit = RegionBoxOnMesh((int)dim, box, given);
    if (fit.fits) continue;
    char        tolerance[32]; // PETSc's own %g would print 1 as "1."
    std::snprintf(tolerance, sizeof tolerance, "%g", 100 * kRegionBoxFitTolerance);
    std::string faces, grid;
    for (PetscInt d = 0; d < dim; ++d) {
      char line[96];
      std::snprintf(line, sizeof line, "%s%c = %.6g + k*%.6g", d ? ", " : "", "xyz"[d], (double)box.lower[d], (double)((box.upper[d] - box.lower[d]) / box.faces[d]));
      grid += line;
      faces += (d ? "," : "") + std::to_string(box.faces[d]);
    }
    SETERRQ(comm, PETSC_ERR_USER_INPUT,
            "-region_%s_box = %s does not fit the mesh (-mesh_box_faces %s): cells join a region by their centroid, so region '%s' would be the box %s; allowed: "
            "box faces on grid lines (%s, within %s %% of a cell) or on or beyond the mesh's sides (change the box or -mesh_box_faces)",
            regions[r].c_str(), joinBounds(given).c_str(), faces.c_str(), regions[r].c_str(), joinBounds(fit.meshed).c_str(), grid.c_str(), tolerance);
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

} // namespace

PetscErrorCode MeshOptionsRead(MPI_Comm comm, PetscInt *dim, MeshOptions *o) {
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
  PetscBool build_set = PETSC_FALSE;
  PetscCall(PetscOptionsEList("-mesh_build",
                              "how a box mesh or a refined -mesh_file is built: auto (a box: distributed where it allows it and has >= 1000 coarse cells per rank, "
                              "or at -element_degree > 1 (with interfaces: 2, 4, 8); a file with -mesh_refine > 0: distributed where its interfaces allow it), serial "
                              "(whole mesh on rank 0, then distributed), distributed (every rank builds its part of a box partitioned as a coarse box, or a coarse mesh "
                              "refined on the distributed mesh)",
                              "MeshCreate", kMeshBuildNames, 3, kMeshBuildNames[o->build], &o->build, &build_set));
  PetscBool refine_set = PETSC_FALSE;
  PetscCall(PetscOptionsRangeInt("-mesh_refine",
                                 "refine the -mesh_file mesh k times uniformly, 0 to 6: each time every edge is halved (straight-sided, 2^dim children per cell); "
                                 "at -element_degree 1 on the distributed mesh unless -mesh_build serial",
                                 "MeshCreate", o->refine, &o->refine, &refine_set, 0, kMaxMeshRefine));
  PetscCheck(!(refine_set && !from_file && o->refine > 0), comm, PETSC_ERR_USER_INPUT,
             "-mesh_refine = %" PetscInt_FMT " with a box mesh; allowed: 0 with a box mesh (set -mesh_box_faces)", o->refine);
  PetscCheck(!(build_set && from_file && o->build == kMeshBuildDistributed && o->refine == 0), comm, PETSC_ERR_USER_INPUT,
             "-mesh_build = distributed with -mesh_file = %s and -mesh_refine 0; allowed: auto or serial, or -mesh_refine > 0 (a Gmsh file is read whole, then refined "
             "on the distributed mesh)",
             file);
  PetscCall(PetscOptionsRangeInt("-element_degree",
                                 "degree p of the spectral elements (GLL nodes), 1 to 8; p > 1 needs quadrilaterals or hexahedra (triangles and tetrahedra are linear only)",
                                 "MeshCreate", o->degree, &o->degree, nullptr, 1, numerics::kMaxSpectralDegree));
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
    PetscCall(checkRegionBoxesFit(comm, *dim, o->box, o->regions, o->region_boxes));
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

} // namespace slipwave::meshing

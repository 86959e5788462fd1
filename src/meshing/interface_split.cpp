#include "slipwave/mesh/point_centroid.hpp"
#include "slipwave/mesh/spectral_face_weights.hpp"
#include "slipwave/mesh/vertex_coordinates.hpp"
#include "slipwave/meshing/interface_split.hpp"

#include "slipwave/mesh/labels.hpp"
#include "slipwave/numerics/reference_cell.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace slipwave::meshing {
namespace {

// Up to 4 vertices of a face, sorted, padded with -1: the key that finds a face of the new
// mesh from the (mapped) vertex set of a face of the old one.
using FaceKey = std::array<PetscInt, 4>;

FaceKey makeKey(const PetscInt *v, PetscInt n) {
  FaceKey k;
  k.fill(-1);
  const int m = n < 4 ? (int)n : 4;
  for (int i = 0; i < m; ++i) k[i] = v[i];
  for (int i = 1; i < m; ++i) // insertion sort of at most 4 entries
    for (int j = i; j > 0 && k[j - 1] > k[j]; --j) std::swap(k[j - 1], k[j]);
  return k;
}

// Vertices of point p in closure order (for a cell: the order the element code sees).
PetscErrorCode closureVertices(DM dm, PetscInt p, PetscInt v_start, PetscInt v_end, std::vector<PetscInt> *verts) {
  PetscInt *closure = nullptr, nclosure;
  PetscFunctionBeginUser;
  verts->clear();
  PetscCall(DMPlexGetTransitiveClosure(dm, p, PETSC_TRUE, &nclosure, &closure));
  for (PetscInt i = 0; i < nclosure; ++i)
    if (closure[2 * i] >= v_start && closure[2 * i] < v_end) verts->push_back(closure[2 * i]);
  PetscCall(DMPlexRestoreTransitiveClosure(dm, p, PETSC_TRUE, &nclosure, &closure));
  PetscFunctionReturn(0);
}

PetscInt regionIndex(const std::vector<std::string> &regions, const std::string &name) {
  for (size_t r = 0; r < regions.size(); ++r)
    if (regions[r] == name) return (PetscInt)r;
  return -1;
}

std::string joinNames(const std::vector<std::string> &names) {
  std::string s;
  for (size_t i = 0; i < names.size(); ++i) s += (i ? ", " : "") + names[i];
  return s;
}

// The serial mesh being split: its point ranges and region label (on rank 0; the other
// ranks hold no points).
struct SerialMesh {
  DM          dm;
  MPI_Comm    comm;
  PetscMPIInt rank;
  PetscInt    dim, cdim, c_start, c_end, v_start, v_end, f_start, f_end;
  DMLabel     region_label;
};

PetscErrorCode serialMeshGet(DM dm, SerialMesh *m) {
  PetscFunctionBeginUser;
  m->dm   = dm;
  m->comm = PetscObjectComm((PetscObject)dm);
  PetscCallMPI(MPI_Comm_rank(m->comm, &m->rank));
  PetscCall(DMGetDimension(dm, &m->dim));
  PetscCall(DMGetCoordinateDim(dm, &m->cdim));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &m->c_start, &m->c_end));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &m->v_start, &m->v_end));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &m->f_start, &m->f_end));
  PetscCall(DMGetLabel(dm, mesh::kRegionLabel, &m->region_label));
  {
    // Labels may exist only on rank 0 (the one holding the cells): decide there, for everyone.
    PetscInt depth, ok[2];
    PetscCall(DMPlexGetDepth(dm, &depth));
    ok[0] = m->region_label != nullptr, ok[1] = depth == m->dim;
    PetscCallMPI(MPI_Bcast(ok, 2, MPIU_INT, 0, m->comm));
    PetscCheck(ok[0], m->comm, PETSC_ERR_ARG_WRONG, "InterfaceSplitSerialMesh: the mesh has no '%s' label; label the regions first", mesh::kRegionLabel);
    PetscCheck(ok[1], m->comm, PETSC_ERR_ARG_WRONG, "InterfaceSplitSerialMesh: the mesh is not interpolated (no faces); create it with interpolate = PETSC_TRUE");
  }
  // The split must see every cell: a mesh already spread over ranks would lose the faces
  // between ranks (and PETSc's own split corrupts distributed meshes, see the notes).
  PetscInt on_other_ranks = m->rank == 0 ? 0 : m->c_end - m->c_start;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &on_other_ranks, 1, MPIU_INT, MPI_SUM, m->comm));
  PetscCheck(on_other_ranks == 0, m->comm, PETSC_ERR_ARG_WRONG,
             "InterfaceSplitSerialMesh: %" PetscInt_FMT " cells on ranks other than 0; split the serial mesh before DMPlexDistribute", on_other_ranks);
  PetscFunctionReturn(0);
}

// What the split does to the old mesh: which vertices are doubled and which cells get the copy.
struct SplitPlan {
  std::vector<PetscInt>              soil_of, structure_of;    // per spec: region indices
  std::vector<PetscInt>              spec_of;                  // per old vertex: its interface (-1: none)
  std::vector<std::vector<PetscInt>> iface_faces, iface_verts; // per spec: old points
  std::vector<PetscInt>              copy_of;                  // per old vertex: new number of its structure copy (-1: none)
  PetscInt                           nv_new = 0;
  PetscInt                           v_start = 0;
  // A vertex seen from a cell of `region`: structure cells of its interface get the copy.
  PetscInt mapVertex(PetscInt v, PetscInt region) const {
    const PetscInt s = spec_of[v - v_start];
    return (s >= 0 && region == structure_of[s]) ? copy_of[v - v_start] : v - v_start;
  }
};

PetscErrorCode resolveSpecRegions(MPI_Comm comm, const std::vector<std::string> &regions, const std::vector<InterfaceSpec> &specs, SplitPlan *plan) {
  const size_t nspecs = specs.size();
  PetscFunctionBeginUser;
  plan->soil_of.resize(nspecs);
  plan->structure_of.resize(nspecs);
  for (size_t s = 0; s < nspecs; ++s) {
    const InterfaceSpec &sp = specs[s];
    plan->soil_of[s]        = regionIndex(regions, sp.soil_region);
    plan->structure_of[s]   = regionIndex(regions, sp.structure_region);
    PetscCheck(plan->soil_of[s] >= 0, comm, PETSC_ERR_USER_INPUT, "interface '%s': soil region '%s' is not a region of the mesh; allowed: %s", sp.name.c_str(),
               sp.soil_region.c_str(), joinNames(regions).c_str());
    PetscCheck(plan->structure_of[s] >= 0, comm, PETSC_ERR_USER_INPUT, "interface '%s': structure region '%s' is not a region of the mesh; allowed: %s", sp.name.c_str(),
               sp.structure_region.c_str(), joinNames(regions).c_str());
    PetscCheck(plan->soil_of[s] != plan->structure_of[s], comm, PETSC_ERR_USER_INPUT,
               "interface '%s': soil and structure region are both '%s'; allowed: two different regions", sp.name.c_str(), sp.soil_region.c_str());
    for (size_t t = 0; t < s; ++t)
      PetscCheck(specs[t].name != sp.name, comm, PETSC_ERR_USER_INPUT, "interface '%s' is defined twice; allowed: distinct interface names", sp.name.c_str());
  }
  PetscFunctionReturn(0);
}

// The faces of interface s (soil cell on one side, structure cell on the other, within its
// face label if it has one) and the vertices they touch, in the order of the original vertex
// numbers, so the pair ids are deterministic for a given mesh.
PetscErrorCode findInterfaceFaces(const SerialMesh &m, const std::vector<std::string> &boundaries, const std::vector<InterfaceSpec> &specs, PetscInt s,
                                  SplitPlan *plan) {
  const InterfaceSpec  &sp         = specs[s];
  DMLabel               face_label = nullptr;
  PetscInt              touching   = -1; // an earlier interface that shares a vertex with this one
  std::vector<PetscInt> fverts;
  PetscFunctionBeginUser;
  if (!sp.face_label.empty()) {
    PetscCall(DMGetLabel(m.dm, sp.face_label.c_str(), &face_label));
    PetscInt exists = face_label != nullptr;
    PetscCallMPI(MPI_Bcast(&exists, 1, MPIU_INT, 0, m.comm));
    PetscCheck(exists, m.comm, PETSC_ERR_USER_INPUT, "interface '%s': face label '%s' does not exist in the mesh; allowed: a face group of the mesh (%s)", sp.name.c_str(),
               sp.face_label.c_str(), joinNames(boundaries).c_str());
  }
  for (PetscInt f = m.f_start; f < m.f_end; ++f) {
    PetscInt nsupp;
    PetscCall(DMPlexGetSupportSize(m.dm, f, &nsupp));
    if (nsupp != 2) continue;
    const PetscInt *supp;
    PetscInt        r0, r1;
    PetscCall(DMPlexGetSupport(m.dm, f, &supp));
    PetscCall(DMLabelGetValue(m.region_label, supp[0], &r0));
    PetscCall(DMLabelGetValue(m.region_label, supp[1], &r1));
    const bool between = (r0 == plan->soil_of[s] && r1 == plan->structure_of[s]) || (r1 == plan->soil_of[s] && r0 == plan->structure_of[s]);
    if (!between) continue;
    if (face_label) {
      PetscInt value;
      PetscCall(DMLabelGetValue(face_label, f, &value));
      if (value < 0) continue;
    }
    plan->iface_faces[s].push_back(f);
    PetscCall(closureVertices(m.dm, f, m.v_start, m.v_end, &fverts));
    for (PetscInt v : fverts) {
      PetscInt &owner = plan->spec_of[v - m.v_start];
      if (owner >= 0 && owner != s) {
        if (touching < 0) touching = owner;
        continue;
      }
      if (owner < 0) plan->iface_verts[s].push_back(v);
      owner = s;
    }
  }
  // A vertex on two interfaces would need three copies and a rule for which cells get which.
  PetscCallMPI(MPI_Bcast(&touching, 1, MPIU_INT, 0, m.comm));
  PetscCheck(touching < 0, m.comm, PETSC_ERR_USER_INPUT, "interfaces '%s' and '%s' share a vertex; not supported yet: interfaces without a common vertex",
             specs[touching].name.c_str(), sp.name.c_str());
  // Only rank 0 holds cells: the verdict must reach every rank before anyone errors out.
  PetscInt nfaces = (PetscInt)plan->iface_faces[s].size();
  PetscCallMPI(MPI_Bcast(&nfaces, 1, MPIU_INT, 0, m.comm));
  PetscCheck(nfaces > 0, m.comm, PETSC_ERR_USER_INPUT,
             "interface '%s': regions '%s' (soil) and '%s' (structure) share no face%s%s%s; allowed: two regions that touch along faces", sp.name.c_str(),
             sp.soil_region.c_str(), sp.structure_region.c_str(), sp.face_label.empty() ? "" : " within face label '", sp.face_label.c_str(),
             sp.face_label.empty() ? "" : "'");
  std::sort(plan->iface_verts[s].begin(), plan->iface_verts[s].end());
  PetscFunctionReturn(0);
}

// 1. The interface faces and vertices of every spec; 2. new vertex numbers: the originals
// keep theirs (0..nv_old-1), the structure copies follow, spec by spec in pair order.
PetscErrorCode planSplit(const SerialMesh &m, const std::vector<std::string> &regions, const std::vector<std::string> &boundaries,
                         const std::vector<InterfaceSpec> &specs, SplitPlan *plan) {
  const PetscInt nspecs = (PetscInt)specs.size(), nv_old = m.v_end - m.v_start;
  PetscFunctionBeginUser;
  PetscCall(resolveSpecRegions(m.comm, regions, specs, plan));
  plan->v_start = m.v_start;
  plan->spec_of.assign(nv_old, -1);
  plan->iface_faces.assign(nspecs, {});
  plan->iface_verts.assign(nspecs, {});
  for (PetscInt s = 0; s < nspecs; ++s) PetscCall(findInterfaceFaces(m, boundaries, specs, s, plan));
  plan->copy_of.assign(nv_old, -1);
  plan->nv_new = nv_old;
  for (PetscInt s = 0; s < nspecs; ++s)
    for (PetscInt v : plan->iface_verts[s]) plan->copy_of[v - m.v_start] = plan->nv_new++;
  PetscFunctionReturn(0);
}

// The split mesh as DMPlexCreateFromCellList takes it: cell-vertex lists in the original
// closure order (so the new cells have the orientation and vertex order of the old ones) and
// the vertex coordinates, the copies exactly on their originals.
struct CellList {
  PetscInt               ncells = 0, ncorners = 0;
  std::vector<PetscInt>  cells, cell_region;
  std::vector<PetscReal> xyz;
};

PetscErrorCode buildCellList(const SerialMesh &m, const SplitPlan &plan, CellList *list) {
  std::vector<PetscInt> cverts;
  PetscFunctionBeginUser;
  list->ncells = m.c_end - m.c_start;
  list->cell_region.resize(list->ncells);
  for (PetscInt c = m.c_start; c < m.c_end; ++c) {
    PetscInt region;
    PetscCall(DMLabelGetValue(m.region_label, c, &region));
    PetscCheck(region >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "InterfaceSplitSerialMesh: cell %" PetscInt_FMT " has no region", c);
    list->cell_region[c - m.c_start] = region;
    PetscCall(closureVertices(m.dm, c, m.v_start, m.v_end, &cverts));
    if (c == m.c_start) list->ncorners = (PetscInt)cverts.size();
    PetscCheck((PetscInt)cverts.size() == list->ncorners, PETSC_COMM_SELF, PETSC_ERR_SUP,
               "InterfaceSplitSerialMesh: cell %" PetscInt_FMT " has %zu vertices, cell %" PetscInt_FMT " has %" PetscInt_FMT "; one cell type per mesh", c, cverts.size(),
               m.c_start, list->ncorners);
    for (PetscInt v : cverts) list->cells.push_back(plan.mapVertex(v, region));
  }
  PetscCallMPI(MPI_Bcast(&list->ncorners, 1, MPIU_INT, 0, m.comm));

  list->xyz.resize((size_t)plan.nv_new * m.cdim);
  // The copies sit exactly on their originals.
  mesh::VertexCoordinates coords;
  PetscCall(coords.Open(m.dm));
  for (PetscInt v = m.v_start; v < m.v_end; ++v) {
    PetscReal *xv = &list->xyz[(size_t)(v - m.v_start) * m.cdim];
    PetscCall(coords.Get(v, xv));
    if (plan.copy_of[v - m.v_start] >= 0) std::copy(xv, xv + m.cdim, &list->xyz[(size_t)plan.copy_of[v - m.v_start] * m.cdim]);
  }
  PetscCall(coords.Close());
  PetscFunctionReturn(0);
}

// 3. The new mesh from the cell list, named as the old one. Everything after relies on PETSc
// keeping the cell and vertex numbers of the list (cell k = first cell + k, vertex k = first
// vertex + k) and on the closure returning the vertices in the order given: check both,
// cheaply, instead of trusting them. (PETSc reproduces any order it is given, so this does
// not prove the cells valid: that follows from passing the closure order of the valid
// original cells; tests/unit/test_interface_split.cpp checks it with DMPlexCheck and
// cell-by-cell coordinates for quads, hexes, triangles and tets.)
PetscErrorCode rebuildMesh(const SerialMesh &m, const SplitPlan &plan, const CellList &list, DM *dm) {
  const bool            root = m.rank == 0;
  std::vector<PetscInt> cverts;
  PetscFunctionBeginUser;
  PetscCall(DMPlexCreateFromCellListPetsc(m.comm, m.dim, root ? list.ncells : 0, root ? plan.nv_new : 0, list.ncorners, PETSC_TRUE, root ? list.cells.data() : nullptr,
                                          m.cdim, root ? list.xyz.data() : nullptr, dm));
  const char *name;
  PetscCall(PetscObjectGetName((PetscObject)m.dm, &name));
  PetscCall(PetscObjectSetName((PetscObject)*dm, name));

  PetscInt nc_start, nc_end, nv_start, nv_end;
  PetscCall(DMPlexGetHeightStratum(*dm, 0, &nc_start, &nc_end));
  PetscCall(DMPlexGetDepthStratum(*dm, 0, &nv_start, &nv_end));
  PetscCheck(nc_end - nc_start == (root ? list.ncells : 0) && nv_end - nv_start == (root ? plan.nv_new : 0), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "InterfaceSplitSerialMesh: the rebuilt mesh has %" PetscInt_FMT " cells and %" PetscInt_FMT " vertices, expected %" PetscInt_FMT " and %" PetscInt_FMT,
             nc_end - nc_start, nv_end - nv_start, list.ncells, plan.nv_new);
  for (PetscInt c = 0; c < (root ? list.ncells : 0); ++c) {
    PetscCall(closureVertices(*dm, nc_start + c, nv_start, nv_end, &cverts));
    bool same = (PetscInt)cverts.size() == list.ncorners;
    for (PetscInt a = 0; a < list.ncorners && same; ++a) same = cverts[a] - nv_start == list.cells[c * list.ncorners + a];
    PetscCheck(same, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "InterfaceSplitSerialMesh: cell %" PetscInt_FMT " of the rebuilt mesh lists its vertices in another order than the original cell", c);
  }
  PetscFunctionReturn(0);
}

// Finds the faces of the new mesh by their vertex sets.
class NewFaceFinder {
public:
  PetscErrorCode Setup(DM dm) {
    PetscInt              nv_start, nv_end, nf_start, nf_end;
    std::vector<PetscInt> fverts;
    PetscFunctionBeginUser;
    PetscCall(DMPlexGetDepthStratum(dm, 0, &nv_start, &nv_end));
    PetscCall(DMPlexGetHeightStratum(dm, 1, &nf_start, &nf_end));
    for (PetscInt f = nf_start; f < nf_end; ++f) {
      PetscCall(closureVertices(dm, f, nv_start, nv_end, &fverts));
      for (PetscInt &v : fverts) v -= nv_start;
      face_of_.emplace_back(makeKey(fverts.data(), (PetscInt)fverts.size()), f);
    }
    std::sort(face_of_.begin(), face_of_.end());
    PetscFunctionReturn(0);
  }
  // The new face made of the old face f's vertices as seen from a cell of `region`.
  PetscErrorCode Find(const SerialMesh &m, const SplitPlan &plan, PetscInt f, PetscInt region, PetscInt *nf) const {
    std::vector<PetscInt> vs;
    PetscFunctionBeginUser;
    PetscCall(closureVertices(m.dm, f, m.v_start, m.v_end, &vs));
    for (PetscInt &v : vs) v = plan.mapVertex(v, region);
    const FaceKey key = makeKey(vs.data(), (PetscInt)vs.size());
    auto          it  = std::lower_bound(face_of_.begin(), face_of_.end(), std::make_pair(key, (PetscInt)-1));
    PetscCheck(it != face_of_.end() && it->first == key, PETSC_COMM_SELF, PETSC_ERR_PLIB, "InterfaceSplitSerialMesh: face %" PetscInt_FMT " has no counterpart in the rebuilt mesh",
               f);
    *nf = it->second;
    PetscFunctionReturn(0);
  }

private:
  std::vector<std::pair<FaceKey, PetscInt>> face_of_;
};

// 4a. The region label, and the boundary labels: each labelled face goes to the new face of
// each of its cells, so a face split by an interface (say an interior Gmsh group along it) is
// labelled on both sides.
PetscErrorCode copyLabels(const SerialMesh &m, const SplitPlan &plan, const CellList &list, const NewFaceFinder &faces, const std::vector<std::string> &boundaries,
                          DM dm) {
  PetscInt nc_start, nc_end;
  DMLabel  new_region;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &nc_start, &nc_end));
  PetscCall(DMCreateLabel(dm, mesh::kRegionLabel));
  PetscCall(DMGetLabel(dm, mesh::kRegionLabel, &new_region));
  for (PetscInt c = 0; c < (m.rank == 0 ? list.ncells : 0); ++c) PetscCall(DMLabelSetValue(new_region, nc_start + c, list.cell_region[c]));
  // The sub-cells of spectral elements (spectral_subdivision.hpp) keep their position in
  // their element: cells keep their numbers.
  for (const char *name : {mesh::kSpectralPositionLabel}) {
    DMLabel old_label, new_label;
    PetscCall(DMGetLabel(m.dm, name, &old_label));
    PetscInt has = old_label != nullptr;
    PetscCallMPI(MPI_Bcast(&has, 1, MPIU_INT, 0, m.comm));
    if (!has) continue;
    PetscCall(DMCreateLabel(dm, name));
    PetscCall(DMGetLabel(dm, name, &new_label));
    for (PetscInt c = 0; c < (m.rank == 0 ? list.ncells : 0); ++c) {
      PetscInt value;
      PetscCall(DMLabelGetValue(old_label, m.c_start + c, &value));
      PetscCall(DMLabelSetValue(new_label, nc_start + c, value));
    }
  }
  for (const std::string &name : boundaries) {
    DMLabel old_label, new_label;
    PetscCall(DMCreateLabel(dm, name.c_str()));
    PetscCall(DMGetLabel(dm, name.c_str(), &new_label));
    PetscCall(DMGetLabel(m.dm, name.c_str(), &old_label));
    if (!old_label) continue; // created empty on ranks that have no points, keep it that way
    for (PetscInt f = m.f_start; f < m.f_end; ++f) {
      PetscInt value;
      PetscCall(DMLabelGetValue(old_label, f, &value));
      if (value < 0) continue;
      PetscInt        nsupp;
      const PetscInt *supp;
      PetscCall(DMPlexGetSupportSize(m.dm, f, &nsupp));
      PetscCall(DMPlexGetSupport(m.dm, f, &supp));
      for (PetscInt k = 0; k < nsupp; ++k) {
        PetscInt nf = -1;
        PetscCall(faces.Find(m, plan, f, list.cell_region[supp[k] - m.c_start], &nf));
        PetscCall(DMLabelSetValue(new_label, nf, value));
      }
    }
  }
  PetscFunctionReturn(0);
}

// 4b. Per interface: interface_<n>_pair (pair id on both vertices of a pair),
// interface_<n>_side (0 soil, 1 structure) and interface_<n> (its soil-side faces).
PetscErrorCode labelInterfaces(const SerialMesh &m, const SplitPlan &plan, const NewFaceFinder &faces, const std::vector<InterfaceSpec> &specs, DM dm) {
  PetscInt nv_start, nv_end;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &nv_start, &nv_end));
  for (size_t s = 0; s < specs.size(); ++s) {
    const std::string base = "interface_" + specs[s].name;
    DMLabel           pair_label, side_label, face_label;
    PetscCall(DMCreateLabel(dm, (base + "_pair").c_str()));
    PetscCall(DMCreateLabel(dm, (base + "_side").c_str()));
    PetscCall(DMCreateLabel(dm, base.c_str()));
    PetscCall(DMGetLabel(dm, (base + "_pair").c_str(), &pair_label));
    PetscCall(DMGetLabel(dm, (base + "_side").c_str(), &side_label));
    PetscCall(DMGetLabel(dm, base.c_str(), &face_label));
    for (size_t p = 0; p < plan.iface_verts[s].size(); ++p) {
      const PetscInt v     = plan.iface_verts[s][p];
      const PetscInt soil  = nv_start + (v - m.v_start);
      const PetscInt strct = nv_start + plan.copy_of[v - m.v_start];
      PetscCall(DMLabelSetValue(pair_label, soil, (PetscInt)p));
      PetscCall(DMLabelSetValue(pair_label, strct, (PetscInt)p));
      PetscCall(DMLabelSetValue(side_label, soil, 0));
      PetscCall(DMLabelSetValue(side_label, strct, 1));
    }
    for (PetscInt f : plan.iface_faces[s]) {
      PetscInt nf = -1;
      PetscCall(faces.Find(m, plan, f, plan.soil_of[s], &nf));
      PetscCall(DMLabelSetValue(face_label, nf, 1));
    }
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode InterfaceSplitSerialMesh(DM serial, const std::vector<std::string> &regions, const std::vector<std::string> &boundaries,
                                        const std::vector<InterfaceSpec> &specs, DM *split) {
  SerialMesh    m;
  SplitPlan     plan;
  CellList      list;
  NewFaceFinder faces;
  DM            dm;
  PetscFunctionBeginUser;
  PetscCall(serialMeshGet(serial, &m));
  PetscCall(planSplit(m, regions, boundaries, specs, &plan));
  PetscCall(buildCellList(m, plan, &list));
  PetscCall(rebuildMesh(m, plan, list, &dm));
  PetscCall(faces.Setup(dm));
  PetscCall(copyLabels(m, plan, list, faces, boundaries, dm));
  PetscCall(labelInterfaces(m, plan, faces, specs, dm));
  *split = dm;
  PetscFunctionReturn(0);
}

PetscErrorCode InterfacePairsBuild(DM dm, const InterfaceSpec &spec, InterfacePairs *pairs) {
  MPI_Comm     comm = PetscObjectComm((PetscObject)dm);
  PetscMPIInt  rank;
  PetscInt     dim, v_start, v_end, f_start, f_end;
  DMLabel      pair_label, side_label, face_label;
  PetscSection gsec;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v_start, &v_end));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &f_start, &f_end));
  const std::string base = "interface_" + spec.name;
  PetscCall(DMGetLabel(dm, (base + "_pair").c_str(), &pair_label));
  PetscCall(DMGetLabel(dm, (base + "_side").c_str(), &side_label));
  PetscCall(DMGetLabel(dm, base.c_str(), &face_label));
  PetscCheck(pair_label && side_label && face_label, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
             "InterfacePairsBuild: the mesh has no labels of interface '%s'; split it with InterfaceSplitSerialMesh before distributing", spec.name.c_str());
  PetscCall(DMGetGlobalSection(dm, &gsec));

  // Number of pairs: the largest pair id anywhere + 1.
  PetscInt npairs = -1;
  {
    IS values;
    PetscInt        n;
    const PetscInt *vals;
    PetscCall(DMLabelGetValueIS(pair_label, &values));
    PetscCall(ISGetLocalSize(values, &n));
    PetscCall(ISGetIndices(values, &vals));
    for (PetscInt i = 0; i < n; ++i) npairs = std::max(npairs, vals[i]);
    PetscCall(ISRestoreIndices(values, &vals));
    PetscCall(ISDestroy(&values));
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &npairs, 1, MPIU_INT, MPI_MAX, comm));
  ++npairs;
  PetscCheck(npairs > 0, comm, PETSC_ERR_ARG_WRONG, "InterfacePairsBuild: interface '%s' has no pairs", spec.name.c_str());

  // Per pair, over all ranks: dofs (any rank that sees a vertex knows its global offset; ghosts
  // store -(off+1)), the owner (the rank where the soil vertex is not a ghost) and the soil
  // vertex coordinates (summed: only the owner contributes).
  std::vector<PetscInt> soil(npairs, -1), strct(npairs, -1), owner(npairs, -1);
  std::vector<double>   geo((size_t)npairs * (2 * dim + 1), 0.0); // area, nsum[dim], x[dim]
  auto                  area = [&](PetscInt p) -> double & { return geo[(size_t)p * (2 * dim + 1)]; };
  auto                  nsum = [&](PetscInt p) { return &geo[(size_t)p * (2 * dim + 1) + 1]; };
  auto                  xp   = [&](PetscInt p) { return &geo[(size_t)p * (2 * dim + 1) + 1 + dim]; };

  const mesh::SpectralLayout *spectral; // degree > 1: GLL face weights of the elements' sides
  PetscCall(mesh::SpectralLayoutOf(dm, &spectral));
  PetscInt c_start;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, nullptr));
  mesh::VertexCoordinates coords;
  PetscCall(coords.Open(dm));

  for (PetscInt v = v_start; v < v_end; ++v) {
    PetscInt p, side;
    PetscCall(DMLabelGetValue(pair_label, v, &p));
    if (p < 0) continue;
    PetscCall(DMLabelGetValue(side_label, v, &side));
    PetscCheck(p < npairs && (side == 0 || side == 1), PETSC_COMM_SELF, PETSC_ERR_PLIB, "InterfacePairsBuild: vertex %" PetscInt_FMT " has pair %" PetscInt_FMT " side %" PetscInt_FMT, v, p, side);
    PetscInt ndof, off;
    PetscCall(PetscSectionGetDof(gsec, v, &ndof));
    PetscCall(PetscSectionGetOffset(gsec, v, &off));
    // Ghost points carry -(dof+1) and -(off+1) in the global section.
    if (ndof < 0) ndof = -(ndof + 1);
    PetscCheck(ndof == dim, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "InterfacePairsBuild: vertex %" PetscInt_FMT " has %" PetscInt_FMT " dofs; the section must have dim = %" PetscInt_FMT " dofs per vertex",
               v, ndof, dim);
    const bool     owned  = off >= 0;
    const PetscInt goff   = owned ? off : -(off + 1);
    (side == 0 ? soil : strct)[p] = goff;
    if (side == 0 && owned) {
      owner[p] = rank;
      PetscCall(coords.Get(v, xp(p)));
    }
  }

  // Soil-side faces of the interface: with overlap 0 each lives only on the rank of its soil
  // cell, so summing over ranks counts every face once.
  std::vector<PetscInt> fverts, face_pairs;
  PetscInt              nodes_per_face = 0;
  for (PetscInt f = f_start; f < f_end; ++f) {
    PetscInt value;
    PetscCall(DMLabelGetValue(face_label, f, &value));
    if (value < 0) continue;
    PetscInt        nsupp;
    const PetscInt *supp;
    PetscCall(DMPlexGetSupportSize(dm, f, &nsupp));
    PetscCall(DMPlexGetSupport(dm, f, &supp));
    PetscCheck(nsupp == 1, PETSC_COMM_SELF, PETSC_ERR_PLIB, "InterfacePairsBuild: interface face %" PetscInt_FMT " has %" PetscInt_FMT " cells; expected only its soil cell (split mesh, overlap 0)", f,
               nsupp);
    PetscCall(closureVertices(dm, f, v_start, v_end, &fverts));
    const PetscInt nfv = (PetscInt)fverts.size();
    PetscCheck(nfv >= 2 && nfv <= 4 && (nodes_per_face == 0 || nodes_per_face == nfv), PETSC_COMM_SELF, PETSC_ERR_SUP,
               "InterfacePairsBuild: interface face %" PetscInt_FMT " has %" PetscInt_FMT " vertices; one face type (2, 3 or 4 vertices) per mesh", f, nfv);
    nodes_per_face = nfv;
    double x[numerics::kMaxFaceNodes * 3], w[numerics::kMaxFaceNodes], n[3], xc[3], xf[3], dot = 0;
    for (PetscInt a = 0; a < nfv; ++a) PetscCall(coords.Get(fverts[a], &x[a * dim]));
    const numerics::FaceShape shape = dim == 2 ? numerics::FaceShape::Seg2 : (nfv == 3 ? numerics::FaceShape::Tri3 : numerics::FaceShape::Quad4);
    if (spectral && spectral->degree > 1) PetscCall(mesh::SpectralFaceWeights(*spectral, coords, supp[0] - c_start, nfv, fverts.data(), w));
    else numerics::faceLumpedWeights(shape, (int)dim, x, w);
    numerics::faceNormal(shape, (int)dim, x, n);
    // Outward from the soil cell = towards the structure (InterfacePairs::normal).
    PetscCall(mesh::MeshPointCentroid(dm, supp[0], xc));
    PetscCall(mesh::MeshPointCentroid(dm, f, xf));
    for (PetscInt d = 0; d < dim; ++d) dot += n[d] * (xf[d] - xc[d]);
    if (dot < 0)
      for (PetscInt d = 0; d < dim; ++d) n[d] = -n[d];
    for (PetscInt a = 0; a < nfv; ++a) {
      PetscInt p, side;
      PetscCall(DMLabelGetValue(pair_label, fverts[a], &p));
      PetscCall(DMLabelGetValue(side_label, fverts[a], &side));
      PetscCheck(p >= 0 && side == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "InterfacePairsBuild: vertex %" PetscInt_FMT " of interface face %" PetscInt_FMT " is not a soil-side pair vertex",
                 fverts[a], f);
      area(p) += w[a];
      for (PetscInt d = 0; d < dim; ++d) nsum(p)[d] += w[a] * n[d];
      face_pairs.push_back(p);
    }
  }
  PetscCall(coords.Close());

  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, soil.data(), (int)npairs, MPIU_INT, MPI_MAX, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, strct.data(), (int)npairs, MPIU_INT, MPI_MAX, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, owner.data(), (int)npairs, MPIU_INT, MPI_MAX, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, geo.data(), (int)geo.size(), MPI_DOUBLE, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &nodes_per_face, 1, MPIU_INT, MPI_MAX, comm));

  *pairs                = InterfacePairs();
  pairs->n_global       = npairs;
  pairs->nodes_per_face = nodes_per_face;
  pairs->face_pairs     = std::move(face_pairs);
  for (PetscInt p = 0; p < npairs; ++p) {
    double len = 0;
    for (PetscInt d = 0; d < dim; ++d) len += nsum(p)[d] * nsum(p)[d];
    len = std::sqrt(len);
    PetscCheck(soil[p] >= 0 && strct[p] >= 0 && owner[p] >= 0 && area(p) > 0 && len > 0, comm, PETSC_ERR_PLIB,
               "InterfacePairsBuild: interface '%s', pair %" PetscInt_FMT " is incomplete (soil dof %" PetscInt_FMT ", structure dof %" PetscInt_FMT ", owner %" PetscInt_FMT ", area %g, |n| %g)",
               spec.name.c_str(), p, soil[p], strct[p], owner[p], area(p), len);
    if (owner[p] != rank) continue;
    pairs->id.push_back(p);
    pairs->soil_dof.push_back(soil[p]);
    pairs->structure_dof.push_back(strct[p]);
    pairs->area.push_back(area(p));
    for (PetscInt d = 0; d < dim; ++d) pairs->normal.push_back(nsum(p)[d] / len);
    for (PetscInt d = 0; d < dim; ++d) pairs->coords.push_back(xp(p)[d]);
  }
  PetscFunctionReturn(0);
}

} // namespace slipwave::meshing

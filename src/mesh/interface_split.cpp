#include "slipwave/mesh/interface_split.hpp"
#include "slipwave/mesh/point_centroid.hpp"
#include "slipwave/mesh/vertex_coordinates.hpp"

#include "slipwave/fem/element_kernels.hpp"
#include "slipwave/mesh/labels.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace slipwave::mesh {
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

} // namespace

PetscErrorCode InterfaceSplitSerialMesh(DM serial, const std::vector<std::string> &regions, const std::vector<std::string> &boundaries,
                                        const std::vector<InterfaceSpec> &specs, DM *split) {
  MPI_Comm    comm = PetscObjectComm((PetscObject)serial);
  PetscMPIInt rank;
  PetscInt    dim, cdim, c_start, c_end, v_start, v_end, f_start, f_end;
  DMLabel     region_label;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(DMGetDimension(serial, &dim));
  PetscCall(DMGetCoordinateDim(serial, &cdim));
  PetscCall(DMPlexGetHeightStratum(serial, 0, &c_start, &c_end));
  PetscCall(DMPlexGetDepthStratum(serial, 0, &v_start, &v_end));
  PetscCall(DMPlexGetHeightStratum(serial, 1, &f_start, &f_end));
  PetscCall(DMGetLabel(serial, kRegionLabel, &region_label));
  {
    // Labels may exist only on rank 0 (the one holding the cells): decide there, for everyone.
    PetscInt depth, ok[2];
    PetscCall(DMPlexGetDepth(serial, &depth));
    ok[0] = region_label != nullptr, ok[1] = depth == dim;
    PetscCallMPI(MPI_Bcast(ok, 2, MPIU_INT, 0, comm));
    PetscCheck(ok[0], comm, PETSC_ERR_ARG_WRONG, "InterfaceSplitSerialMesh: the mesh has no '%s' label; label the regions first", kRegionLabel);
    PetscCheck(ok[1], comm, PETSC_ERR_ARG_WRONG, "InterfaceSplitSerialMesh: the mesh is not interpolated (no faces); create it with interpolate = PETSC_TRUE");
  }
  {
    // The split must see every cell: a mesh already spread over ranks would lose the faces
    // between ranks (and PETSc's own split corrupts distributed meshes, see the notes).
    PetscInt on_other_ranks = rank == 0 ? 0 : c_end - c_start;
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &on_other_ranks, 1, MPIU_INT, MPI_SUM, comm));
    PetscCheck(on_other_ranks == 0, comm, PETSC_ERR_ARG_WRONG, "InterfaceSplitSerialMesh: %" PetscInt_FMT " cells on ranks other than 0; split the serial mesh before DMPlexDistribute",
               on_other_ranks);
  }

  const PetscInt        nspecs = (PetscInt)specs.size();
  std::vector<PetscInt> soil_of(nspecs), structure_of(nspecs);
  for (PetscInt s = 0; s < nspecs; ++s) {
    const InterfaceSpec &sp = specs[s];
    soil_of[s]              = regionIndex(regions, sp.soil_region);
    structure_of[s]         = regionIndex(regions, sp.structure_region);
    PetscCheck(soil_of[s] >= 0, comm, PETSC_ERR_USER_INPUT, "interface '%s': soil region '%s' is not a region of the mesh; allowed: %s", sp.name.c_str(),
               sp.soil_region.c_str(), joinNames(regions).c_str());
    PetscCheck(structure_of[s] >= 0, comm, PETSC_ERR_USER_INPUT, "interface '%s': structure region '%s' is not a region of the mesh; allowed: %s", sp.name.c_str(),
               sp.structure_region.c_str(), joinNames(regions).c_str());
    PetscCheck(soil_of[s] != structure_of[s], comm, PETSC_ERR_USER_INPUT, "interface '%s': soil and structure region are both '%s'; allowed: two different regions",
               sp.name.c_str(), sp.soil_region.c_str());
    for (PetscInt t = 0; t < s; ++t)
      PetscCheck(specs[t].name != sp.name, comm, PETSC_ERR_USER_INPUT, "interface '%s' is defined twice; allowed: distinct interface names", sp.name.c_str());
  }

  // 1. The interface faces of each spec (soil cell on one side, structure cell on the other)
  //    and the vertices they touch. spec_of[v]: the interface vertex v belongs to (-1: none).
  const PetscInt                     nv_old = v_end - v_start;
  std::vector<PetscInt>              spec_of(nv_old, -1);
  std::vector<std::vector<PetscInt>> iface_faces(nspecs), iface_verts(nspecs); // old points
  std::vector<PetscInt>              fverts;
  for (PetscInt s = 0; s < nspecs; ++s) {
    const InterfaceSpec &sp         = specs[s];
    DMLabel              face_label = nullptr;
    PetscInt             touching   = -1; // an earlier interface that shares a vertex with this one
    if (!sp.face_label.empty()) {
      PetscCall(DMGetLabel(serial, sp.face_label.c_str(), &face_label));
      PetscInt exists = face_label != nullptr;
      PetscCallMPI(MPI_Bcast(&exists, 1, MPIU_INT, 0, comm));
      PetscCheck(exists, comm, PETSC_ERR_USER_INPUT, "interface '%s': face label '%s' does not exist in the mesh; allowed: a face group of the mesh (%s)", sp.name.c_str(),
                 sp.face_label.c_str(), joinNames(boundaries).c_str());
    }
    for (PetscInt f = f_start; f < f_end; ++f) {
      PetscInt nsupp;
      PetscCall(DMPlexGetSupportSize(serial, f, &nsupp));
      if (nsupp != 2) continue;
      const PetscInt *supp;
      PetscInt        r0, r1;
      PetscCall(DMPlexGetSupport(serial, f, &supp));
      PetscCall(DMLabelGetValue(region_label, supp[0], &r0));
      PetscCall(DMLabelGetValue(region_label, supp[1], &r1));
      const bool between = (r0 == soil_of[s] && r1 == structure_of[s]) || (r1 == soil_of[s] && r0 == structure_of[s]);
      if (!between) continue;
      if (face_label) {
        PetscInt value;
        PetscCall(DMLabelGetValue(face_label, f, &value));
        if (value < 0) continue;
      }
      iface_faces[s].push_back(f);
      PetscCall(closureVertices(serial, f, v_start, v_end, &fverts));
      for (PetscInt v : fverts) {
        PetscInt &owner = spec_of[v - v_start];
        if (owner >= 0 && owner != s) {
          if (touching < 0) touching = owner;
          continue;
        }
        if (owner < 0) iface_verts[s].push_back(v);
        owner = s;
      }
    }
    // A vertex on two interfaces would need three copies and a rule for which cells get which.
    PetscCallMPI(MPI_Bcast(&touching, 1, MPIU_INT, 0, comm));
    PetscCheck(touching < 0, comm, PETSC_ERR_USER_INPUT, "interfaces '%s' and '%s' share a vertex; not supported yet: interfaces without a common vertex",
               specs[touching].name.c_str(), sp.name.c_str());
    // Only rank 0 holds cells: the verdict must reach every rank before anyone errors out.
    PetscInt nfaces = (PetscInt)iface_faces[s].size();
    PetscCallMPI(MPI_Bcast(&nfaces, 1, MPIU_INT, 0, comm));
    PetscCheck(nfaces > 0, comm, PETSC_ERR_USER_INPUT, "interface '%s': regions '%s' (soil) and '%s' (structure) share no face%s%s%s; allowed: two regions that touch along faces",
               sp.name.c_str(), sp.soil_region.c_str(), sp.structure_region.c_str(), sp.face_label.empty() ? "" : " within face label '", sp.face_label.c_str(),
               sp.face_label.empty() ? "" : "'");
    // Pair ids in the order of the original vertex numbers: deterministic for a given mesh.
    std::sort(iface_verts[s].begin(), iface_verts[s].end());
  }

  // 2. New vertex numbers: the originals keep theirs (0..nv_old-1), the structure copies follow,
  //    spec by spec in pair order. copy_of[v]: new number of the structure copy of v.
  std::vector<PetscInt> copy_of(nv_old, -1);
  PetscInt              nv_new = nv_old;
  for (PetscInt s = 0; s < nspecs; ++s)
    for (PetscInt v : iface_verts[s]) copy_of[v - v_start] = nv_new++;
  // A vertex seen from a cell of region `region`: structure cells of its interface get the copy.
  auto mapVertex = [&](PetscInt v, PetscInt region) -> PetscInt {
    const PetscInt s = spec_of[v - v_start];
    return (s >= 0 && region == structure_of[s]) ? copy_of[v - v_start] : v - v_start;
  };

  // 3. Cell-vertex lists in the original closure order. DMPlexCreateFromCellList takes each
  //    cell's vertices in the order its closure returns them (checked after the build below),
  //    so the new cells have the orientation and vertex order of the old ones.
  const PetscInt        ncells = c_end - c_start;
  PetscInt              ncorners = 0;
  std::vector<PetscInt> cells, cell_region(ncells), cverts;
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscInt region;
    PetscCall(DMLabelGetValue(region_label, c, &region));
    PetscCheck(region >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "InterfaceSplitSerialMesh: cell %" PetscInt_FMT " has no region", c);
    cell_region[c - c_start] = region;
    PetscCall(closureVertices(serial, c, v_start, v_end, &cverts));
    if (c == c_start) ncorners = (PetscInt)cverts.size();
    PetscCheck((PetscInt)cverts.size() == ncorners, PETSC_COMM_SELF, PETSC_ERR_SUP, "InterfaceSplitSerialMesh: cell %" PetscInt_FMT " has %zu vertices, cell %" PetscInt_FMT " has %" PetscInt_FMT "; one cell type per mesh",
               c, cverts.size(), c_start, ncorners);
    for (PetscInt v : cverts) cells.push_back(mapVertex(v, region));
  }
  PetscCallMPI(MPI_Bcast(&ncorners, 1, MPIU_INT, 0, comm));

  // Coordinates: the copies sit exactly on their originals.
  std::vector<PetscReal> xyz((size_t)nv_new * cdim);
  {
    VertexCoordinates coords;
    PetscCall(coords.Open(serial));
    for (PetscInt v = v_start; v < v_end; ++v) {
      PetscReal *xv = &xyz[(size_t)(v - v_start) * cdim];
      PetscCall(coords.Get(v, xv));
      if (copy_of[v - v_start] >= 0) std::copy(xv, xv + cdim, &xyz[(size_t)copy_of[v - v_start] * cdim]);
    }
    PetscCall(coords.Close());
  }

  DM dm;
  PetscCall(DMPlexCreateFromCellListPetsc(comm, dim, rank == 0 ? ncells : 0, rank == 0 ? nv_new : 0, ncorners, PETSC_TRUE, rank == 0 ? cells.data() : nullptr, cdim,
                                          rank == 0 ? xyz.data() : nullptr, &dm));
  {
    const char *name;
    PetscCall(PetscObjectGetName((PetscObject)serial, &name));
    PetscCall(PetscObjectSetName((PetscObject)dm, name));
  }

  PetscInt nc_start, nc_end, nv_start, nv_end, nf_start, nf_end;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &nc_start, &nc_end));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &nv_start, &nv_end));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &nf_start, &nf_end));
  PetscCheck(nc_end - nc_start == (rank == 0 ? ncells : 0) && nv_end - nv_start == (rank == 0 ? nv_new : 0), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "InterfaceSplitSerialMesh: the rebuilt mesh has %" PetscInt_FMT " cells and %" PetscInt_FMT " vertices, expected %" PetscInt_FMT " and %" PetscInt_FMT, nc_end - nc_start,
             nv_end - nv_start, ncells, nv_new);
  // Everything below relies on PETSc keeping the cell and vertex numbers of the list (cell k
  // = nc_start + k, vertex k = nv_start + k) and on the closure returning the vertices in the
  // order given: check both, cheaply, instead of trusting them. (PETSc reproduces any order it
  // is given, so this does not prove the cells valid: that follows from passing the closure
  // order of the valid original cells; tests/unit/test_interface_split.cpp checks it with
  // DMPlexCheck and cell-by-cell coordinates for quads, hexes, triangles and tets.)
  for (PetscInt c = 0; c < (rank == 0 ? ncells : 0); ++c) {
    PetscCall(closureVertices(dm, nc_start + c, nv_start, nv_end, &cverts));
    bool same = (PetscInt)cverts.size() == ncorners;
    for (PetscInt a = 0; a < ncorners && same; ++a) same = cverts[a] - nv_start == cells[c * ncorners + a];
    PetscCheck(same, PETSC_COMM_SELF, PETSC_ERR_PLIB, "InterfaceSplitSerialMesh: cell %" PetscInt_FMT " of the rebuilt mesh lists its vertices in another order than the original cell",
               c);
  }

  // 4. Labels. Faces of the new mesh are found by their vertex sets.
  std::vector<std::pair<FaceKey, PetscInt>> face_of;
  for (PetscInt f = nf_start; f < nf_end; ++f) {
    PetscCall(closureVertices(dm, f, nv_start, nv_end, &fverts));
    for (PetscInt &v : fverts) v -= nv_start;
    face_of.emplace_back(makeKey(fverts.data(), (PetscInt)fverts.size()), f);
  }
  std::sort(face_of.begin(), face_of.end());
  // The new face made of the old face f's vertices as seen from a cell of `region`.
  auto newFace = [&](PetscInt f, PetscInt region, PetscInt *nf) -> PetscErrorCode {
    PetscFunctionBeginUser;
    std::vector<PetscInt> vs;
    PetscCall(closureVertices(serial, f, v_start, v_end, &vs));
    for (PetscInt &v : vs) v = mapVertex(v, region);
    const FaceKey key = makeKey(vs.data(), (PetscInt)vs.size());
    auto          it  = std::lower_bound(face_of.begin(), face_of.end(), std::make_pair(key, (PetscInt)-1));
    PetscCheck(it != face_of.end() && it->first == key, PETSC_COMM_SELF, PETSC_ERR_PLIB, "InterfaceSplitSerialMesh: face %" PetscInt_FMT " has no counterpart in the rebuilt mesh", f);
    *nf = it->second;
    PetscFunctionReturn(0);
  };

  DMLabel new_region;
  PetscCall(DMCreateLabel(dm, kRegionLabel));
  PetscCall(DMGetLabel(dm, kRegionLabel, &new_region));
  for (PetscInt c = 0; c < (rank == 0 ? ncells : 0); ++c) PetscCall(DMLabelSetValue(new_region, nc_start + c, cell_region[c]));

  // Boundary labels: each labelled face goes to the new face of each of its cells, so a face
  // split by an interface (say an interior Gmsh group along it) is labelled on both sides.
  for (const std::string &name : boundaries) {
    DMLabel old_label, new_label;
    PetscCall(DMCreateLabel(dm, name.c_str()));
    PetscCall(DMGetLabel(dm, name.c_str(), &new_label));
    PetscCall(DMGetLabel(serial, name.c_str(), &old_label));
    if (!old_label) continue; // created empty on ranks that have no points, keep it that way
    for (PetscInt f = f_start; f < f_end; ++f) {
      PetscInt value;
      PetscCall(DMLabelGetValue(old_label, f, &value));
      if (value < 0) continue;
      PetscInt        nsupp;
      const PetscInt *supp;
      PetscCall(DMPlexGetSupportSize(serial, f, &nsupp));
      PetscCall(DMPlexGetSupport(serial, f, &supp));
      for (PetscInt k = 0; k < nsupp; ++k) {
        PetscInt nf = -1;
        PetscCall(newFace(f, cell_region[supp[k] - c_start], &nf));
        PetscCall(DMLabelSetValue(new_label, nf, value));
      }
    }
  }

  for (PetscInt s = 0; s < nspecs; ++s) {
    const std::string base = "interface_" + specs[s].name;
    DMLabel           pair_label, side_label, face_label;
    PetscCall(DMCreateLabel(dm, (base + "_pair").c_str()));
    PetscCall(DMCreateLabel(dm, (base + "_side").c_str()));
    PetscCall(DMCreateLabel(dm, base.c_str()));
    PetscCall(DMGetLabel(dm, (base + "_pair").c_str(), &pair_label));
    PetscCall(DMGetLabel(dm, (base + "_side").c_str(), &side_label));
    PetscCall(DMGetLabel(dm, base.c_str(), &face_label));
    for (size_t p = 0; p < iface_verts[s].size(); ++p) {
      const PetscInt v     = iface_verts[s][p];
      const PetscInt soil  = nv_start + (v - v_start);
      const PetscInt strct = nv_start + copy_of[v - v_start];
      PetscCall(DMLabelSetValue(pair_label, soil, (PetscInt)p));
      PetscCall(DMLabelSetValue(pair_label, strct, (PetscInt)p));
      PetscCall(DMLabelSetValue(side_label, soil, 0));
      PetscCall(DMLabelSetValue(side_label, strct, 1));
    }
    for (PetscInt f : iface_faces[s]) {
      PetscInt nf = -1;
      PetscCall(newFace(f, soil_of[s], &nf));
      PetscCall(DMLabelSetValue(face_label, nf, 1));
    }
  }
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

  VertexCoordinates coords;
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
    double x[fem::kMaxFaceNodes * 3], w[fem::kMaxFaceNodes], n[3], xc[3], xf[3], dot = 0;
    for (PetscInt a = 0; a < nfv; ++a) PetscCall(coords.Get(fverts[a], &x[a * dim]));
    const fem::FaceShape shape = dim == 2 ? fem::FaceShape::Seg2 : (nfv == 3 ? fem::FaceShape::Tri3 : fem::FaceShape::Quad4);
    fem::faceLumpedWeights(shape, (int)dim, x, w);
    fem::faceNormal(shape, (int)dim, x, n);
    // Outward from the soil cell = towards the structure (InterfacePairs::normal).
    PetscCall(MeshPointCentroid(dm, supp[0], xc));
    PetscCall(MeshPointCentroid(dm, f, xf));
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

} // namespace slipwave::mesh

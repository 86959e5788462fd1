#include "slipwave/meshing/mesh_refinement.hpp"

#include <petscsf.h>

#include "slipwave/mesh/labels.hpp"

#include <algorithm>

namespace slipwave::meshing {
namespace {

// Keeps a label's values on the points of one height only.
PetscErrorCode keepHeight(DM dm, const char *name, PetscInt height) {
  DMLabel         label;
  IS              values;
  const PetscInt *vals;
  PetscInt        nvalues, p_start, p_end;
  PetscFunctionBeginUser;
  PetscCall(DMGetLabel(dm, name, &label));
  if (!label) PetscFunctionReturn(0);
  PetscCall(DMPlexGetHeightStratum(dm, height, &p_start, &p_end));
  PetscCall(DMLabelGetValueIS(label, &values));
  PetscCall(ISGetLocalSize(values, &nvalues));
  PetscCall(ISGetIndices(values, &vals));
  for (PetscInt i = 0; i < nvalues; ++i) {
    IS                    stratum;
    const PetscInt       *points;
    PetscInt              npoints;
    std::vector<PetscInt> drop;
    PetscCall(DMLabelGetStratumIS(label, vals[i], &stratum));
    if (!stratum) continue;
    PetscCall(ISGetLocalSize(stratum, &npoints));
    PetscCall(ISGetIndices(stratum, &points));
    for (PetscInt k = 0; k < npoints; ++k)
      if (points[k] < p_start || points[k] >= p_end) drop.push_back(points[k]);
    PetscCall(ISRestoreIndices(stratum, &points));
    PetscCall(ISDestroy(&stratum));
    for (PetscInt p : drop) PetscCall(DMLabelClearValue(label, p, vals[i]));
  }
  PetscCall(ISRestoreIndices(values, &vals));
  PetscCall(ISDestroy(&values));
  PetscFunctionReturn(0);
}

std::string interfaceLabel(const InterfaceSpec &spec, const char *suffix = "") { return "interface_" + spec.name + suffix; }

// The labels MeshRefineUniformly puts back; the others are removed before refining.
PetscErrorCode dropOtherLabels(DM dm, const std::vector<std::string> &boundaries, const std::vector<InterfaceSpec> &specs) {
  std::vector<std::string> keep = {"depth", "celltype", mesh::kRegionLabel}, drop;
  PetscInt                 nlabels;
  PetscFunctionBeginUser;
  keep.insert(keep.end(), boundaries.begin(), boundaries.end());
  for (const InterfaceSpec &spec : specs)
    for (const char *suffix : {"", "_pair", "_side"}) keep.push_back(interfaceLabel(spec, suffix));
  PetscCall(DMGetNumLabels(dm, &nlabels));
  for (PetscInt l = 0; l < nlabels; ++l) {
    const char *name;
    PetscCall(DMGetLabelName(dm, l, &name));
    if (std::find(keep.begin(), keep.end(), name) == keep.end()) drop.push_back(name);
  }
  for (const std::string &name : drop) PetscCall(DMRemoveLabel(dm, name.c_str(), nullptr));
  PetscFunctionReturn(0);
}

// Pair ids on the refined mesh. A fine split vertex is, level by level, the mean of the
// vertices of its source point (itself, an edge's midpoint, a quadrilateral's or hexahedron's
// centre), so it is a mean of coarse split vertices with dyadic weights. Its key lists those
// coarse vertices, by interface and coarse pair id, with their weights as integers (units of
// 8^-levels, 8 being the most vertices a source point has): both copies of a vertex have the
// same key (the copies of a coarse point share its pair ids), on any number of ranks and in
// the serial and the distributed build, exactly (a key is integers). Keys ordered give the
// pair ids, as the serial split orders them by vertex. Coordinates would need a tolerance:
// the two copies' midpoints are computed from differently oriented faces, and no tolerance
// is safe for every mesh grading.
struct Blend {
  int     n = 0;  // coarse split vertices in the mean, at most 4 (those of one coarse face); 0: none
  int64_t id[4];  // interface index << 40 | coarse pair id, increasing
  int64_t weight[4];
};
constexpr int kInterfaceShift = 40;

PetscErrorCode coarseBlends(DM dm, const std::vector<InterfaceSpec> &specs, std::vector<Blend> *blend) {
  PetscInt v_start, v_end;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v_start, &v_end));
  blend->assign(v_end - v_start, Blend());
  for (size_t s = 0; s < specs.size(); ++s) {
    DMLabel pair;
    PetscCall(DMGetLabel(dm, interfaceLabel(specs[s], "_pair").c_str(), &pair));
    for (PetscInt v = v_start; v < v_end && pair; ++v) {
      PetscInt id;
      PetscCall(DMLabelGetValue(pair, v, &id));
      if (id < 0) continue;
      Blend &b    = (*blend)[v - v_start];
      b.n         = 1;
      b.id[0]     = (int64_t)s << kInterfaceShift | id;
      b.weight[0] = 1;
    }
  }
  PetscFunctionReturn(0);
}

// One level: each fine vertex is the mean of its source point's coarse vertices.
PetscErrorCode refineBlends(DMPlexTransform tr, DM coarse, DM fine, std::vector<Blend> *blend) {
  PetscInt cv_start, cv_end, fv_start, fv_end;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(coarse, 0, &cv_start, &cv_end));
  PetscCall(DMPlexGetDepthStratum(fine, 0, &fv_start, &fv_end));
  std::vector<Blend> next(fv_end - fv_start);
  for (PetscInt v = fv_start; v < fv_end; ++v) {
    DMPolytopeType ct, ct_new;
    PetscInt       p, r, nclosure, *closure = nullptr;
    PetscCall(DMPlexTransformGetSourcePoint(tr, v, &ct, &ct_new, &p, &r));
    PetscCall(DMPlexGetTransitiveClosure(coarse, p, PETSC_TRUE, &nclosure, &closure));
    std::vector<PetscInt> corners;
    for (PetscInt i = 0; i < nclosure; ++i)
      if (closure[2 * i] >= cv_start && closure[2 * i] < cv_end) corners.push_back(closure[2 * i]);
    PetscCall(DMPlexRestoreTransitiveClosure(coarse, p, PETSC_TRUE, &nclosure, &closure));
    const int64_t share = 8 / (int64_t)corners.size();
    Blend         mean;
    bool          on_interface = 8 % corners.size() == 0;
    for (size_t i = 0; i < corners.size() && on_interface; ++i) {
      const Blend &b = (*blend)[corners[i] - cv_start];
      on_interface   = b.n > 0;
      for (int k = 0; k < b.n && on_interface; ++k) {
        int j = 0;
        while (j < mean.n && mean.id[j] != b.id[k]) ++j;
        // A mean of more than one coarse face's vertices lies off the interface.
        on_interface = j < 4;
        if (!on_interface) break;
        if (j == mean.n) mean.id[mean.n++] = b.id[k], mean.weight[j] = 0;
        mean.weight[j] += share * b.weight[k];
      }
    }
    if (!on_interface) continue;
    for (int i = 1; i < mean.n; ++i) // by id, so a key does not depend on the corners' order
      for (int j = i; j > 0 && mean.id[j - 1] > mean.id[j]; --j) std::swap(mean.id[j - 1], mean.id[j]), std::swap(mean.weight[j - 1], mean.weight[j]);
    next[v - fv_start] = mean;
  }
  blend->swap(next);
  PetscFunctionReturn(0);
}

// One level: the children of cell s are s 2^dim + r.
PetscErrorCode refineSerialCells(DMPlexTransform tr, DM coarse, DM fine, std::vector<PetscInt> *serial_cell) {
  PetscInt dim, cc_start, cc_end, fc_start, fc_end;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(fine, &dim));
  PetscCall(DMPlexGetHeightStratum(coarse, 0, &cc_start, &cc_end));
  PetscCall(DMPlexGetHeightStratum(fine, 0, &fc_start, &fc_end));
  const PetscInt        children = (PetscInt)1 << dim;
  std::vector<PetscInt> next(fc_end - fc_start);
  for (PetscInt c = fc_start; c < fc_end; ++c) {
    DMPolytopeType ct, ct_new;
    PetscInt       p, r;
    PetscCall(DMPlexTransformGetSourcePoint(tr, c, &ct, &ct_new, &p, &r));
    PetscCheck(p >= cc_start && p < cc_end && r < children, PETSC_COMM_SELF, PETSC_ERR_PLIB, "refined cell %" PetscInt_FMT " comes from point %" PetscInt_FMT ", replica %" PetscInt_FMT ", not one of the %" PetscInt_FMT " children of a cell", c, p, r,
               children);
    next[c - fc_start] = (*serial_cell)[p - cc_start] * children + r;
  }
  serial_cell->swap(next);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode InterfacesRefinable(DM coarse, const std::vector<std::string> &regions, const std::vector<InterfaceSpec> &specs, PetscBool *refinable) {
  MPI_Comm comm = PetscObjectComm((PetscObject)coarse);
  PetscInt dim, e_start, e_end, ok = 1;
  DMLabel  region;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(coarse, &dim));
  PetscCall(DMGetLabel(coarse, mesh::kRegionLabel, &region));
  PetscCall(DMPlexGetDepthStratum(coarse, 1, &e_start, &e_end));
  auto index = [&](const std::string &name) { return (PetscInt)(std::find(regions.begin(), regions.end(), name) - regions.begin()); };
  for (const InterfaceSpec &spec : specs) {
    ok = ok && spec.face_label.empty();
    const PetscInt soil = index(spec.soil_region), structure = index(spec.structure_region);
    // In 2D the edges are the faces: only 3D has edges that can join the regions alone.
    for (PetscInt e = e_start; e < e_end && ok && dim == 3; ++e) {
      PetscInt nstar, *star = nullptr;
      bool     on_soil = false, on_structure = false, on_interface = false;
      PetscCall(DMPlexGetTransitiveClosure(coarse, e, PETSC_FALSE, &nstar, &star));
      for (PetscInt i = 0; i < nstar; ++i) {
        const PetscInt p = star[2 * i];
        PetscInt       r, nsupp;
        PetscCall(DMLabelGetValue(region, p, &r));
        on_soil      = on_soil || r == soil;
        on_structure = on_structure || r == structure;
        PetscCall(DMPlexGetSupportSize(coarse, p, &nsupp));
        if (p == e || nsupp != 2) continue;
        const PetscInt *supp;
        PetscInt        r0, r1;
        PetscCall(DMPlexGetSupport(coarse, p, &supp));
        PetscCall(DMLabelGetValue(region, supp[0], &r0));
        PetscCall(DMLabelGetValue(region, supp[1], &r1));
        on_interface = on_interface || (r0 == soil && r1 == structure) || (r0 == structure && r1 == soil);
      }
      PetscCall(DMPlexRestoreTransitiveClosure(coarse, e, PETSC_FALSE, &nstar, &star));
      ok = !(on_soil && on_structure) || on_interface;
    }
  }
  PetscCallMPI(MPI_Bcast(&ok, 1, MPIU_INT, 0, comm));
  *refinable = ok ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(0);
}

PetscErrorCode RefineRegularly(DM *dm, PetscInt levels, const RefinementLevelHook &each_level) {
  MPI_Comm comm = PetscObjectComm((PetscObject)*dm);
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < levels; ++k) {
    DMPlexTransform tr;
    DM              fine;
    // What DMRefine does for a uniform refinement, with the type fixed (DMRefine takes it
    // from -dm_plex_transform_type) and the transform kept for its source points.
    PetscCall(DMPlexTransformCreate(comm, &tr));
    PetscCall(DMPlexTransformSetType(tr, DMPLEXREFINEREGULAR));
    PetscCall(DMPlexTransformSetDM(tr, *dm));
    PetscCall(DMPlexTransformSetUp(tr));
    PetscCall(DMPlexTransformApply(tr, *dm, &fine));
    PetscCall(DMPlexSetRegularRefinement(fine, PETSC_TRUE));
    if (each_level) PetscCall(each_level(tr, *dm, fine));
    PetscCall(DMPlexTransformDestroy(&tr));
    PetscCall(DMDestroy(dm));
    *dm = fine;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode KeepRefinedLabels(DM dm, const std::vector<std::string> &boundaries, const std::vector<InterfaceSpec> &specs) {
  PetscFunctionBeginUser;
  PetscCall(keepHeight(dm, mesh::kRegionLabel, 0));
  for (const std::string &b : boundaries) PetscCall(keepHeight(dm, b.c_str(), 1));
  for (const InterfaceSpec &spec : specs) PetscCall(keepHeight(dm, interfaceLabel(spec).c_str(), 1));
  PetscFunctionReturn(0);
}

PetscErrorCode ForEachInterfaceFaceVertex(DM dm, const InterfaceSpec &spec, const std::function<PetscErrorCode(PetscInt vertex)> &visit) {
  DMLabel  faces;
  PetscInt f_start, f_end, v_start, v_end;
  PetscFunctionBeginUser;
  PetscCall(DMGetLabel(dm, interfaceLabel(spec).c_str(), &faces));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &f_start, &f_end));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v_start, &v_end));
  for (PetscInt f = f_start; f < f_end && faces; ++f) {
    PetscInt value, nclosure, *closure = nullptr;
    PetscCall(DMLabelGetValue(faces, f, &value));
    if (value < 0) continue;
    PetscCall(DMPlexGetTransitiveClosure(dm, f, PETSC_TRUE, &nclosure, &closure));
    for (PetscInt i = 0; i < nclosure; ++i)
      if (closure[2 * i] >= v_start && closure[2 * i] < v_end) PetscCall(visit(closure[2 * i]));
    PetscCall(DMPlexRestoreTransitiveClosure(dm, f, PETSC_TRUE, &nclosure, &closure));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode LabelRefinedPairs(DM dm, const InterfaceSpec &spec, PetscInt structure_region, const PairKeyOf &key_of) {
  MPI_Comm             comm = PetscObjectComm((PetscObject)dm);
  DMLabel              region, pair, side;
  PetscInt             v_start, v_end;
  std::vector<PairKey> mine;
  PetscFunctionBeginUser;
  PetscCall(DMRemoveLabel(dm, interfaceLabel(spec, "_pair").c_str(), nullptr));
  PetscCall(DMRemoveLabel(dm, interfaceLabel(spec, "_side").c_str(), nullptr));
  PetscCall(DMCreateLabel(dm, interfaceLabel(spec, "_pair").c_str()));
  PetscCall(DMCreateLabel(dm, interfaceLabel(spec, "_side").c_str()));
  PetscCall(DMGetLabel(dm, interfaceLabel(spec, "_pair").c_str(), &pair));
  PetscCall(DMGetLabel(dm, interfaceLabel(spec, "_side").c_str(), &side));
  PetscCall(DMGetLabel(dm, mesh::kRegionLabel, &region));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v_start, &v_end));
  PetscCall(ForEachInterfaceFaceVertex(dm, spec, [&](PetscInt v) -> PetscErrorCode {
    bool known;
    PetscFunctionBeginUser;
    PetscCall(key_of(v, &mine.emplace_back(), &known));
    PetscCheck(known, PETSC_COMM_SELF, PETSC_ERR_PLIB, "interface '%s' refined: vertex %" PetscInt_FMT " of one of its faces has no pair key", spec.name.c_str(), v);
    PetscFunctionReturn(0);
  }));
  std::sort(mine.begin(), mine.end());
  mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
  // The interface is a surface: every rank holding all of its keys is cheap.
  const PetscMPIInt        width = (PetscMPIInt)std::tuple_size<PairKey>::value;
  PetscMPIInt              size, nmine = (PetscMPIInt)mine.size() * width;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<PetscMPIInt> counts(size), offsets(size + 1, 0);
  PetscCallMPI(MPI_Allgather(&nmine, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  for (PetscMPIInt r = 0; r < size; ++r) offsets[r + 1] = offsets[r] + counts[r];
  std::vector<PairKey> all(offsets[size] / width);
  PetscCallMPI(MPI_Allgatherv(mine.data(), nmine, MPI_INT64_T, all.data(), counts.data(), offsets.data(), MPI_INT64_T, comm));
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  // Vertices another rank owns (leaves of the point SF) are counted there.
  PetscSF           point_sf;
  PetscInt          nleaves;
  const PetscInt   *leaves;
  std::vector<char> ghost(v_end - v_start, 0);
  PetscCall(DMGetPointSF(dm, &point_sf));
  PetscCall(PetscSFGetGraph(point_sf, nullptr, &nleaves, &leaves, nullptr));
  for (PetscInt i = 0; i < nleaves && nleaves > 0; ++i) {
    const PetscInt p = leaves ? leaves[i] : i;
    if (p >= v_start && p < v_end) ghost[p - v_start] = 1;
  }
  PetscInt owned[2] = {0, 0};
  // Only structure cells hold a structure copy; the soil copy is shared with no structure cell.
  for (PetscInt v = v_start; v < v_end; ++v) {
    PairKey key;
    bool    known;
    PetscCall(key_of(v, &key, &known));
    if (!known) continue;
    auto it = std::lower_bound(all.begin(), all.end(), key);
    if (it == all.end() || *it != key) continue;
    PetscInt nstar, *star = nullptr, on_structure = 0;
    PetscCall(DMPlexGetTransitiveClosure(dm, v, PETSC_FALSE, &nstar, &star));
    for (PetscInt i = 0; i < nstar; ++i) {
      PetscInt r;
      PetscCall(DMLabelGetValue(region, star[2 * i], &r));
      on_structure = on_structure || r == structure_region;
    }
    PetscCall(DMPlexRestoreTransitiveClosure(dm, v, PETSC_FALSE, &nstar, &star));
    PetscCall(DMLabelSetValue(pair, v, (PetscInt)(it - all.begin())));
    PetscCall(DMLabelSetValue(side, v, on_structure));
    if (!ghost[v - v_start]) ++owned[on_structure];
  }
  // Each key must hold exactly one soil and one structure vertex; a guard on the interface
  // itself (vertices doubled away from it, which InterfacesRefinable rules out, would not show
  // here).
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, owned, 2, MPIU_INT, MPI_SUM, comm));
  PetscCheck(owned[0] == (PetscInt)all.size() && owned[1] == (PetscInt)all.size(), comm, PETSC_ERR_PLIB,
             "interface '%s' refined: %" PetscInt_FMT " soil and %" PetscInt_FMT " structure vertices for %zu pairs; build with -mesh_build serial", spec.name.c_str(),
             owned[0], owned[1], all.size());
  PetscFunctionReturn(0);
}

PetscErrorCode MeshRefineUniformly(DM *dm, PetscInt levels, const std::vector<std::string> &regions, const std::vector<std::string> &boundaries,
                                   const std::vector<InterfaceSpec> &specs, std::vector<PetscInt> *serial_cell) {
  std::vector<Blend> blend;
  PetscInt           v_start, v_end;
  PetscFunctionBeginUser;
  PetscCall(dropOtherLabels(*dm, boundaries, specs));
  PetscCall(coarseBlends(*dm, specs, &blend));
  PetscCall(RefineRegularly(dm, levels, [&](DMPlexTransform tr, DM coarse, DM fine) -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(refineBlends(tr, coarse, fine, &blend));
    PetscCall(refineSerialCells(tr, coarse, fine, serial_cell));
    PetscFunctionReturn(0);
  }));
  PetscCall(KeepRefinedLabels(*dm, boundaries, specs));
  PetscCall(DMPlexGetDepthStratum(*dm, 0, &v_start, &v_end));
  for (size_t s = 0; s < specs.size(); ++s) {
    const PetscInt structure = (PetscInt)(std::find(regions.begin(), regions.end(), specs[s].structure_region) - regions.begin());
    PetscCall(LabelRefinedPairs(*dm, specs[s], structure, [&](PetscInt v, PairKey *key, bool *known) -> PetscErrorCode {
      const Blend &b = blend[v - v_start];
      *known         = b.n > 0 && b.id[0] >> kInterfaceShift == (int64_t)s;
      key->fill(-1);
      for (int k = 0; k < b.n && *known; ++k) (*key)[2 * k] = b.id[k], (*key)[2 * k + 1] = b.weight[k];
      return 0;
    }));
  }
  PetscFunctionReturn(0);
}

} // namespace slipwave::meshing

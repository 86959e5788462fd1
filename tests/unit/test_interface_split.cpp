// The interface split (src/meshing/interface_split.cpp): duplicating the structure-side vertices
// of an interface on the serial mesh, and the pair tables on the (distributed) split mesh.
//   test_interface_split               one rank: quads, footing, hexes, triangles, tets, two
//                                      interfaces at once, input errors
//   test_interface_split -distribute   2+ ranks (tests/cases/interface_split_mpi.sh): the split
//                                      8x8 mesh distributed by the options' partitioner (metis)
//                                      and by a forced partition that cuts the interface
//   test_interface_split -gmsh_file f.msh -gmsh_plane h   one rank: an unstructured Gmsh mesh
//                                      split along "last coordinate = h" (from the case script)
// Expected areas are the lumped face weights ∫ N_a dA of the faces around a pair: a segment of
// length L gives L/2 to each end, a unit square face 1/4 to each corner, a triangle of area A
// gives A/3 to each corner.
#include "slipwave/fem/node_fields.hpp"
#include "slipwave/mesh/partition_metis.hpp"
#include "slipwave/meshing/interface_split.hpp"
#include "slipwave/meshing/mesh_builder.hpp"

#include "petsc_test_main.hpp"

#include <petscdmplex.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace {

using slipwave::meshing::InterfacePairs;
using slipwave::meshing::InterfaceSpec;
using slipwave::mesh::kRegionLabel;

using RegionOf = std::function<PetscInt(const double *)>; // region index from a cell centroid

PetscErrorCode closureVertices(DM dm, PetscInt p, std::vector<PetscInt> *verts) {
  PetscInt  v_start, v_end, n, *closure = nullptr;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v_start, &v_end));
  verts->clear();
  PetscCall(DMPlexGetTransitiveClosure(dm, p, PETSC_TRUE, &n, &closure));
  for (PetscInt i = 0; i < n; ++i)
    if (closure[2 * i] >= v_start && closure[2 * i] < v_end) verts->push_back(closure[2 * i]);
  PetscCall(DMPlexRestoreTransitiveClosure(dm, p, PETSC_TRUE, &n, &closure));
  PetscFunctionReturn(0);
}

PetscErrorCode vertexCoords(DM dm, PetscInt v, double *x) {
  Vec                coords;
  DM                 cdm;
  PetscSection       sec;
  const PetscScalar *a;
  PetscInt           off, cdim;
  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinateDim(dm, &cdim));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &sec));
  PetscCall(PetscSectionGetOffset(sec, v, &off));
  PetscCall(VecGetArrayRead(coords, &a));
  for (PetscInt d = 0; d < cdim; ++d) x[d] = PetscRealPart(a[off + d]);
  PetscCall(VecRestoreArrayRead(coords, &a));
  PetscFunctionReturn(0);
}

PetscErrorCode centroid(DM dm, PetscInt p, double *xc) {
  std::vector<PetscInt> vs;
  PetscInt              dim;
  double                x[3];
  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinateDim(dm, &dim));
  PetscCall(closureVertices(dm, p, &vs));
  for (PetscInt d = 0; d < dim; ++d) xc[d] = 0;
  for (PetscInt v : vs) {
    PetscCall(vertexCoords(dm, v, x));
    for (PetscInt d = 0; d < dim; ++d) xc[d] += x[d] / vs.size();
  }
  PetscFunctionReturn(0);
}

PetscErrorCode labelRegions(DM dm, const RegionOf &region_of) {
  DMLabel  label;
  PetscInt c_start, c_end;
  PetscFunctionBeginUser;
  PetscCall(DMCreateLabel(dm, kRegionLabel));
  PetscCall(DMGetLabel(dm, kRegionLabel, &label));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
  for (PetscInt c = c_start; c < c_end; ++c) {
    double x[3];
    PetscCall(centroid(dm, c, x));
    PetscCall(DMLabelSetValue(label, c, region_of(x)));
  }
  PetscFunctionReturn(0);
}

// Box sides by face centroid, as mesh_builder does: left/right/bottom/top(/front/back order of
// the axes x, y(, z) in 2D: left, right, bottom, top; 3D: left, right, front, back, bottom, top).
PetscErrorCode labelSides(DM dm, const double *lo, const double *hi, std::vector<std::string> *names) {
  PetscInt dim, f_start, f_end;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  const char *n2[4] = {"left", "right", "bottom", "top"}, *n3[6] = {"left", "right", "front", "back", "bottom", "top"};
  names->clear();
  for (PetscInt s = 0; s < 2 * dim; ++s) {
    names->push_back(dim == 2 ? n2[s] : n3[s]);
    PetscCall(DMCreateLabel(dm, names->back().c_str()));
  }
  PetscCall(DMPlexGetHeightStratum(dm, 1, &f_start, &f_end));
  for (PetscInt f = f_start; f < f_end; ++f) {
    PetscInt ns;
    PetscCall(DMPlexGetSupportSize(dm, f, &ns));
    if (ns != 1) continue;
    double x[3];
    PetscCall(centroid(dm, f, x));
    for (PetscInt d = 0; d < dim; ++d) {
      if (std::fabs(x[d] - lo[d]) < 1e-9) PetscCall(DMSetLabelValue(dm, (*names)[2 * d].c_str(), f, 1));
      if (std::fabs(x[d] - hi[d]) < 1e-9) PetscCall(DMSetLabelValue(dm, (*names)[2 * d + 1].c_str(), f, 1));
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode createBox(PetscInt dim, const PetscInt *faces, const double *lo, const double *hi, const RegionOf &region_of, DM *dm,
                         std::vector<std::string> *sides) {
  PetscReal l[3], h[3];
  PetscFunctionBeginUser;
  for (PetscInt d = 0; d < dim; ++d) l[d] = lo[d], h[d] = hi[d];
  PetscCall(DMPlexCreateBoxMesh(PETSC_COMM_WORLD, dim, PETSC_FALSE, faces, l, h, nullptr, PETSC_TRUE, dm));
  PetscCall(labelRegions(*dm, region_of));
  PetscCall(labelSides(*dm, lo, hi, sides));
  PetscFunctionReturn(0);
}

PetscInt labelCount(DM dm, const char *name, PetscInt value) {
  DMLabel  label;
  PetscInt n = 0;
  DMGetLabel(dm, name, &label);
  if (label) DMLabelGetStratumSize(label, value, &n);
  return n;
}

// What every split must satisfy, whatever the mesh: same cells with the same vertex
// coordinates in the same closure order (so no cell is inverted or twisted), valid plex
// topology and geometry, the region label and boundary face counts carried over, vertices
// = original + one copy per pair, each pair one soil and one structure vertex at the same
// place, cells of the structure regions using only structure copies, soil cells only the
// originals. npairs[s]: expected pair count of spec s.
PetscErrorCode checkSplit(const std::string &tag, DM orig, DM split, const std::vector<std::string> &boundaries, const std::vector<InterfaceSpec> &specs,
                          const std::vector<PetscInt> &structure_region, const std::vector<PetscInt> &soil_region, const std::vector<PetscInt> &npairs) {
  PetscInt oc0, oc1, ov0, ov1, sc0, sc1, sv0, sv1, cdim;
  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinateDim(orig, &cdim));
  PetscCall(DMPlexGetHeightStratum(orig, 0, &oc0, &oc1));
  PetscCall(DMPlexGetDepthStratum(orig, 0, &ov0, &ov1));
  PetscCall(DMPlexGetHeightStratum(split, 0, &sc0, &sc1));
  PetscCall(DMPlexGetDepthStratum(split, 0, &sv0, &sv1));
  PetscInt total_pairs = 0;
  for (PetscInt n : npairs) total_pairs += n;
  unit::check(sc1 - sc0 == oc1 - oc0, tag + ": same number of cells (" + std::to_string(sc1 - sc0) + ")");
  unit::check(sv1 - sv0 == ov1 - ov0 + total_pairs,
              tag + ": vertices = " + std::to_string(ov1 - ov0) + " + " + std::to_string(total_pairs) + " copies (got " + std::to_string(sv1 - sv0) + ")");
  PetscCall(DMPlexCheck(split)); // symmetry, skeleton, face cones vs cell types, geometry (det J > 0)
  unit::check(true, tag + ": DMPlexCheck passes (topology, face orientation, positive Jacobians)");

  DMLabel oreg, sreg;
  PetscCall(DMGetLabel(orig, kRegionLabel, &oreg));
  PetscCall(DMGetLabel(split, kRegionLabel, &sreg));
  bool                  same_coords = true, same_region = true, structure_copies = true, soil_originals = true;
  std::vector<PetscInt> ov, sv;
  for (PetscInt c = 0; c < oc1 - oc0 && sc1 - sc0 == oc1 - oc0; ++c) {
    PetscInt ro, rs;
    PetscCall(DMLabelGetValue(oreg, oc0 + c, &ro));
    PetscCall(DMLabelGetValue(sreg, sc0 + c, &rs));
    same_region = same_region && ro == rs;
    PetscCall(closureVertices(orig, oc0 + c, &ov));
    PetscCall(closureVertices(split, sc0 + c, &sv));
    same_coords = same_coords && ov.size() == sv.size();
    for (size_t a = 0; a < ov.size() && same_coords; ++a) {
      double xo[3], xs[3];
      PetscCall(vertexCoords(orig, ov[a], xo));
      PetscCall(vertexCoords(split, sv[a], xs));
      for (PetscInt d = 0; d < cdim; ++d) same_coords = same_coords && xo[d] == xs[d];
    }
    for (size_t s = 0; s < specs.size(); ++s) {
      DMLabel side;
      PetscCall(DMGetLabel(split, ("interface_" + specs[s].name + "_side").c_str(), &side));
      for (PetscInt v : sv) {
        PetscInt value;
        PetscCall(DMLabelGetValue(side, v, &value));
        if (rs == structure_region[s]) structure_copies = structure_copies && value != 0;
        if (rs == soil_region[s]) soil_originals = soil_originals && value != 1;
      }
    }
  }
  unit::check(same_region, tag + ": region label carried cell by cell");
  unit::check(same_coords, tag + ": every cell has the original vertex coordinates in the original closure order");
  unit::check(structure_copies, tag + ": structure cells reference no soil-side interface vertex");
  unit::check(soil_originals, tag + ": soil cells reference no structure copy");

  for (const std::string &b : boundaries)
    unit::check(labelCount(split, b.c_str(), 1) == labelCount(orig, b.c_str(), 1),
                tag + ": boundary '" + b + "' keeps its " + std::to_string(labelCount(orig, b.c_str(), 1)) + " faces (got " + std::to_string(labelCount(split, b.c_str(), 1)) + ")");

  for (size_t s = 0; s < specs.size(); ++s) {
    const std::string base = "interface_" + specs[s].name;
    DMLabel           pair, side;
    PetscCall(DMGetLabel(split, (base + "_pair").c_str(), &pair));
    PetscCall(DMGetLabel(split, (base + "_side").c_str(), &side));
    bool ok = pair && side;
    for (PetscInt p = 0; p < npairs[s] && ok; ++p) {
      IS              is;
      PetscInt        n;
      const PetscInt *pts;
      PetscCall(DMLabelGetStratumIS(pair, p, &is));
      ok = is != nullptr;
      if (!ok) break;
      PetscCall(ISGetLocalSize(is, &n));
      PetscCall(ISGetIndices(is, &pts));
      ok = n == 2;
      if (ok) {
        PetscInt s0, s1;
        double   x0[3], x1[3];
        PetscCall(DMLabelGetValue(side, pts[0], &s0));
        PetscCall(DMLabelGetValue(side, pts[1], &s1));
        PetscCall(vertexCoords(split, pts[0], x0));
        PetscCall(vertexCoords(split, pts[1], x1));
        ok = s0 + s1 == 1 && s0 * s1 == 0;
        for (PetscInt d = 0; d < cdim; ++d) ok = ok && x0[d] == x1[d];
      }
      PetscCall(ISRestoreIndices(is, &pts));
      PetscCall(ISDestroy(&is));
    }
    ok = ok && labelCount(split, (base + "_pair").c_str(), npairs[s]) == 0;
    unit::check(ok, tag + ": " + base + ": pairs 0.." + std::to_string(npairs[s] - 1) + " each one soil + one structure vertex, coincident");
  }
  PetscFunctionReturn(0);
}

// Pairs of the serial split mesh with dim dofs per vertex, sorted by coordinates (x, then y,
// then z) so the expected lists read along the interface.
struct Pair {
  double x[3], n[3], area;
  PetscInt id, soil_dof, structure_dof;
};

PetscErrorCode buildPairs(DM split, const InterfaceSpec &spec, std::vector<Pair> *out, InterfacePairs *raw = nullptr) {
  PetscInt       dim;
  InterfacePairs pairs;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(split, &dim));
  PetscCall(slipwave::fem::NodeFieldSetSection(split, dim));
  PetscCall(slipwave::meshing::InterfacePairsBuild(split, spec, &pairs));
  out->clear();
  for (size_t k = 0; k < pairs.id.size(); ++k) {
    Pair p{};
    for (PetscInt d = 0; d < dim; ++d) p.x[d] = pairs.coords[k * dim + d], p.n[d] = pairs.normal[k * dim + d];
    p.area = pairs.area[k];
    p.id = pairs.id[k], p.soil_dof = pairs.soil_dof[k], p.structure_dof = pairs.structure_dof[k];
    out->push_back(p);
  }
  std::sort(out->begin(), out->end(), [](const Pair &a, const Pair &b) {
    for (int d = 0; d < 3; ++d)
      if (a.x[d] != b.x[d]) return a.x[d] < b.x[d];
    return false;
  });
  if (raw) *raw = pairs;
  PetscFunctionReturn(0);
}

// areas[k], normals[k], coords[k]: expected values along the sorted pairs.
void checkPairs(const std::string &tag, PetscInt dim, const std::vector<Pair> &got, const std::vector<double> &areas, const std::vector<std::vector<double>> &normals,
                const std::vector<std::vector<double>> &coords) {
  unit::check(got.size() == areas.size(), tag + ": " + std::to_string(areas.size()) + " pairs (got " + std::to_string(got.size()) + ")");
  if (got.size() != areas.size()) return;
  bool   ok_a = true, ok_n = true, ok_x = true, ok_d = true;
  double total = 0, want_total = 0;
  for (size_t k = 0; k < got.size(); ++k) {
    ok_a = ok_a && std::fabs(got[k].area - areas[k]) < 1e-12;
    total += got[k].area, want_total += areas[k];
    const std::vector<double> &n = normals.size() == 1 ? normals[0] : normals[k];
    for (PetscInt d = 0; d < dim; ++d) ok_n = ok_n && std::fabs(got[k].n[d] - n[d]) < 1e-12;
    for (PetscInt d = 0; d < dim; ++d) ok_x = ok_x && std::fabs(got[k].x[d] - coords[k][d]) < 1e-12;
    ok_d = ok_d && got[k].soil_dof >= 0 && got[k].structure_dof >= 0 && got[k].soil_dof != got[k].structure_dof && got[k].soil_dof % dim == 0 && got[k].structure_dof % dim == 0;
  }
  unit::check(ok_x, tag + ": pair coordinates along the interface");
  unit::check(ok_a, tag + ": pair areas (lumped face weights)");
  unit::near(total, want_total, 1e-14, 1e-14, tag + ": total area = interface length/area");
  unit::check(ok_n, tag + ": pair normals (from soil into structure)");
  unit::check(ok_d, tag + ": soil and structure dofs valid and distinct");
}

const std::vector<double> kUp2 = {0, 1}, kUp3 = {0, 0, 1};

// 4x4 unit quads on [0,4]^2, soil y < 2, block y > 2: the interface is the line y = 2 with
// 5 vertices; each unit segment gives 1/2 to each end: 0.5, 1, 1, 1, 0.5 (sum 4 = length).
PetscErrorCode testQuads() {
  const PetscInt           faces[2] = {4, 4};
  const double             lo[2] = {0, 0}, hi[2] = {4, 4};
  DM                       dm, split;
  std::vector<std::string> sides;
  PetscFunctionBeginUser;
  PetscCall(createBox(2, faces, lo, hi, [](const double *x) -> PetscInt { return x[1] < 2 ? 0 : 1; }, &dm, &sides));
  const std::vector<InterfaceSpec> specs = {{"base", "soil", "block", ""}};
  PetscCall(slipwave::meshing::InterfaceSplitSerialMesh(dm, {"soil", "block"}, sides, specs, &split));
  PetscCall(checkSplit("quads 4x4", dm, split, sides, specs, {1}, {0}, {5}));
  unit::check(labelCount(split, "interface_base", 1) == 4, "quads 4x4: interface label holds the 4 soil-side faces");
  // Left/right faces of the block: the two lowest (y in [2,3]) touch y = 2 and must use the copy.
  for (const char *b : {"left", "right"}) {
    DMLabel         label, side;
    IS              is;
    const PetscInt *f;
    PetscInt        n, block_faces = 0, uses_copy = 0;
    PetscCall(DMGetLabel(split, b, &label));
    PetscCall(DMGetLabel(split, "interface_base_side", &side));
    PetscCall(DMLabelGetStratumIS(label, 1, &is));
    PetscCall(ISGetLocalSize(is, &n));
    PetscCall(ISGetIndices(is, &f));
    for (PetscInt i = 0; i < n; ++i) {
      double                xc[2];
      std::vector<PetscInt> vs;
      PetscCall(centroid(split, f[i], xc));
      if (xc[1] < 2) continue;
      ++block_faces;
      PetscCall(closureVertices(split, f[i], &vs));
      for (PetscInt v : vs) {
        PetscInt value;
        PetscCall(DMLabelGetValue(side, v, &value));
        uses_copy += value == 1;
        PetscCheck(value != 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "block face uses the soil vertex");
      }
    }
    PetscCall(ISRestoreIndices(is, &f));
    PetscCall(ISDestroy(&is));
    unit::check(block_faces == 2 && uses_copy == 1, std::string("quads 4x4: '") + b + "' faces of the block use the structure copy at y = 2");
  }
  std::vector<Pair> pairs;
  PetscCall(buildPairs(split, specs[0], &pairs));
  checkPairs("quads 4x4", 2, pairs, {0.5, 1, 1, 1, 0.5}, {kUp2}, {{0, 2}, {1, 2}, {2, 2}, {3, 2}, {4, 2}});
  PetscCall(DMDestroy(&split));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

// 6x4 unit quads, block = x in [2,4], y in [3,4]: a 2x1-cell footing set into the top layer.
// Restricted to a face label on its base: 2 faces, 3 pairs (both ends split), 0.5, 1, 0.5.
// Unrestricted, the sides x = 2 and x = 4 (soil cells left and right of the footing) are part
// of the interface too: 5 pairs; a base corner gets 1/2 from the base (normal +y) and 1/2 from
// the side (normal ±x, out of the soil cell beside the footing): area 1, normal (±1, 1)/√2.
PetscErrorCode testFooting() {
  const PetscInt           faces[2] = {6, 4};
  const double             lo[2] = {0, 0}, hi[2] = {6, 4};
  DM                       dm, split;
  std::vector<std::string> sides;
  const RegionOf           region_of = [](const double *x) -> PetscInt { return x[0] > 2 && x[0] < 4 && x[1] > 3 ? 1 : 0; };
  PetscFunctionBeginUser;
  PetscCall(createBox(2, faces, lo, hi, region_of, &dm, &sides));
  // "footing_base": the faces at y = 3 under the footing (as a Gmsh physical group would be).
  PetscInt f_start, f_end;
  PetscCall(DMCreateLabel(dm, "footing_base"));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &f_start, &f_end));
  for (PetscInt f = f_start; f < f_end; ++f) {
    double x[2];
    PetscCall(centroid(dm, f, x));
    if (std::fabs(x[1] - 3) < 1e-12 && x[0] > 2 && x[0] < 4) PetscCall(DMSetLabelValue(dm, "footing_base", f, 7));
  }
  std::vector<std::string> bnd = sides;
  bnd.push_back("footing_base");
  {
    const std::vector<InterfaceSpec> specs = {{"base", "soil", "block", "footing_base"}};
    PetscCall(slipwave::meshing::InterfaceSplitSerialMesh(dm, {"soil", "block"}, bnd, specs, &split));
    PetscCall(checkSplit("footing (base label)", dm, split, sides, specs, {1}, {0}, {3}));
    // The interior group lies along the interface: both sides' faces keep it (value 7).
    unit::check(labelCount(split, "footing_base", 7) == 4, "footing (base label): interior face group carried to both sides (2 + 2 faces)");
    std::vector<Pair> pairs;
    PetscCall(buildPairs(split, specs[0], &pairs));
    checkPairs("footing (base label)", 2, pairs, {0.5, 1, 0.5}, {kUp2}, {{2, 3}, {3, 3}, {4, 3}});
    PetscCall(DMDestroy(&split));
  }
  {
    const std::vector<InterfaceSpec> specs = {{"all", "soil", "block", ""}};
    PetscCall(slipwave::meshing::InterfaceSplitSerialMesh(dm, {"soil", "block"}, sides, specs, &split));
    PetscCall(checkSplit("footing (all faces)", dm, split, sides, specs, {1}, {0}, {5}));
    std::vector<Pair> pairs;
    PetscCall(buildPairs(split, specs[0], &pairs));
    const double r = 1 / std::sqrt(2.0);
    // sorted by x then y: (2,3) (2,4) (3,3) (4,3) (4,4)
    checkPairs("footing (all faces)", 2, pairs, {1, 0.5, 1, 1, 0.5}, {{r, r}, {1, 0}, {0, 1}, {-r, r}, {-1, 0}}, {{2, 3}, {2, 4}, {3, 3}, {4, 3}, {4, 4}});
    PetscCall(DMDestroy(&split));
  }
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

// 2x2x2 unit hexes, top layer = block: the interface z = 1 is a 2x2 grid of unit squares,
// lumped weights 1/4 per corner: corners 0.25, edge midpoints 0.5, centre 1 (sum 4).
PetscErrorCode testHexes() {
  const PetscInt           faces[3] = {2, 2, 2};
  const double             lo[3] = {0, 0, 0}, hi[3] = {2, 2, 2};
  DM                       dm, split;
  std::vector<std::string> sides;
  PetscFunctionBeginUser;
  PetscCall(createBox(3, faces, lo, hi, [](const double *x) -> PetscInt { return x[2] < 1 ? 0 : 1; }, &dm, &sides));
  const std::vector<InterfaceSpec> specs = {{"base", "soil", "block", ""}};
  PetscCall(slipwave::meshing::InterfaceSplitSerialMesh(dm, {"soil", "block"}, sides, specs, &split));
  PetscCall(checkSplit("hexes 2x2x2", dm, split, sides, specs, {1}, {0}, {9}));
  std::vector<Pair> pairs;
  PetscCall(buildPairs(split, specs[0], &pairs));
  std::vector<double>              areas;
  std::vector<std::vector<double>> xs;
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) {
      areas.push_back(0.25 * (i == 1 ? 2 : 1) * (j == 1 ? 2 : 1));
      xs.push_back({(double)i, (double)j, 1});
    }
  checkPairs("hexes 2x2x2", 3, pairs, areas, {kUp3}, xs);
  PetscCall(DMDestroy(&split));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

// A hand-made simplex mesh (box meshes are quads/hexes only in this PETSc), regions by centroid.
PetscErrorCode createFromList(PetscInt dim, PetscInt ncorners, const std::vector<PetscInt> &cells, const std::vector<double> &xyz, const RegionOf &region_of, DM *dm) {
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  std::vector<PetscReal> x(xyz.begin(), xyz.end());
  PetscCall(DMPlexCreateFromCellListPetsc(PETSC_COMM_WORLD, dim, rank ? 0 : (PetscInt)cells.size() / ncorners, rank ? 0 : (PetscInt)xyz.size() / dim, ncorners, PETSC_TRUE,
                                          cells.data(), dim, x.data(), dm));
  PetscCall(labelRegions(*dm, region_of));
  PetscFunctionReturn(0);
}

// Triangles: [0,2]^2 as 2x2 squares cut by their (0,0)-(1,1) diagonals, soil y < 1. The
// interface y = 1 has two unit segments: 0.5, 1, 0.5.
PetscErrorCode testTriangles() {
  std::vector<PetscInt> cells;
  std::vector<double>   xyz;
  DM                    dm, split;
  PetscFunctionBeginUser;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 2; ++i) xyz.insert(xyz.end(), {(double)i, (double)j});
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const PetscInt v00 = i + 3 * j, v10 = v00 + 1, v01 = v00 + 3, v11 = v00 + 4;
      cells.insert(cells.end(), {v00, v10, v11, v00, v11, v01}); // counter-clockwise
    }
  PetscCall(createFromList(2, 3, cells, xyz, [](const double *x) -> PetscInt { return x[1] < 1 ? 0 : 1; }, &dm));
  PetscCall(DMPlexCheck(dm));
  const double             lo[2] = {0, 0}, hi[2] = {2, 2};
  std::vector<std::string> sides;
  PetscCall(labelSides(dm, lo, hi, &sides));
  const std::vector<InterfaceSpec> specs = {{"base", "soil", "block", ""}};
  PetscCall(slipwave::meshing::InterfaceSplitSerialMesh(dm, {"soil", "block"}, sides, specs, &split));
  PetscCall(checkSplit("triangles", dm, split, sides, specs, {1}, {0}, {3}));
  std::vector<Pair> pairs;
  PetscCall(buildPairs(split, specs[0], &pairs));
  checkPairs("triangles", 2, pairs, {0.5, 1, 0.5}, {kUp2}, {{0, 1}, {1, 1}, {2, 1}});
  PetscCall(DMDestroy(&split));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

// Tets: two unit cubes stacked in z, each cut into the 6 tets around its (0,0,0)-(1,1,1)
// diagonal (conforming: both cubes cut the square z = 1 along (0,0,1)-(1,1,1)). Soil z < 1.
// Interface: two triangles of area 1/2, 1/6 per corner: (0,0) and (1,1) get 1/3, (1,0) and
// (0,1) 1/6 (sum 1).
PetscErrorCode testTets() {
  std::vector<PetscInt> cells;
  std::vector<double>   xyz;
  DM                    dm, split;
  PetscFunctionBeginUser;
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 1; ++i) xyz.insert(xyz.end(), {(double)i, (double)j, (double)k});
  auto id = [](int i, int j, int k) { return (PetscInt)(i + 2 * j + 4 * k); };
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < 2; ++k)
    for (const auto &p : perms) {
      int      c[3] = {0, 0, k};
      PetscInt t[4];
      t[0] = id(c[0], c[1], c[2]);
      for (int s = 0; s < 3; ++s) {
        ++c[p[s]];
        t[s + 1] = id(c[0], c[1], c[2]);
      }
      // PETSc's reference tetrahedron has v0, v1, v2 clockwise seen from v3 (its triple
      // product (v1-v0)x(v2-v0)·(v3-v0) < 0); DMPlexCheck (geometry) below confirms the choice.
      double e[3][3];
      for (int a = 0; a < 3; ++a)
        for (int d = 0; d < 3; ++d) e[a][d] = xyz[3 * t[a + 1] + d] - xyz[3 * t[0] + d];
      const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
      if (det > 0) std::swap(t[1], t[2]);
      cells.insert(cells.end(), t, t + 4);
    }
  PetscCall(createFromList(3, 4, cells, xyz, [](const double *x) -> PetscInt { return x[2] < 1 ? 0 : 1; }, &dm));
  PetscCall(DMPlexCheck(dm));
  const double             lo[3] = {0, 0, 0}, hi[3] = {1, 1, 2};
  std::vector<std::string> sides;
  PetscCall(labelSides(dm, lo, hi, &sides));
  const std::vector<InterfaceSpec> specs = {{"base", "soil", "block", ""}};
  PetscCall(slipwave::meshing::InterfaceSplitSerialMesh(dm, {"soil", "block"}, sides, specs, &split));
  PetscCall(checkSplit("tets", dm, split, sides, specs, {1}, {0}, {4}));
  std::vector<Pair> pairs;
  PetscCall(buildPairs(split, specs[0], &pairs));
  checkPairs("tets", 3, pairs, {1.0 / 3, 1.0 / 6, 1.0 / 6, 1.0 / 3}, {kUp3}, {{0, 0, 1}, {0, 1, 1}, {1, 0, 1}, {1, 1, 1}});
  PetscCall(DMDestroy(&split));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

// Runs f with errors returned instead of printed; *code: the error, *msg: PETSc's message.
PetscErrorCode expectError(const std::function<PetscErrorCode()> &f, PetscErrorCode *code, std::string *msg) {
  PetscFunctionBeginUser;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  *code = f();
  PetscCall(PetscPopErrorHandler());
  const char *text = nullptr;
  char       *specific = nullptr;
  PetscErrorMessage(*code, &text, &specific);
  *msg = specific ? specific : "";
  PetscFunctionReturn(0);
}

// Three layers on 4x4: soil y < 2, mid y in [2,3], top y > 3. Two interfaces in one call
// (soil|mid at y = 2, mid|top at y = 3: no common vertex): 5 pairs each, 25 + 10 vertices;
// mid cells use the copies at y = 2 and the originals at y = 3. Then the errors.
PetscErrorCode testSeveralAndErrors() {
  const PetscInt           faces[2] = {4, 4};
  const double             lo[2] = {0, 0}, hi[2] = {4, 4};
  DM                       dm, split = nullptr;
  std::vector<std::string> sides;
  const std::vector<std::string> regions = {"soil", "mid", "top"};
  PetscFunctionBeginUser;
  PetscCall(createBox(2, faces, lo, hi, [](const double *x) -> PetscInt { return x[1] < 2 ? 0 : (x[1] < 3 ? 1 : 2); }, &dm, &sides));
  const std::vector<InterfaceSpec> specs = {{"lower", "soil", "mid", ""}, {"upper", "mid", "top", ""}};
  PetscCall(slipwave::meshing::InterfaceSplitSerialMesh(dm, regions, sides, specs, &split));
  PetscCall(checkSplit("two interfaces", dm, split, sides, specs, {1, 2}, {0, 1}, {5, 5}));
  for (size_t s = 0; s < specs.size(); ++s) {
    std::vector<Pair> pairs;
    PetscCall(buildPairs(split, specs[s], &pairs));
    const double y = s == 0 ? 2 : 3;
    checkPairs("two interfaces, " + specs[s].name, 2, pairs, {0.5, 1, 1, 1, 0.5}, {kUp2}, {{0, y}, {1, y}, {2, y}, {3, y}, {4, y}});
  }
  PetscCall(DMDestroy(&split));

  PetscErrorCode code;
  std::string    msg;
  PetscCall(expectError([&]() { return slipwave::meshing::InterfaceSplitSerialMesh(dm, regions, sides, {{"far", "soil", "top", ""}}, &split); }, &code, &msg));
  std::printf("# no shared face: %s\n", msg.c_str());
  unit::check(code == PETSC_ERR_USER_INPUT, "regions without a common face: PETSC_ERR_USER_INPUT");
  unit::check(msg.find("'far'") != std::string::npos && msg.find("'soil'") != std::string::npos && msg.find("'top'") != std::string::npos &&
                  msg.find("share no face") != std::string::npos,
              "regions without a common face: the message names the interface, both regions and says they share no face");
  PetscCall(expectError([&]() { return slipwave::meshing::InterfaceSplitSerialMesh(dm, regions, sides, {{"x", "soil", "rock", ""}}, &split); }, &code, &msg));
  unit::check(code == PETSC_ERR_USER_INPUT && msg.find("'rock'") != std::string::npos, "unknown region: PETSC_ERR_USER_INPUT naming it");
  PetscCall(expectError([&]() { return slipwave::meshing::InterfaceSplitSerialMesh(dm, regions, sides, {{"x", "soil", "mid", "nolabel"}}, &split); }, &code, &msg));
  unit::check(code == PETSC_ERR_USER_INPUT && msg.find("'nolabel'") != std::string::npos, "unknown face label: PETSC_ERR_USER_INPUT naming it");
  PetscCall(DMDestroy(&dm));

  // soil | left block and soil | right block meet at the vertex (2,2).
  PetscCall(createBox(2, faces, lo, hi, [](const double *x) -> PetscInt { return x[1] < 2 ? 0 : (x[0] < 2 ? 1 : 2); }, &dm, &sides));
  PetscCall(expectError(
      [&]() { return slipwave::meshing::InterfaceSplitSerialMesh(dm, {"soil", "a", "b"}, sides, {{"ia", "soil", "a", ""}, {"ib", "soil", "b", ""}}, &split); }, &code, &msg));
  std::printf("# touching interfaces: %s\n", msg.c_str());
  unit::check(code == PETSC_ERR_USER_INPUT && msg.find("'ia'") != std::string::npos && msg.find("'ib'") != std::string::npos,
              "interfaces sharing a vertex: PETSC_ERR_USER_INPUT naming both");
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

// A Gmsh mesh (unstructured triangles or tetrahedra from tests/cases/interface_split_mpi.sh)
// of two bodies meshed conformingly along the plane "last coordinate = h": soil below, block
// above by centroid. Checks the generic split properties, one pair per mesh vertex on the
// plane, total area = the plane's extent (product of the other extents), normals straight up.
PetscErrorCode testGmsh(const char *file, double h) {
  DM       dm, split;
  PetscInt dim, v_start, v_end, on_plane = 0;
  PetscFunctionBeginUser;
  PetscCall(DMPlexCreateFromFile(PETSC_COMM_WORLD, file, "gmsh", PETSC_TRUE, &dm));
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(labelRegions(dm, [dim, h](const double *x) -> PetscInt { return x[dim - 1] < h ? 0 : 1; }));
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v_start, &v_end));
  for (PetscInt v = v_start; v < v_end; ++v) {
    double x[3];
    PetscCall(vertexCoords(dm, v, x));
    for (PetscInt d = 0; d < dim; ++d) lo[d] = std::min(lo[d], x[d]), hi[d] = std::max(hi[d], x[d]);
    on_plane += std::fabs(x[dim - 1] - h) < 1e-9;
  }
  std::vector<std::string> sides;
  PetscCall(labelSides(dm, lo, hi, &sides));
  const std::string tag = std::string("gmsh ") + (dim == 2 ? "triangles" : "tets");
  const std::vector<InterfaceSpec> specs = {{"base", "soil", "block", ""}};
  PetscCall(slipwave::meshing::InterfaceSplitSerialMesh(dm, {"soil", "block"}, sides, specs, &split));
  PetscCall(checkSplit(tag, dm, split, sides, specs, {1}, {0}, {on_plane}));
  std::vector<Pair> pairs;
  PetscCall(buildPairs(split, specs[0], &pairs));
  double total = 0, extent = 1;
  bool   up = pairs.size() == (size_t)on_plane;
  for (const Pair &p : pairs) {
    total += p.area;
    for (PetscInt d = 0; d < dim; ++d) up = up && std::fabs(p.n[d] - (d == dim - 1 ? 1 : 0)) < 1e-12;
    up = up && std::fabs(p.x[dim - 1] - h) < 1e-9 && p.area > 0;
  }
  for (PetscInt d = 0; d < dim - 1; ++d) extent *= hi[d] - lo[d];
  unit::check(up, tag + ": " + std::to_string(on_plane) + " pairs (the mesh vertices on the plane), on the plane, normal up, positive area");
  unit::near(total, extent, 1e-12, 0, tag + ": total area = extent of the plane");
  PetscCall(DMDestroy(&split));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

// ---- distributed ----------------------------------------------------------------------

// 8x8 unit quads, soil y < 4, block y > 4: 9 pairs along y = 4, areas 0.5, 1 x 7, 0.5.
// `how`: "options" (the partitioner from the options: metis in the case script) or "cut"
// (cells with x < 4 to rank 0, the rest to the last rank: the interface is cut in two).
PetscErrorCode distributedCase(const char *how) {
  const PetscInt           faces[2] = {8, 8};
  const double             lo[2] = {0, 0}, hi[2] = {8, 8};
  DM                       dm, split, dist = nullptr;
  std::vector<std::string> sides;
  PetscMPIInt              rank, size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  PetscCall(createBox(2, faces, lo, hi, [](const double *x) -> PetscInt { return x[1] < 4 ? 0 : 1; }, &dm, &sides));
  const InterfaceSpec spec = {"base", "soil", "block", ""};
  PetscCall(slipwave::meshing::InterfaceSplitSerialMesh(dm, {"soil", "block"}, sides, {spec}, &split));
  PetscCall(DMDestroy(&dm));

  // Serial reference on the same split mesh (all on rank 0, which owns every pair).
  InterfacePairs serial;
  {
    DM copy;
    PetscCall(DMClone(split, &copy));
    PetscCall(slipwave::fem::NodeFieldSetSection(copy, 2));
    PetscCall(slipwave::meshing::InterfacePairsBuild(copy, spec, &serial));
    PetscCall(DMDestroy(&copy));
  }
  std::vector<double> ref_area(9, 0), ref_normal(18, 0), ref_x(18, 0);
  for (size_t k = 0; k < serial.id.size(); ++k) {
    ref_area[serial.id[k]] = serial.area[k];
    for (int d = 0; d < 2; ++d) ref_normal[2 * serial.id[k] + d] = serial.normal[2 * k + d], ref_x[2 * serial.id[k] + d] = serial.coords[2 * k + d];
  }
  PetscCallMPI(MPI_Bcast(ref_area.data(), 9, MPI_DOUBLE, 0, PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Bcast(ref_normal.data(), 18, MPI_DOUBLE, 0, PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Bcast(ref_x.data(), 18, MPI_DOUBLE, 0, PETSC_COMM_WORLD));
  bool ref_ok = true;
  for (int p = 0; p < 9; ++p) {
    // the interface is y = 4, x = 0..8 in unit steps: end pairs get half a segment
    const double want = (ref_x[2 * p] == 0 || ref_x[2 * p] == 8) ? 0.5 : 1.0;
    ref_ok = ref_ok && ref_area[p] == want && ref_x[2 * p + 1] == 4 && ref_normal[2 * p] == 0 && ref_normal[2 * p + 1] == 1;
  }
  const std::string tag = std::string("distributed (") + how + ")";
  if (rank == 0) unit::check(serial.n_global == 9 && serial.id.size() == 9 && ref_ok, tag + ": serial reference: 9 pairs, areas 0.5/1/0.5, normal (0,1), y = 4");

  PetscPartitioner part;
  PetscCall(DMPlexGetPartitioner(split, &part));
  if (std::strcmp(how, "cut") == 0) {
    PetscInt c_start, c_end;
    PetscCall(DMPlexGetHeightStratum(split, 0, &c_start, &c_end));
    std::vector<PetscInt> sizes(size, 0), points;
    for (int pass = 0; pass < 2; ++pass)
      for (PetscInt c = c_start; c < c_end; ++c) {
        double x[2];
        PetscCall(centroid(split, c, x));
        if ((x[0] < 4) == (pass == 0)) {
          points.push_back(c);
          ++sizes[pass == 0 ? 0 : size - 1];
        }
      }
    PetscCall(PetscPartitionerSetType(part, PETSCPARTITIONERSHELL));
    PetscCall(PetscPartitionerShellSetPartition(part, size, sizes.data(), points.data()));
  } else {
    PetscCall(PetscPartitionerSetFromOptions(part));
  }
  PetscCall(DMPlexDistribute(split, 0, nullptr, &dist));
  if (dist) {
    PetscCall(DMDestroy(&split));
    split = dist;
  }
  PetscCall(slipwave::fem::NodeFieldSetSection(split, 2));
  InterfacePairs pairs;
  PetscCall(slipwave::meshing::InterfacePairsBuild(split, spec, &pairs));

  // Is the interface cut? (soil-side faces on more than one rank)
  PetscInt has_faces = pairs.face_pairs.empty() ? 0 : 1, ranks_with_faces = 0, owned = (PetscInt)pairs.id.size(), owned_total = 0;
  PetscCallMPI(MPI_Allreduce(&has_faces, &ranks_with_faces, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Allreduce(&owned, &owned_total, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  std::vector<PetscInt> times_owned(9, 0);
  for (PetscInt p : pairs.id)
    if (p >= 0 && p < 9) ++times_owned[p];
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, times_owned.data(), 9, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCall(PetscSynchronizedPrintf(PETSC_COMM_WORLD, "# %s: rank %d owns %d pairs, holds %d interface faces\n", tag.c_str(), rank, (int)owned,
                                    (int)(pairs.face_pairs.size() / std::max<PetscInt>(pairs.nodes_per_face, 1))));
  PetscCall(PetscSynchronizedFlush(PETSC_COMM_WORLD, PETSC_STDOUT));

  // Each dof must point at its own vertex: a global vector holding (x, side) per vertex
  // (side: 0 soil copy, 1 structure copy, -1 elsewhere), gathered everywhere.
  Vec          local, global, all;
  VecScatter   to_all;
  PetscInt     v_start, v_end, nglobal;
  PetscSection lsec;
  DMLabel      side;
  PetscCall(DMGetLocalSection(split, &lsec));
  PetscCall(DMGetLabel(split, "interface_base_side", &side));
  PetscCall(DMCreateLocalVector(split, &local));
  PetscCall(DMCreateGlobalVector(split, &global));
  PetscCall(DMPlexGetDepthStratum(split, 0, &v_start, &v_end));
  PetscScalar *a;
  PetscCall(VecGetArray(local, &a));
  for (PetscInt v = v_start; v < v_end; ++v) {
    PetscInt off, s;
    double   x[2];
    PetscCall(PetscSectionGetOffset(lsec, v, &off));
    PetscCall(DMLabelGetValue(side, v, &s));
    PetscCall(vertexCoords(split, v, x));
    a[off] = x[0], a[off + 1] = s;
  }
  PetscCall(VecRestoreArray(local, &a));
  PetscCall(DMLocalToGlobal(split, local, INSERT_VALUES, global));
  PetscCall(VecGetSize(global, &nglobal));
  PetscCall(VecScatterCreateToAll(global, &to_all, &all));
  PetscCall(VecScatterBegin(to_all, global, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(to_all, global, all, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar *g;
  PetscCall(VecGetArrayRead(all, &g));
  PetscInt bad_dof = 0, bad_geom = 0;
  for (size_t k = 0; k < pairs.id.size(); ++k) {
    const PetscInt p = pairs.id[k], sd = pairs.soil_dof[k], bd = pairs.structure_dof[k];
    const bool     in_range = sd >= 0 && sd + 1 < nglobal && bd >= 0 && bd + 1 < nglobal && sd != bd;
    if (!in_range || PetscRealPart(g[sd]) != ref_x[2 * p] || PetscRealPart(g[bd]) != ref_x[2 * p] || PetscRealPart(g[sd + 1]) != 0 || PetscRealPart(g[bd + 1]) != 1) ++bad_dof;
    if (std::fabs(pairs.area[k] - ref_area[p]) > 1e-14 || std::fabs(pairs.normal[2 * k] - ref_normal[2 * p]) > 1e-14 || std::fabs(pairs.normal[2 * k + 1] - ref_normal[2 * p + 1]) > 1e-14 ||
        pairs.coords[2 * k] != ref_x[2 * p] || pairs.coords[2 * k + 1] != ref_x[2 * p + 1])
      ++bad_geom;
  }
  PetscCall(VecRestoreArrayRead(all, &g));
  PetscCall(VecScatterDestroy(&to_all));
  PetscCall(VecDestroy(&all));
  PetscCall(VecDestroy(&global));
  PetscCall(VecDestroy(&local));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &bad_dof, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &bad_geom, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscInt face_entries = (PetscInt)pairs.face_pairs.size(), face_entries_total = 0;
  PetscCallMPI(MPI_Allreduce(&face_entries, &face_entries_total, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));

  if (rank == 0) {
    std::printf("# %s: interface faces on %d of %d ranks (%s)\n", tag.c_str(), (int)ranks_with_faces, size, ranks_with_faces > 1 ? "cut by the partition" : "not cut");
    if (std::strcmp(how, "cut") == 0) unit::check(ranks_with_faces > 1, tag + ": the interface is cut by the partition");
    unit::check(pairs.n_global == 9, tag + ": n_global = 9");
    bool once = owned_total == 9;
    for (PetscInt n : times_owned) once = once && n == 1;
    unit::check(once, tag + ": every pair owned by exactly one rank (" + std::to_string(owned_total) + " owned in all)");
    unit::check(bad_dof == 0, tag + ": soil/structure dofs within the global vector, distinct, and pointing at the right vertex and copy");
    unit::check(bad_geom == 0, tag + ": areas, normals, coordinates equal the serial values");
    unit::check(face_entries_total == 8 * 2, tag + ": the 8 interface faces appear once over the ranks (2 pair ids each)");
  }
  PetscCall(DMDestroy(&split));
  PetscFunctionReturn(0);
}

PetscErrorCode Run(bool distribute) {
  char      gmsh[PETSC_MAX_PATH_LEN];
  PetscBool has_gmsh;
  PetscReal h = 0;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-gmsh_file", gmsh, sizeof gmsh, &has_gmsh));
  if (has_gmsh) {
    PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-gmsh_plane", &h, nullptr));
    PetscCall(testGmsh(gmsh, h));
    PetscFunctionReturn(0);
  }
  if (distribute) {
    PetscCall(slipwave::mesh::PartitionerRegisterMetis());
    PetscCall(distributedCase("options"));
    PetscCall(distributedCase("cut"));
    PetscFunctionReturn(0);
  }
  PetscMPIInt size;
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  // The serial checks read the whole mesh on every rank; the split itself on several ranks
  // (rank 0 holds all, the others nothing) is exercised by -distribute.
  PetscCheck(size == 1, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "test_interface_split without -distribute runs on one rank");
  PetscCall(testQuads());
  PetscCall(testFooting());
  PetscCall(testHexes());
  PetscCall(testTriangles());
  PetscCall(testTets());
  PetscCall(testSeveralAndErrors());
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char **argv) { return unit::runPetscTest(argc, argv, Run); }

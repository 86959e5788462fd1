// Spectral elements as GLL sub-cells (meshing/spectral_subdivision, spectral_layout,
// spectral_face_weights), through MeshCreate with -element_degree, on any number of ranks
// (tests/cases/spectral_mesh.sh runs it on 1 and 2). Expected numbers:
//  - a box of n_x x n_y (x n_z) elements of degree p has (n_x p + 1)(n_y p + 1)(...) nodes, at
//    x = lower + h (e + (xi_i + 1)/2) per axis (xi_i the GLL points, numerics::gllPointsWeights,
//    themselves unit-tested against closed forms);
//  - a labelled side of m faces has m p^(dim-1) sub-faces;
//  - the layout groups p^dim sub-cells per element, whole on one rank, every element once,
//    and its nodes, read lexicographically, are the element's Q1 map at the GLL points;
//  - GLL weights for p = 4 on [-1, 1]: 1/10, 49/90, 32/45, 49/90, 1/10; p = 3: 1/6, 5/6, 5/6,
//    1/6. A node's assembled face weight is (h/2) w_i, doubled at a node two elements share;
//    3D: (h/2)^2 w_i w_j. Their sum is the side's length / area.
//  - an interface along y = 1 of 4 elements of degree 4: 4 p + 1 = 17 pairs with those areas;
//    in 3D along z = 1 under 2x2 elements of degree 2: 25 pairs (see interface3d).
//  - p = 1: one element per cell, its nodes lexicographic (node 1 - node 0 along the first
//    frame axis, node 2 - node 0 along the second, right-handed).
//  - -gmsh_file f.msh [-gmsh_cells V,E,C]: a Gmsh quad or hex mesh at p = 3 has
//    V + E (p-1) + F (p-1)^2 + C (p-1)^dim nodes (see gmsh()).
#include "slipwave/fem/node_fields.hpp"
#include "slipwave/input/boundary_faces.hpp"
#include "slipwave/mesh/spectral_face_weights.hpp"
#include "slipwave/mesh/spectral_layout.hpp"
#include "slipwave/meshing/mesh_builder.hpp"
#include "slipwave/numerics/gll_basis.hpp"

#include "petsc_test_main.hpp"

#include <petscsf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace {

using Options = std::vector<std::pair<const char *, const char *>>;

PetscErrorCode build(const Options &opts, DM *dm, slipwave::meshing::MeshDescription *desc) {
  PetscFunctionBeginUser;
  for (auto &o : opts) PetscCall(PetscOptionsSetValue(nullptr, o.first, o.second));
  PetscCall(slipwave::meshing::MeshCreate(PETSC_COMM_WORLD, dm, desc));
  for (auto &o : opts) PetscCall(PetscOptionsClearValue(nullptr, o.first));
  PetscFunctionReturn(0);
}

// Vertices this rank owns (not leaves of the point SF), summed over ranks.
PetscErrorCode globalVertexCount(DM dm, PetscInt *n) {
  PetscInt        v_start, v_end, nleaves;
  const PetscInt *leaves;
  PetscSF         sf;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v_start, &v_end));
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, nullptr, &nleaves, &leaves, nullptr));
  std::vector<char> ghost(v_end - v_start, 0);
  for (PetscInt i = 0; i < (nleaves > 0 ? nleaves : 0); ++i) {
    const PetscInt q = leaves ? leaves[i] : i;
    if (q >= v_start && q < v_end) ghost[q - v_start] = 1;
  }
  *n = 0;
  for (char g : ghost) *n += !g;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, n, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscFunctionReturn(0);
}

// Index of x on the GLL grid of an axis (elements of size h from lower), -1 if off the grid.
PetscInt gridIndex(double x, double lower, double h, PetscInt n, PetscInt p, const double *gll) {
  for (PetscInt e = 0; e < n; ++e)
    for (PetscInt i = 0; i <= p; ++i)
      if (std::fabs(x - (lower + h * (e + 0.5 * (gll[i] + 1)))) < 1e-12 * h * n) return e * p + i;
  return -1;
}

// The layout against the Q1 map of each element's corners; the elements over all ranks.
PetscErrorCode checkLayout(DM dm, PetscInt degree, PetscInt nelem_global, const std::string &what) {
  const slipwave::mesh::SpectralLayout *L;
  slipwave::mesh::SpectralLayout        built;
  PetscFunctionBeginUser;
  if (degree > 1) PetscCall(slipwave::mesh::SpectralLayoutOf(dm, &L));
  else {
    PetscCall(slipwave::mesh::SpectralLayoutBuild(dm, 1, &built));
    L = &built;
  }
  PetscInt dim, c_start, c_end, nlocal = 0;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
  double gll[9], w[9];
  slipwave::numerics::gllPointsWeights((int)degree, gll, w);
  const PetscInt np1 = degree + 1, nnode = dim == 2 ? np1 * np1 : np1 * np1 * np1, nsub = dim == 2 ? degree * degree : degree * degree * degree;
  std::vector<double> centre; // per element: the mean of its corners, to count each once over ranks
  double                err = 0;
  bool                  cells_ok = true;
  slipwave::mesh::VertexCoordinates vc;
  PetscCall(vc.Open(dm));
  if (L) {
    nlocal = L->nelem;
    for (PetscInt e = 0; e < L->nelem; ++e) {
      double X[8][3];
      for (PetscInt k = 0; k < (dim == 2 ? 4 : 8); ++k) {
        const PetscInt a = (k & 1) * degree, b = ((k >> 1) & 1) * degree, z = ((k >> 2) & 1) * degree;
        PetscCall(vc.Get(L->element_nodes[e * nnode + a + np1 * (b + np1 * z)], X[k]));
      }
      for (PetscInt d = 0; d < 3; ++d) {
        double m = 0;
        for (PetscInt k = 0; k < (dim == 2 ? 4 : 8); ++k) m += d < dim ? X[k][d] : 0;
        centre.push_back(m);
      }
      for (PetscInt n = 0; n < nnode; ++n) {
        const PetscInt idx[3] = {n % np1, (n / np1) % np1, n / (np1 * np1)};
        double         want[3] = {0, 0, 0}, got[3];
        for (PetscInt k = 0; k < (dim == 2 ? 4 : 8); ++k) {
          double N = 1;
          for (PetscInt d = 0; d < dim; ++d) N *= ((k >> d) & 1) ? 0.5 * (gll[idx[d]] + 1) : 0.5 * (1 - gll[idx[d]]);
          for (PetscInt d = 0; d < dim; ++d) want[d] += N * X[k][d];
        }
        PetscCall(vc.Get(L->element_nodes[e * nnode + n], got));
        for (PetscInt d = 0; d < dim; ++d) err = std::max(err, std::fabs(got[d] - want[d]));
      }
      for (PetscInt s = 0; s < nsub; ++s) {
        const PetscInt c = L->element_cells[e * nsub + s];
        cells_ok = cells_ok && L->cell_element[c - c_start] == e && L->cell_position[c - c_start] == s;
      }
      // Right-handed frame: the first two axes turn counter-clockwise (2D); triple product > 0 (3D).
      if (dim == 2) cells_ok = cells_ok && (X[1][0] - X[0][0]) * (X[2][1] - X[0][1]) - (X[1][1] - X[0][1]) * (X[2][0] - X[0][0]) > 0;
      if (dim == 3) { // (x1 - x0) x (x2 - x0) . (x4 - x0) > 0: box elements have right angles there
        double a[3], b[3], c[3];
        for (int d = 0; d < 3; ++d) a[d] = X[1][d] - X[0][d], b[d] = X[2][d] - X[0][d], c[d] = X[4][d] - X[0][d];
        cells_ok = cells_ok && (a[1] * b[2] - a[2] * b[1]) * c[0] + (a[2] * b[0] - a[0] * b[2]) * c[1] + (a[0] * b[1] - a[1] * b[0]) * c[2] > 0;
      }
    }
    cells_ok = cells_ok && (PetscInt)L->cell_element.size() == c_end - c_start;
  }
  PetscCall(vc.Close());
  // Elements of all ranks by their centres: all distinct (an element counted on two ranks would
  // repeat one).
  PetscMPIInt size, rank;
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  int              mine = (int)centre.size();
  std::vector<int> counts(size), displs(size, 0);
  PetscCallMPI(MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, PETSC_COMM_WORLD));
  for (int r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<double> all(displs[size - 1] + counts[size - 1]);
  PetscCallMPI(MPI_Allgatherv(centre.data(), mine, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, PETSC_COMM_WORLD));
  std::vector<std::array<double, 3>> keys;
  for (size_t i = 0; i + 2 < all.size(); i += 3) keys.push_back({all[i], all[i + 1], all[i + 2]});
  std::sort(keys.begin(), keys.end());
  bool once = std::adjacent_find(keys.begin(), keys.end()) == keys.end();
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &nlocal, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &err, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD));
  int ok = cells_ok;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &ok, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD));
  unit::check(nlocal == nelem_global && once, what + ": every element on exactly one rank, whole");
  unit::check(ok, what + ": every sub-cell at its position in its element, frames right-handed");
  unit::near(err, 0, 0, 1e-12, what + ": element nodes lexicographic = the Q1 map of the corners at the GLL points");
  PetscFunctionReturn(0);
}

PetscInt countFaces(DM dm, const char *name) {
  std::vector<slipwave::input::BoundaryFace> faces;
  PetscCallAbort(PETSC_COMM_WORLD, slipwave::input::BoundaryFacesGet(dm, name, &faces));
  PetscInt n = (PetscInt)faces.size();
  MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD);
  return n;
}

PetscErrorCode box2d() {
  DM                              dm;
  slipwave::meshing::MeshDescription desc;
  PetscFunctionBeginUser;
  PetscCall(build({{"-mesh_box_faces", "3,2"}, {"-mesh_box_upper", "6,2"}, {"-element_degree", "4"}}, &dm, &desc));
  const PetscInt p = 4;
  double         gll[5], w[5];
  slipwave::numerics::gllPointsWeights(4, gll, w);
  PetscInt nv;
  PetscCall(globalVertexCount(dm, &nv));
  unit::check(nv == 13 * 9 && desc.degree == 4, "2D box 3x2, p = 4: (3*4+1)(2*4+1) = 117 nodes");
  PetscInt v_start, v_end;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v_start, &v_end));
  slipwave::mesh::VertexCoordinates vc;
  PetscCall(vc.Open(dm));
  int on_grid = 1;
  for (PetscInt v = v_start; v < v_end; ++v) {
    double x[2];
    PetscCall(vc.Get(v, x));
    on_grid = on_grid && gridIndex(x[0], 0, 2, 3, p, gll) >= 0 && gridIndex(x[1], 0, 1, 2, p, gll) >= 0;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &on_grid, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD));
  unit::check(on_grid, "2D box: every node at GLL coordinates of its element");
  unit::check(countFaces(dm, "bottom") == 12 && countFaces(dm, "top") == 12 && countFaces(dm, "left") == 8 && countFaces(dm, "right") == 8,
              "2D box: sides have 3*4 (bottom, top) and 2*4 (left, right) sub-faces");
  PetscCall(checkLayout(dm, p, 6, "2D box p = 4"));
  // Bottom weights per node, assembled over ranks by the node's x index.
  std::vector<slipwave::input::BoundaryFace> faces;
  PetscCall(slipwave::input::BoundaryFacesGet(dm, "bottom", &faces));
  std::vector<double> node_w(13, 0.0);
  for (auto &f : faces)
    for (PetscInt a = 0; a < f.nvert; ++a) {
      double x[2];
      PetscCall(vc.Get(f.vertices[a], x));
      node_w[gridIndex(x[0], 0, 2, 3, p, gll)] += f.weights[a];
    }
  PetscCall(vc.Close());
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, node_w.data(), 13, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD));
  const double gw[5] = {1. / 10, 49. / 90, 32. / 45, 49. / 90, 1. / 10}; // GLL p = 4, closed form
  double       sum = 0, err = 0;
  for (PetscInt k = 0; k < 13; ++k) {
    const PetscInt i    = k % 4;
    const double   want = 1.0 * (i == 0 && k > 0 && k < 12 ? 2 * gw[0] : gw[i == 0 && k == 12 ? 4 : i]); // h/2 = 1
    err = std::max(err, std::fabs(node_w[k] - want));
    sum += node_w[k];
  }
  unit::near(sum, 6, 1e-14, 0, "2D box: bottom weights sum to its length 6");
  unit::near(err, 0, 0, 1e-14, "2D box: bottom node weights = (h/2) GLL weights 1/10, 49/90, 32/45 (2/10 where elements meet)");
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

PetscErrorCode box3d() {
  DM                              dm;
  slipwave::meshing::MeshDescription desc;
  PetscFunctionBeginUser;
  PetscCall(build({{"-mesh_dim", "3"}, {"-mesh_box_faces", "2,1,1"}, {"-mesh_box_upper", "2,1,1"}, {"-element_degree", "3"}}, &dm, &desc));
  PetscInt nv;
  PetscCall(globalVertexCount(dm, &nv));
  unit::check(nv == 7 * 4 * 4, "3D box 2x1x1, p = 3: 7*4*4 = 112 nodes");
  unit::check(countFaces(dm, "top") == 18 && countFaces(dm, "left") == 9, "3D box: top 2*3^2 = 18, left 3^2 = 9 sub-faces");
  PetscCall(checkLayout(dm, 3, 2, "3D box p = 3"));
  std::vector<slipwave::input::BoundaryFace> faces;
  PetscCall(slipwave::input::BoundaryFacesGet(dm, "top", &faces));
  slipwave::mesh::VertexCoordinates vc;
  PetscCall(vc.Open(dm));
  double sum = 0, corner = 0;
  for (auto &f : faces)
    for (PetscInt a = 0; a < f.nvert; ++a) {
      double x[3];
      PetscCall(vc.Get(f.vertices[a], x));
      sum += f.weights[a];
      if (std::fabs(x[0]) + std::fabs(x[1]) < 1e-12) corner += f.weights[a];
    }
  PetscCall(vc.Close());
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &corner, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD));
  unit::near(sum, 2, 1e-14, 0, "3D box: top weights sum to its area 2");
  unit::near(corner, 0.25 / 36, 1e-13, 0, "3D box: top corner node weight (h/2)^2 w_0^2 = 1/4 * 1/36 (p = 3, w_0 = 1/6)");
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

PetscErrorCode interface2d() {
  DM                              dm;
  slipwave::meshing::MeshDescription desc;
  PetscFunctionBeginUser;
  PetscCall(build({{"-mesh_box_faces", "4,2"}, {"-mesh_box_upper", "4,2"}, {"-element_degree", "4"}, {"-regions", "soil,block"}, {"-region_block_box", "0,4,1,2"},
                   {"-interfaces", "base"}, {"-interface_base_regions", "soil,block"}},
                  &dm, &desc));
  PetscCall(slipwave::fem::NodeFieldSetSection(dm, 2));
  slipwave::meshing::InterfacePairs pairs;
  PetscCall(slipwave::meshing::InterfacePairsBuild(dm, desc.interfaces[0], &pairs));
  unit::check(pairs.n_global == 17, "interface along y = 1, 4 elements of p = 4: 4*4+1 = 17 pairs");
  double gll[5], w[5];
  slipwave::numerics::gllPointsWeights(4, gll, w);
  const double gw[5] = {1. / 10, 49. / 90, 32. / 45, 49. / 90, 1. / 10};
  double       err = 0, sum = 0;
  for (size_t k = 0; k < pairs.id.size(); ++k) {
    const PetscInt g = gridIndex(pairs.coords[2 * k], 0, 1, 4, 4, gll), i = g % 4;
    const double   want = 0.5 * (i == 0 && g > 0 && g < 16 ? 2 * gw[0] : gw[g == 16 ? 4 : i]); // h/2 = 1/2
    err = std::max(err, std::fabs(pairs.area[k] - want));
    sum += pairs.area[k];
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &err, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD));
  unit::near(err, 0, 0, 1e-14, "interface: pair areas = (h/2) GLL weights (2 w_0 where elements meet)");
  unit::near(sum, 4, 1e-14, 0, "interface: areas sum to its length 4");
  PetscCall(checkLayout(dm, 4, 8, "split box p = 4"));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

// 3D: 2x2x2 unit hexahedra, the block above z = 1, p = 2 (GLL weights 1/3, 4/3, 1/3):
// (2*2+1)^2 = 25 pairs; the pair at a corner of the plane (0,0,1) has (h/2)^2 w_0^2 = 1/36,
// the one at its centre (1,1,1), a corner of 4 elements, 4/36; they sum to the area 4.
PetscErrorCode interface3d() {
  DM                              dm;
  slipwave::meshing::MeshDescription desc;
  PetscFunctionBeginUser;
  PetscCall(build({{"-mesh_dim", "3"}, {"-mesh_box_faces", "2,2,2"}, {"-mesh_box_upper", "2,2,2"}, {"-element_degree", "2"}, {"-regions", "soil,block"},
                   {"-region_block_box", "0,2,0,2,1,2"}, {"-interfaces", "base"}, {"-interface_base_regions", "soil,block"}},
                  &dm, &desc));
  PetscCall(slipwave::fem::NodeFieldSetSection(dm, 3));
  slipwave::meshing::InterfacePairs pairs;
  PetscCall(slipwave::meshing::InterfacePairsBuild(dm, desc.interfaces[0], &pairs));
  unit::check(pairs.n_global == 25, "3D interface z = 1, 2x2 elements of p = 2: 5^2 = 25 pairs");
  double sum = 0, corner = 0, centre = 0;
  for (size_t k = 0; k < pairs.id.size(); ++k) {
    const double *x = &pairs.coords[3 * k];
    sum += pairs.area[k];
    if (std::fabs(x[0]) + std::fabs(x[1]) < 1e-12) corner += pairs.area[k];
    if (std::fabs(x[0] - 1) + std::fabs(x[1] - 1) < 1e-12) centre += pairs.area[k];
  }
  for (double *v : {&sum, &corner, &centre}) PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, v, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD));
  unit::near(sum, 4, 1e-14, 0, "3D interface: areas sum to 4");
  unit::near(corner, 1. / 36, 1e-13, 0, "3D interface: corner pair (h/2)^2 w_0^2 = 1/36");
  unit::near(centre, 4. / 36, 1e-13, 0, "3D interface: centre pair, 4 elements' corners, 4/36");
  PetscCall(checkLayout(dm, 2, 8, "split 3D box p = 2"));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

PetscErrorCode linear() {
  DM                              dm;
  slipwave::meshing::MeshDescription desc;
  PetscFunctionBeginUser;
  PetscCall(build({{"-mesh_box_faces", "3,2"}, {"-mesh_box_upper", "6,2"}}, &dm, &desc));
  PetscInt nv;
  PetscCall(globalVertexCount(dm, &nv));
  unit::check(nv == 12 && desc.degree == 1, "p = 1: the box's 4*3 vertices");
  PetscCall(checkLayout(dm, 1, 6, "2D box p = 1"));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

// counts "V,E,C" (2D, from the case script) or empty: the expected node count from the
// strata of the file's own interpolated mesh, V + E (p-1) + F (p-1)^2 + C (p-1)^3 (each
// vertex one node, each edge, face and cell its interior GLL nodes).
PetscErrorCode gmsh(const char *file, const char *counts) {
  DM                              dm, parent;
  slipwave::meshing::MeshDescription desc;
  PetscInt                        V, E, F = 0, C, dim;
  PetscFunctionBeginUser;
  PetscCall(DMPlexCreateFromFile(PETSC_COMM_WORLD, file, "parent", PETSC_TRUE, &parent));
  PetscCall(DMGetDimension(parent, &dim));
  PetscInt n[4] = {0, 0, 0, 0};
  for (PetscInt d = 0; d <= dim; ++d) {
    PetscInt a, b;
    PetscCall(DMPlexGetDepthStratum(parent, d, &a, &b));
    n[d] = b - a;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, n, 4, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCall(DMDestroy(&parent));
  V = n[0], E = n[1], C = n[dim];
  if (dim == 3) F = n[2];
  if (counts[0]) {
    PetscInt v2, e2, c2;
    PetscCheck(std::sscanf(counts, "%" PetscInt_FMT ",%" PetscInt_FMT ",%" PetscInt_FMT, &v2, &e2, &c2) == 3, PETSC_COMM_WORLD, PETSC_ERR_USER, "-gmsh_cells V,E,C");
    unit::check(v2 == V && e2 == E && c2 == C, "Gmsh mesh: the script's V, E = V + C - 1, C agree with the mesh's strata");
  }
  PetscCall(build({{"-mesh_file", file}, {"-regions", "soil"}, {"-element_degree", "3"}}, &dm, &desc));
  PetscInt nv;
  PetscCall(globalVertexCount(dm, &nv));
  const std::string what = dim == 2 ? "Gmsh quads" : "Gmsh hexes";
  unit::check(nv == V + 2 * E + 4 * F + 8 * C * (dim == 3) + 4 * C * (dim == 2), what + ", p = 3: V + 2E (+ 4F) + 4C (2D) / 8C (3D) nodes");
  PetscCall(checkLayout(dm, 3, C, what + " p = 3"));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

PetscErrorCode run(bool) {
  char      file[PETSC_MAX_PATH_LEN] = "", counts[64] = "";
  PetscBool has_file;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-gmsh_file", file, sizeof file, &has_file));
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-gmsh_cells", counts, sizeof counts, nullptr));
  if (has_file) PetscFunctionReturn(gmsh(file, counts));
  PetscCall(box2d());
  PetscCall(box3d());
  PetscCall(interface2d());
  PetscCall(interface3d());
  PetscCall(linear());
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char **argv) { return unit::runPetscTest(argc, argv, run); }

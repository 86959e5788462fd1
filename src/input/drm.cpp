#include "slipwave/input/drm.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "slipwave/core/option_choice.hpp"
#include "slipwave/input/drm_field_file.hpp"
#include "slipwave/medium/attenuation.hpp"
#include "slipwave/physics/biot.hpp"
#include "slipwave/physics/plane_wave_layered.hpp"

namespace slipwave::input {

struct Drm {
  physics::PlaneWaveLayered   field;
  physics::PlaneWaveType      wave = physics::PlaneWaveType::SV;
  TimeFunction                incident;
  double                      angle = 0, azimuth = 0;    // deg
  double                      radial[3] = {0, 0, 0}, transverse[3] = {0, 0, 0}; // horizontal unit vectors
  double                      surface = 0;                // vertical coordinate of the free surface
  double                      reference_depth = 0, radial_min = 0;
  std::vector<double>         depths;                     // distinct depths of this rank's DRM nodes
  // This rank's DRM nodes (nodes of its layer elements, every GLL node at degree p > 1):
  // local dof offset, depth index, delay p (xi - xi_min).
  std::vector<PetscInt>       node_offset;
  std::vector<size_t>         node_depth;
  std::vector<double>         node_delay;
  std::vector<double>         node_coords;                // dim per DRM node
  // This rank's layer elements (the bulk operator's: the cells at degree 1); per element node:
  // index into the DRM nodes and whether it is a b node.
  std::vector<PetscInt>       elements;
  std::vector<size_t>         element_node;
  std::vector<char>           element_node_is_b;
  std::vector<double>         scratch;                    // one layer element's vectors (DrmAddForce)
  physics::PlaneWaveHistories histories;
  std::string                 file;                       // -drm_free_field_file, or "" for the plane wave
  FieldFileHistories          file_histories;
  bool                        synthesized = false;
  std::vector<double>         u0;                         // dim per DRM node, at field_time
  // Saturated sites: per layer element its undrained medium (lambda_u, mu, alpha, M; M = 0 in
  // a dry element), and p0 per element node at field_time.
  bool                        saturated = false;
  std::vector<double>         element_fluid, p0;
  double                      field_time = 0;
  bool                        field_valid = false;
  // Damping of the forces (docs/drm.md, "Damped sites"): the stiffness-proportional Rayleigh
  // term beta K v0 with the solver's half-step velocity, and the constant-Q memory of each
  // layer element's rows, both from the committed state (the last accepted step), as the
  // solver's own memory (medium/attenuation.hpp) is.
  double                      beta = 0;                   // Rayleigh's stiffness coefficient [s]
  std::vector<double>         omega;                      // relaxation frequencies w_l [rad/s]; empty: no constant Q
  std::vector<double>         element_weight;             // per layer element: its region's Y_l (omega.size() each)
  std::vector<double>         u0_committed, v0;           // dim per DRM node: u0 at the committed time, the half-step velocity
  std::vector<double>         memory_committed, memory_trial; // per layer element row and mechanism
  std::vector<double>         drive_committed, drive_trial;   // per layer element row: its K_be u0_e or K_eb u0_b
  bool                        started = false, has_trial = false;
  double                      committed_time = 0, trial_time = 0;
  Vec                         f_local = nullptr, f_global = nullptr;
  std::vector<std::string>    report;
};

namespace {

const char *const kMethods[] = {"base", "drm"};
const char *const kWaves[]   = {"p", "sv", "sh"};

struct DrmOptions {
  PetscInt              wave = 1;
  PetscReal             angle = 0, azimuth = 0;
  PetscInt              offset = 2;
  std::vector<PetscReal> box;
  std::vector<std::string> regions;
  std::string            file;
};

PetscErrorCode readOptions(MPI_Comm comm, PetscInt dim, Drm *d, DrmOptions *o, bool *use_drm) {
  PetscInt  method = 0, nbox = 5;
  PetscReal box[5];
  char      regions[PETSC_MAX_PATH_LEN] = "", file[PETSC_MAX_PATH_LEN] = "";
  PetscBool box_set = PETSC_FALSE, regions_set = PETSC_FALSE, azimuth_set = PETSC_FALSE, wave_set = PETSC_FALSE, angle_set = PETSC_FALSE, file_set = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "Seismic input method", "slipwave");
  PetscCall(core::OptionsChoice(PetscOptionsObject, "-input_method",
                                "base (a vertically incident wave through the absorbing base, -input_wave) or drm (Domain Reduction Method, any incidence, -drm_*)",
                                kMethods, 2, &method, nullptr));
  *use_drm = method == 1;
  if (*use_drm) {
    PetscCall(core::OptionsChoice(PetscOptionsObject, "-drm_wave", "incident plane wave: p, sv, sh (sh: 3D only)", kWaves, 3, &o->wave, &wave_set));
    PetscCall(PetscOptionsReal("-drm_incidence_angle", "angle of the incident wave from the vertical in the half-space [deg]: 0 <= angle < 90 (2D: -90 < angle < 90, negative travels toward -x)",
                               "DrmCreate", o->angle, &o->angle, &angle_set));
    PetscCall(PetscOptionsReal("-drm_azimuth", "3D: horizontal direction of travel [deg] from +x toward +y, any value", "DrmCreate", o->azimuth, &o->azimuth, &azimuth_set));
    PetscCall(PetscOptionsRealArray("-drm_box", "interior Omega: elements with the centroid in xmin,xmax,ymin (2D) or xmin,xmax,ymin,ymax,zmin (3D) [m], open upward",
                                    "DrmCreate", box, &nbox, &box_set));
    PetscCall(PetscOptionsInt("-drm_offset", "default interior: the mesh's bounding box shrunk by this many elements (the smallest one's size) on the sides and base, >= 1", "DrmCreate",
                              o->offset, &o->offset, nullptr));
    PetscCall(PetscOptionsString("-drm_regions", "interior Omega: these regions a,b (instead of -drm_box)", "DrmCreate", regions, regions, sizeof regions, &regions_set));
    PetscCall(d->incident.Read(comm, "drm_", HistoryRole::IncidentWave, PetscOptionsObject));
    PetscCall(PetscOptionsString("-drm_free_field_file", "HDF5 file with the free field (/coordinates, /time, /displacement; docs/drm.md) instead of the plane wave",
                                 "DrmCreate", file, file, sizeof file, &file_set));
  }
  PetscOptionsEnd();
  if (!*use_drm) PetscFunctionReturn(0);
  const PetscInt want = dim == 2 ? 3 : 5;
  PetscCheck(!box_set || nbox == want, comm, PETSC_ERR_USER_INPUT, "-drm_box has %" PetscInt_FMT " values; allowed: %s", nbox,
             dim == 2 ? "xmin,xmax,ymin [m]" : "xmin,xmax,ymin,ymax,zmin [m]");
  PetscCheck(!(box_set && regions_set), comm, PETSC_ERR_USER_INPUT, "-drm_box and -drm_regions are both given; allowed: one of them");
  PetscCheck(o->offset >= 1, comm, PETSC_ERR_USER_INPUT, "-drm_offset = %" PetscInt_FMT "; allowed: >= 1 cells", o->offset);
  PetscCheck(dim == 3 || o->wave != 2, comm, PETSC_ERR_USER_INPUT, "-drm_wave = sh in 2D; allowed: p or sv (SH moves out of the plane: use a 3D mesh)");
  PetscCheck(dim == 3 || !azimuth_set, comm, PETSC_ERR_USER_INPUT, "-drm_azimuth in 2D; allowed: only in 3D (a negative -drm_incidence_angle travels toward -x)");
  const bool angle_ok = dim == 2 ? (o->angle > -90 && o->angle < 90) : (o->angle >= 0 && o->angle < 90);
  PetscCheck(angle_ok, comm, PETSC_ERR_USER_INPUT, "-drm_incidence_angle = %g; allowed: %s [deg]", (double)o->angle, dim == 2 ? "-90 < angle < 90" : "0 <= angle < 90");
  if (file_set && file[0]) {
    PetscCheck(!(wave_set || angle_set || azimuth_set || d->incident.active()), comm, PETSC_ERR_USER_INPUT,
               "-drm_free_field_file = %s with a plane-wave option (-drm_wave, -drm_incidence_angle, -drm_azimuth, -drm_stf); allowed: one of the two free fields", file);
    o->file = file;
  } else
    PetscCheck(d->incident.active(), comm, PETSC_ERR_USER_INPUT,
               "-input_method drm needs the incident wave's velocity history; allowed: -drm_stf ricker, gabor or record (or -drm_free_field_file)");
  if (box_set) o->box.assign(box, box + nbox);
  for (const char *s = regions; regions_set && *s;) {
    const char *e = s;
    while (*e && *e != ',') ++e;
    o->regions.emplace_back(s, e);
    s = *e ? e + 1 : e;
  }
  PetscFunctionReturn(0);
}

// The interior, the layer and the forces are made of the bulk operator's elements (degree 1:
// the cells; degree p > 1: the spectral elements, with all their GLL nodes), so that the
// forces are rows of the very operator the solver applies.
void elementBounds(const fem::BulkOperator &bulk, PetscInt e, double lo[3], double hi[3]) {
  const PetscInt dim = bulk.dimension();
  for (int i = 0; i < 3; ++i) lo[i] = 1e300, hi[i] = -1e300;
  for (PetscInt a = 0; a < bulk.nodesPerElement(); ++a)
    for (PetscInt i = 0; i < dim; ++i) {
      lo[i] = std::min(lo[i], bulk.elementCoordinates(e)[a * dim + i]);
      hi[i] = std::max(hi[i], bulk.elementCoordinates(e)[a * dim + i]);
    }
}

// Global bounding box of the mesh's nodes, through the elements' coordinates.
PetscErrorCode boundingBox(MPI_Comm comm, const fem::BulkOperator &bulk, double lo[3], double hi[3]) {
  PetscFunctionBeginUser;
  for (int i = 0; i < 3; ++i) lo[i] = 1e300, hi[i] = -1e300;
  for (PetscInt e = 0; e < bulk.elementCount(); ++e) {
    double clo[3], chi[3];
    elementBounds(bulk, e, clo, chi);
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], clo[i]), hi[i] = std::max(hi[i], chi[i]);
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, lo, 3, MPI_DOUBLE, MPI_MIN, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, hi, 3, MPI_DOUBLE, MPI_MAX, comm));
  PetscFunctionReturn(0);
}

// Where the vertical line through the horizontal point x0 crosses cell c: the extremes of its
// crossings with the cell's edges (2D) or faces (3D, triangles; a hexahedron's faces split in
// two), exact for convex cells. False when the line misses the cell or only touches it.
bool verticalCrossing(const fem::BulkOperator &bulk, PetscInt c, const double *x0, double *lo, double *hi) {
  const PetscInt dim = bulk.dimension(), nen = bulk.nodesPerCell();
  const double  *X   = bulk.cellCoordinates(c);
  *lo = 1e300, *hi = -1e300;
  auto take = [&](double v) { *lo = std::min(*lo, v), *hi = std::max(*hi, v); };
  if (dim == 2) {
    for (PetscInt a = 0; a < nen; ++a) {
      const double *p = &X[a * 2], *q = &X[((a + 1) % nen) * 2];
      if (p[0] == q[0] || (x0[0] - p[0]) * (x0[0] - q[0]) > 0) continue;
      take(p[1] + (q[1] - p[1]) * (x0[0] - p[0]) / (q[0] - p[0]));
    }
  } else {
    static const int kTet[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
    static const int kHex[12][3] = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    const int (*tri)[3] = nen == 4 ? kTet : kHex;
    for (int f = 0; f < (nen == 4 ? 4 : 12); ++f) {
      const double *A = &X[tri[f][0] * 3], *B = &X[tri[f][1] * 3], *C = &X[tri[f][2] * 3];
      // Barycentric coordinates of x0 in the triangle's horizontal projection.
      const double det = (B[0] - A[0]) * (C[1] - A[1]) - (C[0] - A[0]) * (B[1] - A[1]);
      if (std::fabs(det) < 1e-300) continue;
      const double l1 = ((x0[0] - A[0]) * (C[1] - A[1]) - (C[0] - A[0]) * (x0[1] - A[1])) / det;
      const double l2 = ((B[0] - A[0]) * (x0[1] - A[1]) - (x0[0] - A[0]) * (B[1] - A[1])) / det;
      if (l1 < 0 || l2 < 0 || l1 + l2 > 1) continue;
      take(A[2] + l1 * (B[2] - A[2]) + l2 * (C[2] - A[2]));
    }
  }
  return *hi > *lo;
}

// Regions a and b are one site medium: the same material and damping (a constant-Q region's
// element moduli also depend on its own reference frequency, through its unrelaxed factor).
bool sameMedium(const DrmSetting &m, PetscInt a, PetscInt b) {
  const physics::ElasticMaterial &x = m.materials[a].elastic, &y = m.materials[b].elastic;
  const bool same_q = !m.attenuation || (m.materials[a].damping_ratio == m.materials[b].damping_ratio && m.attenuation->region_factor[a] == m.attenuation->region_factor[b]);
  const bool same_fluid = !m.pore_fluid || ((*m.pore_fluid)[a].alpha == (*m.pore_fluid)[b].alpha && (*m.pore_fluid)[a].M == (*m.pore_fluid)[b].M);
  return x.rho == y.rho && x.vp == y.vp && x.vs == y.vs && same_q && same_fluid;
}

// How the discrete model damps region r: the global Rayleigh coefficients and the region's
// fitted constant-Q body with the factor on its element moduli.
physics::MediumDamping regionDamping(const DrmSetting &m, PetscInt r) {
  physics::MediumDamping d;
  d.rayleigh = m.rayleigh;
  if (m.attenuation) {
    d.constant_q       = m.attenuation->region_models[r];
    d.unrelaxed_factor = m.attenuation->region_factor[r];
  }
  return d;
}

// The layered site the mesh holds: the cells crossed by the vertical line through the
// horizontal point lo + h/100 (the mesh's first column), gathered from every rank, sorted by
// depth, equal neighbours merged. Returns the materials by region index, and in *surface
// (given: the mesh's top) the top of that column: the site's free surface, below the mesh's
// top where a structure stands on the ground (the default scene's block).
PetscErrorCode siteFromMesh(MPI_Comm comm, const DrmSetting &m, double *surface, const double lo[3], double h, physics::LayeredSite *site,
                            std::vector<PetscInt> *site_regions) {
  const fem::BulkOperator &bulk = m.bulk;
  const double             x0[2] = {lo[0] + h / 100, lo[1] + h / 100};
  std::vector<double>      mine; // top depth, bottom depth, region
  PetscFunctionBeginUser;
  for (PetscInt c = 0; c < bulk.cellCount(); ++c) {
    double zlo, zhi;
    if (verticalCrossing(bulk, c, x0, &zlo, &zhi)) mine.insert(mine.end(), {*surface - zhi, *surface - zlo, (double)bulk.cellRegion(c)});
  }
  PetscMPIInt size, n = (PetscMPIInt)mine.size();
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<PetscMPIInt> counts(size), displs(size, 0);
  PetscCallMPI(MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  for (PetscMPIInt r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<double> all(displs[size - 1] + counts[size - 1]);
  PetscCallMPI(MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, comm));
  std::vector<std::array<double, 3>> column;
  for (size_t i = 0; i < all.size(); i += 3) column.push_back({all[i], all[i + 1], all[i + 2]});
  std::sort(column.begin(), column.end());
  PetscCheck(!column.empty(), comm, PETSC_ERR_PLIB, "DRM: no cell found in the mesh's first column");
  const double top = column.front()[0];
  for (auto &cell : column) cell[0] -= top, cell[1] -= top;
  *surface -= top;
  std::vector<double> tops;
  site_regions->clear();
  double bottom = 0;
  for (const auto &cell : column) {
    PetscCheck(std::fabs(cell[0] - bottom) <= 1e-6 * h, comm, PETSC_ERR_USER_INPUT,
               "-input_method drm: the mesh's first column has a gap or overlap at depth %g m; the free-field site must be horizontally layered", bottom);
    bottom = cell[1];
    const auto region = (PetscInt)cell[2];
    if (site_regions->empty() || !sameMedium(m, site_regions->back(), region)) {
      site_regions->push_back(region);
      tops.push_back(cell[0]);
    }
  }
  *site = physics::LayeredSite{};
  for (size_t j = 0; j < site_regions->size(); ++j) {
    // A saturated layer carries the undrained wave: its P modulus holds alpha^2 M.
    site->materials.push_back(medium::boundaryElastic(m.materials[(*site_regions)[j]]));
    site->damping.push_back(regionDamping(m, (*site_regions)[j]));
    if (j + 1 < site_regions->size()) site->thickness.push_back(tops[j + 1] - tops[j]);
  }
  PetscFunctionReturn(0);
}

// Index of the site medium at depth z (the half-space below the last interface).
size_t mediumAt(const physics::LayeredSite &site, double z) {
  size_t j = 0;
  for (double top = 0; j < site.thickness.size() && z > top + site.thickness[j]; ++j) top += site.thickness[j];
  return j;
}

// global = the sum over the ranks of what fill writes into the zeroed local (ghosted) array.
PetscErrorCode sumOverRanks(DM dm, Vec local, Vec global, const std::function<void(PetscScalar *)> &fill) {
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(local));
  PetscCall(VecGetArray(local, &a));
  fill(a);
  PetscCall(VecRestoreArray(local, &a));
  PetscCall(VecZeroEntries(global));
  PetscCall(DMLocalToGlobal(dm, local, ADD_VALUES, global));
  PetscFunctionReturn(0);
}

// Omega (interior) flags per local element; the b nodes (in Omega and in an exterior element,
// on any rank) as a ghosted local array with 1 on them. h_element, the smallest element's size,
// is the unit of -drm_offset. At degree p > 1 a GLL node is a b node exactly when it lies on a
// face between Omega and the exterior: a layer element's other GLL nodes are e nodes.
PetscErrorCode classify(const DrmSetting &m, const DrmOptions &o, const double lo[3], const double hi[3], double h_element, std::vector<char> *interior,
                        std::vector<double> *b_flag) {
  const fem::BulkOperator &bulk = m.bulk;
  const PetscInt           dim  = m.dim, nen = bulk.nodesPerElement();
  PetscFunctionBeginUser;
  std::vector<PetscInt> regions;
  for (const std::string &name : o.regions) {
    const auto it = std::find(m.regions.begin(), m.regions.end(), name);
    PetscCheck(it != m.regions.end(), m.comm, PETSC_ERR_USER_INPUT, "-drm_regions names '%s'; allowed: regions of the mesh", name.c_str());
    regions.push_back((PetscInt)(it - m.regions.begin()));
  }
  // Box: [xmin, xmax] x [ymin, ymax] horizontally (2D: x only) and above zmin.
  double blo[3], bhi[3];
  for (PetscInt i = 0; i < dim; ++i) blo[i] = lo[i] + o.offset * h_element, bhi[i] = hi[i] - o.offset * h_element;
  bhi[dim - 1] = 1e300;
  if (!o.box.empty()) {
    for (PetscInt i = 0; i + 1 < dim; ++i) blo[i] = o.box[2 * i], bhi[i] = o.box[2 * i + 1];
    blo[dim - 1] = o.box[2 * (dim - 1)];
  }
  interior->assign(bulk.elementCount(), 0);
  for (PetscInt e = 0; e < bulk.elementCount(); ++e) {
    if (!o.regions.empty()) {
      (*interior)[e] = std::find(regions.begin(), regions.end(), bulk.elementRegion(e)) != regions.end();
      continue;
    }
    // The centroid as the mean of the element's nodes: at p > 1 the GLL nodes lie symmetric
    // about the reference centre, so on the mesh's Q1 map it is the mean of the corners.
    bool in = true;
    for (PetscInt i = 0; i < dim; ++i) {
      double x = 0;
      for (PetscInt a = 0; a < nen; ++a) x += bulk.elementCoordinates(e)[a * dim + i] / nen;
      in = in && blo[i] <= x && x <= bhi[i];
    }
    (*interior)[e] = in;
  }
  // Component 0 counts interior elements at a node, component 1 exterior ones.
  Vec          local, global;
  PetscScalar *a;
  PetscCall(DMGetLocalVector(m.dm, &local));
  PetscCall(DMGetGlobalVector(m.dm, &global));
  PetscCall(sumOverRanks(m.dm, local, global, [&](PetscScalar *v) {
    for (PetscInt e = 0; e < bulk.elementCount(); ++e)
      for (PetscInt k = 0; k < nen; ++k) v[bulk.elementNodeOffset(e, k) + ((*interior)[e] ? 0 : 1)] += 1;
  }));
  PetscCall(DMGlobalToLocal(m.dm, global, INSERT_VALUES, local));
  PetscInt n;
  PetscCall(VecGetLocalSize(local, &n));
  b_flag->assign(n, 0.0);
  PetscCall(VecGetArray(local, &a));
  for (PetscInt i = 0; i < n; i += dim) (*b_flag)[i] = PetscRealPart(a[i]) > 0 && PetscRealPart(a[i + 1]) > 0;
  PetscCall(VecRestoreArray(local, &a));
  PetscCall(DMRestoreGlobalVector(m.dm, &global));
  PetscCall(DMRestoreLocalVector(m.dm, &local));
  PetscFunctionReturn(0);
}

// The layer: this rank's exterior elements with a b node, their nodes (coordinates, radial
// coordinate in node_delay for now, depth), and the global counts and extremes. With a site
// (the plane wave) every layer element must hold the site's material and damping at its depth.
PetscErrorCode collectLayer(const DrmSetting &m, Drm *d, const std::vector<char> &interior, const std::vector<double> &b_flag, const physics::LayeredSite *site,
                            const std::vector<PetscInt> &site_regions, PetscInt counts[3], double *deepest_out) {
  const MPI_Comm comm = m.comm;
  const PetscInt dim = m.dim, vert = dim - 1, nen = m.bulk.nodesPerElement();
  PetscFunctionBeginUser;
  std::vector<PetscInt> node_of_offset(b_flag.size(), -1);
  double                deepest = 0, radial_min = 1e300;
  double                foreign_depth = -1;      // deepest layer element whose material is not the site's there
  for (PetscInt e = 0; e < m.bulk.elementCount(); ++e) {
    if (interior[e]) continue;
    bool touches = false;
    for (PetscInt a = 0; a < nen; ++a) touches = touches || b_flag[m.bulk.elementNodeOffset(e, a)] > 0;
    if (!touches) continue;
    double clo[3], chi[3];
    elementBounds(m.bulk, e, clo, chi);
    const double                   zc   = d->surface - 0.5 * (clo[vert] + chi[vert]);
    if (site && !sameMedium(m, site_regions[mediumAt(*site, zc)], m.bulk.elementRegion(e))) foreign_depth = std::max(foreign_depth, zc);
    d->elements.push_back(e);
    ++counts[0];
    for (PetscInt a = 0; a < nen; ++a) {
      const PetscInt off = m.bulk.elementNodeOffset(e, a);
      if (node_of_offset[off] < 0) {
        node_of_offset[off] = (PetscInt)d->node_offset.size();
        d->node_offset.push_back(off);
        const double *x = &m.bulk.elementCoordinates(e)[a * dim];
        d->node_coords.insert(d->node_coords.end(), x, x + dim);
        double        xi = 0;
        for (PetscInt i = 0; i < vert; ++i) xi += x[i] * d->radial[i];
        d->node_delay.push_back(xi); // the radial coordinate for now
        radial_min = std::min(radial_min, xi);
        deepest    = std::max(deepest, d->surface - x[vert]);
        d->depths.push_back(d->surface - x[vert]);
      }
      d->element_node.push_back((size_t)node_of_offset[off]);
      d->element_node_is_b.push_back(b_flag[off] > 0);
    }
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &radial_min, 1, MPI_DOUBLE, MPI_MIN, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &deepest, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, counts, 1, MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &foreign_depth, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscCheck(foreign_depth < 0, comm, PETSC_ERR_USER_INPUT,
             "-input_method drm: a DRM layer element at depth %g m has a material or damping other than the free-field site's there (the mesh's first column); allowed: a layer "
             "in the horizontally layered soil, away from the structure",
             foreign_depth);
  PetscCheck(counts[0] > 0, comm, PETSC_ERR_USER_INPUT, "-input_method drm: the DRM layer is empty (no element outside the interior touches it); check -drm_box / -drm_regions");
  d->radial_min = radial_min;
  *deepest_out  = deepest;
  PetscFunctionReturn(0);
}

// Distinct depths of the DRM nodes (one history each); each node keeps the index of its own
// and turns its radial coordinate into its delay p (xi - xi_ref).
void indexDepths(Drm *d, double h) {
  std::vector<double> node_z = d->depths;
  std::sort(d->depths.begin(), d->depths.end());
  d->depths.erase(std::unique(d->depths.begin(), d->depths.end(), [h](double a, double b) { return std::fabs(a - b) <= 1e-9 * h; }), d->depths.end());
  for (size_t k = 0; k < node_z.size(); ++k) {
    d->node_depth.push_back((size_t)(std::lower_bound(d->depths.begin(), d->depths.end(), node_z[k] - 1e-9 * h) - d->depths.begin()));
    d->node_delay[k] = d->field.horizontalSlowness() * (d->node_delay[k] - d->radial_min);
  }
}

// The numbers of b and e nodes, each counted once (owned nodes only) through a global vector.
PetscErrorCode countNodes(const DrmSetting &m, const Drm *d, const std::vector<double> &b_flag, PetscInt counts[2]) {
  const PetscInt dim = m.dim;
  PetscFunctionBeginUser;
  Vec local, global;
  PetscCall(DMGetLocalVector(m.dm, &local));
  PetscCall(DMGetGlobalVector(m.dm, &global));
  PetscCall(sumOverRanks(m.dm, local, global, [&](PetscScalar *v) {
    for (size_t k = 0; k < d->node_offset.size(); ++k) v[d->node_offset[k] + (b_flag[d->node_offset[k]] > 0 ? 0 : 1)] = 1;
  }));
  PetscInt           n;
  const PetscScalar *g;
  PetscCall(VecGetLocalSize(global, &n));
  PetscCall(VecGetArrayRead(global, &g));
  for (PetscInt i = 0; i < n; i += dim) counts[0] += PetscRealPart(g[i]) > 0, counts[1] += PetscRealPart(g[i + 1]) > 0;
  PetscCall(VecRestoreArrayRead(global, &g));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, counts, 2, MPIU_INT, MPI_SUM, m.comm));
  PetscCall(DMRestoreGlobalVector(m.dm, &global));
  PetscCall(DMRestoreLocalVector(m.dm, &local));
  PetscFunctionReturn(0);
}

// The damped forces' state: zero memory, the free field at rest.
void setupDamping(const DrmSetting &m, Drm *d) {
  const size_t rows = d->elements.size() * m.bulk.nodesPerElement() * m.dim;
  d->beta           = m.rayleigh.beta;
  if (m.attenuation) {
    d->omega = m.attenuation->omega;
    for (PetscInt e : d->elements) {
      const std::vector<double> &y = m.attenuation->region_models[m.bulk.elementRegion(e)].weight;
      if (y.empty()) d->element_weight.insert(d->element_weight.end(), d->omega.size(), 0.0); // an elastic region's element
      else d->element_weight.insert(d->element_weight.end(), y.begin(), y.end());
    }
  }
  d->u0_committed.assign(d->u0.size(), 0.0);
  d->v0.assign(d->u0.size(), 0.0);
  d->memory_committed.assign(rows * d->omega.size(), 0.0);
  d->memory_trial = d->memory_committed;
  d->drive_committed.assign(d->omega.empty() ? 0 : rows, 0.0);
  d->drive_trial = d->drive_committed;
}

// Saturated sites: refuses what the undrained free field cannot carry (before the layer is
// built); setupPoreFluid keeps each layer element's undrained medium (lambda_u, mu, alpha, M;
// zeros in a dry element).
PetscErrorCode checkPoreFluid(const DrmSetting &m, const DrmOptions &o, Drm *d) {
  PetscFunctionBeginUser;
  if (!m.pore_fluid) PetscFunctionReturn(0);
  for (const DrmPoreFluid &f : *m.pore_fluid) d->saturated = d->saturated || f.M > 0;
  if (!d->saturated) PetscFunctionReturn(0);
  // The u-p layer terms (porous/pore_pressure_drm.cpp) use the pore pressure's stored cell
  // matrices, which exist at degree 1 only.
  PetscCheck(m.bulk.degree() == 1, m.comm, PETSC_ERR_USER_INPUT,
             "-element_degree = %" PetscInt_FMT " with -input_method drm and a saturated region: not supported yet; allowed: -element_degree 1", m.bulk.degree());
  PetscCheck(o.file.empty(), m.comm, PETSC_ERR_USER_INPUT,
             "-drm_free_field_file = %s with a saturated region (-material_<r>_saturated): not supported (the file has no pore pressure); allowed: the plane wave (-drm_wave, -drm_stf)",
             o.file.c_str());
  // The solver damps the skeleton only (beta K, its constant-Q memory), not the fluid's
  // alpha^2 M, so the damped site's complex undrained modulus is not (lambda + alpha^2 M)(1 + i w beta).
  PetscCheck(m.rayleigh.alpha == 0 && m.rayleigh.beta == 0, m.comm, PETSC_ERR_USER_INPUT,
             "-damping_ratio > 0 (Rayleigh alpha %g 1/s, beta %g s) with -input_method drm and a saturated region: not supported yet; allowed: -damping_ratio 0", m.rayleigh.alpha,
             m.rayleigh.beta);
  for (size_t r = 0; r < m.materials.size(); ++r)
    PetscCheck((*m.pore_fluid)[r].M == 0 || m.materials[r].damping_ratio == 0, m.comm, PETSC_ERR_USER_INPUT,
               "-material_%s_damping_ratio = %g with -material_%s_saturated and -input_method drm: not supported yet; allowed: 0 in saturated regions", m.materials[r].region.c_str(),
               m.materials[r].damping_ratio, m.materials[r].region.c_str());
  PetscFunctionReturn(0);
}

void setupPoreFluid(const DrmSetting &m, Drm *d) {
  if (!d->saturated) return;
  for (PetscInt e : d->elements) {
    const PetscInt            r = m.bulk.elementRegion(e);
    const DrmPoreFluid        f = (*m.pore_fluid)[r];
    const physics::LameParameters lm = physics::lame(medium::boundaryElastic(m.materials[r]));
    if (f.M > 0) d->element_fluid.insert(d->element_fluid.end(), {lm.lambda, lm.mu, f.alpha, f.M});
    else d->element_fluid.insert(d->element_fluid.end(), 4, 0.0);
  }
  d->p0.assign(d->elements.size() * m.bulk.nodesPerElement(), 0.0);
}

// The run report's lines: the wave (or the file), the layer, the site.
PetscErrorCode report(const DrmSetting &m, Drm *d, const DrmOptions &o, const PetscInt counts[3], const physics::LayeredSite &site,
                      const std::vector<PetscInt> &site_regions) {
  const PetscInt dim = m.dim;
  char           buf[400];
  PetscFunctionBeginUser;
  if (!d->file.empty()) {
    std::snprintf(buf, sizeof buf, "  input: Domain Reduction Method, free field from %s: %zu samples every %g s from %g s", d->file.c_str(), d->file_histories.samples,
                  d->file_histories.dt, d->file_histories.t0);
    d->report.push_back(buf);
    std::snprintf(buf, sizeof buf, "    DRM layer: %" PetscInt_FMT " elements, %" PetscInt_FMT " boundary (b) and %" PetscInt_FMT " exterior (e) nodes", counts[0], counts[1],
                  counts[2]);
    d->report.push_back(buf);
    PetscFunctionReturn(0);
  }
  char direction[64];
  if (dim == 3) std::snprintf(direction, sizeof direction, ", azimuth %g deg", d->azimuth);
  else std::snprintf(direction, sizeof direction, ", toward %sx", d->azimuth == 0 ? "+" : "-");
  std::snprintf(buf, sizeof buf, "  input: Domain Reduction Method, %s wave at %g deg from the vertical%s, p = %.4g s/m; %s", kWaves[o.wave], d->angle, direction,
                d->field.horizontalSlowness(), d->incident.describe().c_str());
  d->report.push_back(buf);
  std::snprintf(buf, sizeof buf, "    DRM layer: %" PetscInt_FMT " elements, %" PetscInt_FMT " boundary (b) and %" PetscInt_FMT " exterior (e) nodes; the wave's reference point: depth %g m, %s = %g m",
                counts[0], counts[1], counts[2], d->reference_depth, dim == 2 ? "x" : "radial coordinate", d->radial_min);
  d->report.push_back(buf);
  std::string layers;
  for (size_t j = 0; j < site.materials.size(); ++j) {
    char one[200], q[64] = "";
    const auto &mat = site.materials[j];
    const double xi = m.materials[site_regions[j]].damping_ratio;
    if (xi > 0) std::snprintf(q, sizeof q, ", constant Q xi %g %%", 100 * xi);
    if (j < site.thickness.size())
      std::snprintf(one, sizeof one, "%s%g m of '%s' (vs %g%s)", j ? ", " : "", site.thickness[j], m.regions[site_regions[j]].c_str(), mat.vs, q);
    else
      std::snprintf(one, sizeof one, "%shalf-space '%s' (vp %g, vs %g%s)", j ? " on " : "", m.regions[site_regions[j]].c_str(), mat.vp, mat.vs, q);
    layers += one;
  }
  d->report.push_back("    DRM free-field site (the mesh's first column): " + layers);
  if (d->saturated)
    d->report.push_back("    DRM on a saturated site: the undrained free field (vp of a saturated layer is its undrained one, p0 = -alpha M eps_v), the forces of the u-p operator (docs/drm.md)");
  if (m.rayleigh.alpha > 0 || m.rayleigh.beta > 0 || m.attenuation)
    d->report.push_back("    DRM damped as the model: the free field with complex moduli per frequency, the forces with the layer's damping terms (docs/drm.md)");
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode DrmCreate(const DrmSetting &m, Drm **out) {
  const MPI_Comm comm = m.comm;
  const PetscInt dim = m.dim, vert = dim - 1;
  auto          *d = new Drm;
  DrmOptions     o;
  bool           use = false;
  PetscFunctionBeginUser;
  *out = nullptr;
  PetscCall(readOptions(comm, dim, d, &o, &use));
  if (!use) {
    delete d;
    PetscFunctionReturn(0);
  }
  PetscCheck(m.input_wave == InputWave::None, comm, PETSC_ERR_USER_INPUT,
             "-input_wave = %s with -input_method drm; allowed: -input_wave none (DRM brings the wave in through its layer, -drm_wave)", inputWaveName(m.input_wave));
  PetscCall(checkPoreFluid(m, o, d));
  d->wave    = (physics::PlaneWaveType)o.wave;
  d->angle   = std::fabs(o.angle);
  d->azimuth = dim == 2 ? (o.angle < 0 ? 180 : 0) : o.azimuth;
  const double az = d->azimuth * M_PI / 180;
  d->radial[0] = std::cos(az), d->radial[1] = dim == 3 ? std::sin(az) : 0;
  d->transverse[0] = -std::sin(az), d->transverse[1] = std::cos(az);
  if (dim == 2) d->radial[1] = 0, d->radial[0] = std::round(d->radial[0]);

  double lo[3], hi[3];
  PetscCall(boundingBox(comm, m.bulk, lo, hi));
  d->surface     = hi[vert];
  const double h = m.bulk.minCellSize();
  d->file       = o.file;
  const bool plane = d->file.empty();
  physics::LayeredSite  site;
  std::vector<PetscInt> site_regions;
  if (plane) {
    PetscCall(siteFromMesh(comm, m, &d->surface, lo, h, &site, &site_regions));
    const std::string problem = d->field.setup(site, d->wave, d->angle);
    PetscCheck(problem.empty(), comm, PETSC_ERR_USER_INPUT, "-input_method drm: %s", problem.c_str());
  }

  std::vector<char>   interior;
  std::vector<double> b_flag;
  PetscCall(classify(m, o, lo, hi, m.bulk.minElementSize(), &interior, &b_flag));
  PetscInt counts[3] = {0, 0, 0}; // layer elements, b nodes, e nodes
  double   deepest;
  PetscCall(collectLayer(m, d, interior, b_flag, plane ? &site : nullptr, site_regions, counts, &deepest));
  d->reference_depth = plane ? std::max(deepest, d->field.halfspaceDepth()) : 0;
  indexDepths(d, h);
  d->u0.assign(dim * d->node_offset.size(), 0.0);
  // Coordinates written by another code carry its rounding: 1e-3 of a cell matches them.
  if (!plane) PetscCall(FieldFileRead(comm, "-drm_free_field_file", d->file, (int)dim, d->node_coords, 1e-3 * h, &d->file_histories));
  PetscCall(DMCreateLocalVector(m.dm, &d->f_local));
  PetscCall(DMCreateGlobalVector(m.dm, &d->f_global));

  PetscCall(countNodes(m, d, b_flag, &counts[1]));
  setupDamping(m, d);
  setupPoreFluid(m, d);
  PetscCall(report(m, d, o, counts, site, site_regions));
  *out = d;
  PetscFunctionReturn(0);
}

PetscErrorCode DrmDestroy(Drm **d) {
  PetscFunctionBeginUser;
  if (!*d) PetscFunctionReturn(0);
  PetscCall(VecDestroy(&(*d)->f_local));
  PetscCall(VecDestroy(&(*d)->f_global));
  delete *d;
  *d = nullptr;
  PetscFunctionReturn(0);
}

namespace {

// Samples the incident velocity to the TS's final time at 40 per period of its top frequency
// (the Hermite interpolation in time is then accurate to ~1e-7), but no finer than the time
// step: a record's top frequency is its Nyquist frequency, far above what the mesh carries, and
// its 40 samples per period would cost memory for nothing.
PetscErrorCode synthesize(Drm *d, TS ts) {
  PetscReal t_end, step;
  PetscFunctionBeginUser;
  PetscCall(TSGetMaxTime(ts, &t_end));
  PetscCall(TSGetTimeStep(ts, &step));
  const double f_top = d->incident.topFrequency();
  const double dt    = std::min(t_end / 64, std::max(f_top > 0 ? 1 / (40 * f_top) : t_end / 64, (double)step));
  const size_t m     = (size_t)std::ceil(t_end / dt) + 2;
  std::vector<double> v_in(m);
  for (size_t k = 0; k < m; ++k) v_in[k] = d->incident.velocity(k * dt);
  d->histories   = physics::synthesizeHistories(d->field, d->depths, d->reference_depth, v_in, dt, d->saturated);
  d->synthesized = true;
  PetscFunctionReturn(0);
}

// u0 of the plane wave at every DRM node: its depth's history at t - p (xi - xi_ref), in mesh axes.
void planeWaveDisplacements(Drm *d, PetscInt dim, double t) {
  for (size_t k = 0; k < d->node_offset.size(); ++k) {
    double u[3];
    for (size_t c = 0; c < 3; ++c) u[c] = physics::planeWaveDisplacementAt(d->histories, d->node_depth[k], c, t - d->node_delay[k]);
    for (PetscInt i = 0; i < dim; ++i) d->u0[dim * k + i] = u[0] * d->radial[i] + u[1] * d->transverse[i];
    d->u0[dim * k + dim - 1] += u[2];
  }
}

// p0 of the undrained plane wave at every node of the layer's saturated elements, each with its
// element's medium (sigma_zz and eps_xx are continuous across the layers, eps_v is not).
void undrainedPressures(Drm *d, PetscInt nen, double t) {
  for (size_t ei = 0; ei < d->elements.size(); ++ei) {
    const double *f = &d->element_fluid[4 * ei];
    for (PetscInt a = 0; a < nen; ++a) {
      const size_t k = d->element_node[ei * nen + a];
      const double s = physics::planeWaveDisplacementAt(d->histories, d->node_depth[k], 3, t - d->node_delay[k]);
      const double e = physics::planeWaveDisplacementAt(d->histories, d->node_depth[k], 4, t - d->node_delay[k]);
      d->p0[ei * nen + a] = f[3] > 0 ? physics::undrainedPlaneWavePressure(s, e, f[0], f[1], f[2], f[3]) : 0.0;
    }
  }
}

} // namespace

PetscErrorCode DrmFreeFieldUpdate(Drm *d, const DrmSetting &m, TS ts, PetscReal t) {
  const PetscInt dim = m.dim;
  PetscFunctionBeginUser;
  if (d->field_valid && d->field_time == t) PetscFunctionReturn(0);
  if (!d->file.empty()) {
    for (size_t k = 0; k < d->node_offset.size(); ++k)
      for (PetscInt i = 0; i < dim; ++i) d->u0[dim * k + i] = FieldFileDisplacement(d->file_histories, k, (int)i, t);
  } else {
    if (!d->synthesized) PetscCall(synthesize(d, ts));
    planeWaveDisplacements(d, dim, t);
    if (d->saturated) undrainedPressures(d, m.bulk.nodesPerElement(), t);
  }
  d->field_time  = t;
  d->field_valid = true;
  PetscFunctionReturn(0);
}

DrmLayer DrmLayerOf(const Drm *d) { return {d->elements, d->element_node, d->element_node_is_b, d->u0, d->p0, d->field_time}; }

bool DrmSaturated(const Drm *d) { return d && d->saturated; }

PetscErrorCode DrmAddForce(Drm *d, const DrmSetting &m, TS ts, PetscReal t, Vec f) {
  constexpr int  kMaxMechanisms = 8;
  const PetscInt dim = m.dim, nen = m.bulk.nodesPerElement(), nd = nen * dim;
  const size_t   L = d->omega.size();
  PetscFunctionBeginUser;
  // Before the first commit the trial starts at t (a zero interval), like the solver's memory.
  const double t_committed = d->started ? d->committed_time : t;
  PetscCheck(t >= t_committed, PETSC_COMM_SELF, PETSC_ERR_ORDER, "DRM: force asked at t = %g s, before the committed state at %g s", (double)t, t_committed);
  d->trial_time = t;
  d->has_trial  = true;
  PetscCall(DrmFreeFieldUpdate(d, m, ts, t));
  // The solver's stiffness-proportional damping uses v_{n+1/2} = (u_{n+1} - u_n)/h, so the free
  // field's is the same difference of u0; at the first call (t_0, where the solver uses v_0)
  // the free field is at rest.
  if (d->beta > 0)
    for (size_t k = 0; k < d->u0.size(); ++k) d->v0[k] = t > t_committed ? (d->u0[k] - d->u0_committed[k]) / (t - t_committed) : 0.0;
  physics::MemoryUpdate upd[kMaxMechanisms];
  for (size_t l = 0; l < L; ++l) upd[l] = physics::memoryUpdate(d->omega[l], t - t_committed);
  // A layer element's rows: K applied to u0 on its e nodes alone (zero on its b nodes) is
  // K_be u0_e on its b rows, and applied to u0 on its b nodes alone, K_eb u0_b on its e rows.
  // Each is one product of the solver's own element operator (degree > 1 its sum-factorised
  // kernel: cheaper than a stored element matrix, docs/drm.md), and two more give K v0.
  d->scratch.resize(5 * (size_t)nd);
  double *part = d->scratch.data();                              // u0 or v0 on one side's nodes
  double *ku[2] = {part + nd, part + 2 * nd}, *kv[2] = {part + 3 * nd, part + 4 * nd}; // [0]: of the e part, [1]: of the b part
  PetscScalar *fl;
  PetscCall(VecZeroEntries(d->f_local));
  PetscCall(VecGetArray(d->f_local, &fl));
  for (size_t ei = 0; ei < d->elements.size(); ++ei) {
    const PetscInt e     = d->elements[ei];
    const size_t  *nodes = &d->element_node[ei * nen];
    const char    *is_b  = &d->element_node_is_b[ei * nen];
    auto product = [&](const std::vector<double> &field, bool b_side, double *out) {
      for (PetscInt a = 0; a < nen; ++a)
        for (PetscInt i = 0; i < dim; ++i) part[a * dim + i] = (is_b[a] != 0) == b_side ? field[dim * nodes[a] + i] : 0.0;
      m.bulk.elementStiffnessTimes(e, part, out);
    };
    for (int side = 0; side < 2; ++side) {
      product(d->u0, side == 1, ku[side]);
      if (d->beta > 0) product(d->v0, side == 1, kv[side]);
    }
    for (PetscInt a = 0; a < nen; ++a)
      for (PetscInt i = 0; i < dim; ++i) {
        // P_b = -F_be u0_e on b rows, P_e = +F_eb u0_b on e rows, F the layer's internal force:
        // K u0 + beta K v0 - (constant-Q memory driven by K u0).
        const int     other = is_b[a] ? 0 : 1;
        const size_t  r     = a * dim + i, row = ei * nd + r;
        const double  s     = ku[other][r];
        double        force = s + (d->beta > 0 ? d->beta * kv[other][r] : 0.0);
        const double *y     = L ? &d->element_weight[ei * L] : nullptr;
        for (size_t l = 0; l < L; ++l) {
          const double z = upd[l].decay * d->memory_committed[row * L + l] + y[l] * (upd[l].end * s + upd[l].start * d->drive_committed[row]);
          d->memory_trial[row * L + l] = z;
          force -= z;
        }
        if (L) d->drive_trial[row] = s;
        fl[d->node_offset[nodes[a]] + i] += is_b[a] ? -force : force;
      }
  }
  PetscCall(VecRestoreArray(d->f_local, &fl));
  PetscCall(VecZeroEntries(d->f_global));
  PetscCall(DMLocalToGlobal(m.dm, d->f_local, ADD_VALUES, d->f_global));
  PetscCall(VecAXPY(f, 1.0, d->f_global));
  PetscFunctionReturn(0);
}

double DrmTopFrequency(const Drm *drm) { return drm->incident.topFrequency(); }

std::vector<std::string> DrmReport(const Drm *d) { return d ? d->report : std::vector<std::string>{}; }

void DrmCommit(Drm *d) {
  if (!d || !d->has_trial) return;
  d->memory_committed.swap(d->memory_trial);
  d->drive_committed.swap(d->drive_trial);
  d->u0_committed   = d->u0;
  d->started        = true;
  d->committed_time = d->trial_time;
  d->has_trial      = false;
}

std::vector<double> DrmState(const Drm *d) {
  std::vector<double> s = {d->started ? 1.0 : 0.0, d->committed_time};
  for (const std::vector<double> *x : {&d->u0_committed, &d->memory_committed, &d->drive_committed}) s.insert(s.end(), x->begin(), x->end());
  return s;
}

bool DrmSetState(Drm *d, const std::vector<double> &s) {
  if ((PetscInt)s.size() != DrmStateSize(d)) return false;
  d->started        = s[0] != 0;
  d->committed_time = s[1];
  d->has_trial      = false;
  d->field_valid    = false;
  size_t o          = 2;
  for (std::vector<double> *x : {&d->u0_committed, &d->memory_committed, &d->drive_committed}) {
    std::copy(s.begin() + o, s.begin() + o + x->size(), x->begin());
    o += x->size();
  }
  return true;
}

PetscInt DrmStateSize(const Drm *d) { return (PetscInt)(2 + d->u0_committed.size() + d->memory_committed.size() + d->drive_committed.size()); }

} // namespace slipwave::input

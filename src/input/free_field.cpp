#include "slipwave/input/free_field.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "slipwave/input/boundary_faces.hpp"
#include "slipwave/medium/attenuation.hpp"
#include "slipwave/medium/hysteresis.hpp"
#include "slipwave/mesh/spectral_layout.hpp"
#include "slipwave/mesh/vertex_coordinates.hpp"
#include "slipwave/numerics/gll_basis.hpp"
#include "slipwave/physics/absorbing_boundary.hpp"

namespace slipwave::input {
namespace {

// Height (last coordinate) of a vertex point.
PetscErrorCode vertexHeight(const mesh::VertexCoordinates &vc, PetscInt v, double *z) {
  double x[3];
  PetscFunctionBeginUser;
  PetscCall(vc.Get(v, x));
  *z = x[vc.dimension() - 1];
  PetscFunctionReturn(0);
}

bool sameMaterial(const medium::RegionMaterialInfo &a, const medium::RegionMaterialInfo &b) {
  return a.elastic.rho == b.elastic.rho && a.elastic.vp == b.elastic.vp && a.elastic.vs == b.elastic.vs && a.damping_ratio == b.damping_ratio && a.model == b.model &&
         a.hysteretic.model == b.hysteretic.model;
}

bool sameFluid(const physics::ColumnFluidSegment &a, const physics::ColumnFluidSegment &b) {
  return a.saturated == b.saturated && (!a.saturated || (a.alpha == b.alpha && a.M == b.M && a.kappa == b.kappa));
}

// The column's pore pressure: its saturated segments' Biot numbers, and at each node the main
// mesh's fluid condition at the side's nodes there (drained, p_h, the inflow's pressure rate),
// so the column's top and base drain or seal as the main mesh's do.
PetscErrorCode setColumnFluid(DM dm, const FreeFieldFluid &fluid, const std::vector<PetscInt> &segment_region, FreeFieldSide *side) {
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscInt dim;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  for (const auto &[name, condition] : fluid.fluid_boundaries)
    PetscCheck(name != side->name, comm, PETSC_ERR_USER_INPUT,
               "-bc_%s_fluid %s on a free-field side (-bc_%s_type freefield): not supported (the free field has no horizontal flow); allowed: -bc_%s_fluid noflow",
               side->name.c_str(), condition.c_str(), side->name.c_str(), side->name.c_str());
  std::vector<physics::ColumnFluidSegment> segments;
  for (PetscInt r : segment_region) segments.push_back(fluid.region[r]);
  // Per column node, from any rank with a side vertex there (all hold the same values): drained,
  // p_h, q / S; -1e300 where this rank has none (the MAX reduction takes the others').
  const int           n = side->column.nodeCount();
  std::vector<double> values(3 * n, -1e300);
  Vec                 global[4] = {fluid.storage, fluid.free_mask, fluid.p_hydrostatic, fluid.inflow}, local[4];
  const PetscScalar  *a[4];
  for (int k = 0; k < 4; ++k) {
    PetscCall(DMGetLocalVector(fluid.pdm, &local[k]));
    PetscCall(DMGlobalToLocal(fluid.pdm, global[k], INSERT_VALUES, local[k]));
    PetscCall(VecGetArrayRead(local[k], &a[k]));
  }
  for (const FreeFieldTerm &term : side->terms) {
    // Node i of the pressure layout is node i of the displacement's (fem/node_fields.hpp), so
    // a vertex's local offset there is its displacement offset over dim.
    const PetscInt i = term.offset / dim;
    const double   S = PetscRealPart(a[0][i]);
    values[3 * term.node]     = S > 0 && PetscRealPart(a[1][i]) == 0 ? 1.0 : 0.0;
    values[3 * term.node + 1] = PetscRealPart(a[2][i]);
    values[3 * term.node + 2] = S > 0 ? PetscRealPart(a[3][i]) / S : 0.0;
  }
  for (int k = 0; k < 4; ++k) {
    PetscCall(VecRestoreArrayRead(local[k], &a[k]));
    PetscCall(DMRestoreLocalVector(fluid.pdm, &local[k]));
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, values.data(), 3 * n, MPI_DOUBLE, MPI_MAX, comm));
  std::vector<physics::ColumnFluidNode> nodes(n);
  for (int i = 0; i < n; ++i) nodes[i] = {values[3 * i] > 0, values[3 * i + 1], values[3 * i + 2]};
  const std::string problem = side->column.setPorePressure(segments, nodes, fluid.rules);
  PetscCheck(problem.empty(), comm, PETSC_ERR_USER_INPUT, "-bc_%s_type freefield beside a saturated region: %s; allowed: absorbing or tied sides",
             side->name.c_str(), problem.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode buildSide(DM dm, const std::string &name, const BoundaryConditions &bc, const std::vector<medium::RegionMaterialInfo> &materials,
                         const physics::RayleighCoefficients &rayleigh, const medium::Attenuation *att, const FreeFieldFluid *fluid, double tol, FreeFieldSide *side) {
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscInt dim;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  side->name = name;
  std::vector<BoundaryFace> faces;
  PetscCall(BoundaryFacesGet(dm, name, &faces));
  mesh::VertexCoordinates vc;
  PetscCall(vc.Open(dm));
  // Faces must be vertical: the column models a vertically propagating wave seen through a
  // vertical side.
  std::vector<double> local_z;
  for (const BoundaryFace &f : faces) {
    PetscCheck(std::fabs(f.normal[dim - 1]) <= 1e-6, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
               "-bc_%s_type freefield: boundary '%s' has a face with normal (%g, %g%s) that is not horizontal; allowed: free-field boundaries on vertical sides",
               name.c_str(), name.c_str(), f.normal[0], f.normal[1], dim == 3 ? ", ..." : "");
    for (PetscInt k = 0; k < f.nvert; ++k) {
      double z = 0;
      PetscCall(vertexHeight(vc, f.vertices[k], &z));
      local_z.push_back(z);
    }
  }
  // Node heights: the union over ranks of the side's vertex heights, merged within tol.
  PetscMPIInt size, nloc = (PetscMPIInt)local_z.size();
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<PetscMPIInt> counts(size), displs(size, 0);
  PetscCallMPI(MPI_Allgather(&nloc, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  for (int r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<double> all_z(displs[size - 1] + counts[size - 1]);
  PetscCallMPI(MPI_Allgatherv(local_z.data(), nloc, MPI_DOUBLE, all_z.data(), counts.data(), displs.data(), MPI_DOUBLE, comm));
  std::sort(all_z.begin(), all_z.end());
  std::vector<double> heights;
  for (double z : all_z)
    if (heights.empty() || z - heights.back() > tol) heights.push_back(z);
  PetscCheck(heights.size() >= 2, comm, PETSC_ERR_USER_INPUT, "-bc_%s_type freefield: boundary '%s' has no vertical extent; allowed: a vertical side of the mesh",
             name.c_str(), name.c_str());
  const int nseg = (int)heights.size() - 1;

  // Each face spans exactly one segment; its region gives the segment's material.
  physics::FreeFieldColumn probe; // for findNode on the heights
  {
    std::vector<physics::ElasticMaterial> dummy(nseg, materials[0].elastic);
    const std::string problem = probe.setup((int)dim, heights, dummy, 0, 0);
    PetscCheck(problem.empty(), comm, PETSC_ERR_PLIB, "free-field column of '%s': %s", name.c_str(), problem.c_str());
  }
  std::vector<PetscInt> seg_min(nseg, PETSC_MAX_INT), seg_max(nseg, -1);
  PetscSection          s;
  PetscCall(DMGetLocalSection(dm, &s));
  for (const BoundaryFace &f : faces) {
    int    lo = INT32_MAX, hi = -1;
    int    nodes[4];
    double x[numerics::kMaxFaceNodes * 3];
    for (PetscInt k = 0; k < f.nvert; ++k) {
      PetscCall(vc.Get(f.vertices[k], &x[k * dim]));
      const double z = x[k * dim + dim - 1];
      nodes[k]       = probe.findNode(z, tol);
      PetscCheck(nodes[k] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "free-field side '%s': vertex at height %g has no column node", name.c_str(), z);
      lo = std::min(lo, nodes[k]);
      hi = std::max(hi, nodes[k]);
    }
    PetscCheck(hi == lo + 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
               "-bc_%s_type freefield: a face of '%s' spans heights %g to %g, which holds %d other node height(s) of the side; allowed: a side whose nodes lie on "
               "common heights (layers of cells, e.g. a box mesh or a Gmsh mesh with the same vertical spacing along the side)",
               name.c_str(), name.c_str(), heights[lo], heights[hi], std::max(hi - lo - 1, 0));
    seg_min[lo] = std::min(seg_min[lo], f.region);
    seg_max[lo] = std::max(seg_max[lo], f.region);
    // The face integral of the pore pressure against each vertex's shape function
    // (FreeFieldColumn::poreStress): the share of the vertices at the other height in the
    // vertex's row of the face's consistent mass.
    const numerics::FaceShape shape = dim == 2 ? numerics::FaceShape::Seg2 : (f.nvert == 3 ? numerics::FaceShape::Tri3 : numerics::FaceShape::Quad4);
    double                    Mf[numerics::kMaxFaceNodes * numerics::kMaxFaceNodes];
    numerics::faceConsistentMass(shape, (int)dim, x, Mf);
    for (PetscInt k = 0; k < f.nvert; ++k) {
      FreeFieldTerm term;
      double        row = 0, other = 0;
      for (PetscInt c = 0; c < f.nvert; ++c) {
        row += Mf[k * f.nvert + c];
        if (nodes[c] != nodes[k]) other += Mf[k * f.nvert + c];
      }
      term.theta = other / row;
      PetscCall(PetscSectionGetOffset(s, f.vertices[k], &term.offset));
      term.node    = nodes[k];
      term.segment = lo;
      term.weight  = f.weights[k];
      for (int d = 0; d < 3; ++d) term.normal[d] = f.normal[d];
      physics::lysmerDashpot((int)dim, f.normal, f.weights[k], medium::boundaryElastic(materials[f.region]), term.C);
      side->terms.push_back(term);
    }
  }
  PetscCall(vc.Close());
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, seg_min.data(), nseg, MPIU_INT, MPI_MIN, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, seg_max.data(), nseg, MPIU_INT, MPI_MAX, comm));
  std::vector<physics::ElasticMaterial> seg_mat(nseg);
  for (int e = 0; e < nseg; ++e) {
    PetscCheck(seg_max[e] >= 0, comm, PETSC_ERR_USER_INPUT, "-bc_%s_type freefield: boundary '%s' has no face between heights %g and %g; allowed: a side without gaps",
               name.c_str(), name.c_str(), heights[e], heights[e + 1]);
    const auto &a = materials[seg_min[e]], &b = materials[seg_max[e]];
    PetscCheck(sameMaterial(a, b), comm, PETSC_ERR_USER_INPUT,
               "-bc_%s_type freefield: along '%s' between heights %g and %g the regions %s and %s differ; allowed: horizontally layered materials along a free-field side",
               name.c_str(), name.c_str(), heights[e], heights[e + 1], a.region.c_str(), b.region.c_str());
    PetscCheck(!fluid || sameFluid(fluid->region[seg_min[e]], fluid->region[seg_max[e]]), comm, PETSC_ERR_USER_INPUT,
               "-bc_%s_type freefield: along '%s' between heights %g and %g the pore fluids of regions %s and %s differ; allowed: horizontally layered materials along a free-field side",
               name.c_str(), name.c_str(), heights[e], heights[e + 1], a.region.c_str(), b.region.c_str());
    // The skeleton's material: a saturated segment's undrained stiffening comes from the
    // column's pore pressure (setColumnFluid), as in the main mesh's cells.
    seg_mat[e] = a.elastic;
  }
  // Spectral elements: the column is the 1D element of the mesh's degree on the side's GLL
  // nodes (physics/free_field_column.hpp), so a height-only motion is an exact discrete
  // solution of the main mesh at any degree.
  const mesh::SpectralLayout *layout = nullptr;
  PetscCall(mesh::SpectralLayoutOf(dm, &layout));
  physics::ColumnElement element;
  if (layout && layout->degree > 1) {
    const int p    = (int)layout->degree;
    element.degree = p;
    element.x.resize(p + 1);
    element.w.resize(p + 1);
    element.D.resize((p + 1) * (p + 1));
    numerics::gllPointsWeights(p, element.x.data(), element.w.data());
    numerics::lagrangeDerivativeMatrix(p, element.x.data(), element.D.data());
  }
  const std::string problem = side->column.setup((int)dim, heights, seg_mat, rayleigh.alpha, rayleigh.beta, element);
  PetscCheck(problem.empty(), comm, PETSC_ERR_USER_INPUT, "-bc_%s_type freefield: %s", name.c_str(), problem.c_str());
  if (att) {
    // The column's segments carry the damping of the side's cells, so that the free-field
    // traction matches the interior's stress, memory included.
    std::vector<physics::ConstantQModel> seg_models(nseg);
    std::vector<double>                  seg_factor(nseg);
    for (int e = 0; e < nseg; ++e) {
      seg_models[e] = att->region_models[seg_min[e]];
      seg_factor[e] = att->region_factor[seg_min[e]];
    }
    const std::string q_problem = side->column.setAttenuation(seg_models, seg_factor);
    PetscCheck(q_problem.empty(), comm, PETSC_ERR_PLIB, "-bc_%s_type freefield: %s", name.c_str(), q_problem.c_str());
  }
  // Hysteretic regions: the segments beside them carry the region's Iwan model on the same
  // element moduli, so the side's traction is the stress the interior's cells would give
  // (one model per region, which the segments of an element share).
  std::vector<std::shared_ptr<const physics::HystereticSoilModel>> region_soil(materials.size()), seg_soil(nseg);
  for (size_t r = 0; r < materials.size(); ++r) PetscCall(medium::HystereticElementModel(materials[r], &region_soil[r]));
  for (int e = 0; e < nseg; ++e) seg_soil[e] = region_soil[seg_min[e]];
  const std::string h_problem = side->column.setHysteresis(seg_soil);
  PetscCheck(h_problem.empty(), comm, PETSC_ERR_PLIB, "-bc_%s_type freefield: %s", name.c_str(), h_problem.c_str());
  // Darendeli regions with sigma'_0 from the geostatic stage: the column's from its own weight
  // (the stage's state beside a laterally confined side).
  std::vector<bool> seg_geostatic(nseg);
  for (int e = 0; e < nseg; ++e) seg_geostatic[e] = seg_soil[e] && materials[seg_min[e]].hysteretic.mean_stress_geostatic;
  side->column.setGeostaticScales(bc.gravity, seg_geostatic, medium::kDarendeliReferenceStress, medium::kGeostaticStressFloor);
  if (bc.input_wave != InputWave::None) side->column.setInput((int)bc.input_component, bc.input_wave == InputWave::P);
  if (fluid) PetscCall(setColumnFluid(dm, *fluid, seg_min, side));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode FreeFieldCreate(DM dm, const BoundaryConditions &bc, const std::vector<medium::RegionMaterialInfo> &materials, const physics::RayleighCoefficients &rayleigh,
                               const medium::Attenuation *att, const FreeFieldFluid *fluid, double h_min, FreeField **out) {
  PetscFunctionBeginUser;
  auto *ff = new FreeField();
  PetscCall(DMGetDimension(dm, &ff->dim));
  for (size_t i = 0; i < bc.names.size(); ++i)
    if (bc.types[i] == BoundaryType::FreeField) {
      ff->sides.emplace_back();
      PetscCall(buildSide(dm, bc.names[i], bc, materials, rayleigh, att, fluid, 1e-9 * h_min, &ff->sides.back()));
    }
  PetscCall(DMCreateGlobalVector(dm, &ff->force));
  PetscCall(DMCreateLocalVector(dm, &ff->force_local));
  PetscCall(VecZeroEntries(ff->force));
  *out = ff;
  PetscFunctionReturn(0);
}

PetscErrorCode FreeFieldUpdate(FreeField *ff, DM dm, TS ts, PetscReal t, double v_in, bool enabled) {
  PetscFunctionBeginUser;
  if (!enabled) {
    PetscCall(VecZeroEntries(ff->force));
    PetscFunctionReturn(0);
  }
  PetscReal h_ts = 0;
  if (ts) PetscCall(TSGetTimeStep(ts, &h_ts));
  for (FreeFieldSide &side : ff->sides) {
    physics::FreeFieldColumn &col = side.trial;
    col                           = side.column;
    if (!col.started()) {
      col.start(t, v_in);
    } else if (t > col.time()) {
      // The TS's own step when it is the one being taken (avoids the round-off of t - t_n).
      const double h = ts && std::fabs(col.time() + h_ts - t) <= 1e-9 * h_ts ? (double)h_ts : t - col.time();
      col.step(h, v_in);
    } else {
      PetscCheck(t == col.time(), PETSC_COMM_SELF, PETSC_ERR_ORDER, "free-field column of '%s' is at t = %.17g s and cannot go back to t = %.17g s", side.name.c_str(),
                 col.time(), (double)t);
    }
  }
  ff->has_trial = true;
  PetscScalar   *f;
  const PetscInt dim = ff->dim;
  PetscCall(VecZeroEntries(ff->force_local));
  PetscCall(VecGetArray(ff->force_local, &f));
  for (FreeFieldSide &side : ff->sides) {
    const physics::FreeFieldColumn &col = side.trial;
    for (const FreeFieldTerm &term : side.terms) {
      // The face's element's stress at the term's node (GLL face rule; degree 1: the segment's).
      double sig[9];
      col.stress(term.segment, term.node, sig);
      const double pore = col.poreStress(term.segment, term.node, term.theta); // total stress: less alpha p I
      for (PetscInt i = 0; i < dim; ++i) sig[i * dim + i] -= pore;
      for (PetscInt i = 0; i < dim; ++i) {
        double fi = 0;
        for (PetscInt j = 0; j < dim; ++j) fi += term.C[i * dim + j] * col.velocity(term.node, (int)j) + term.weight * sig[i * dim + j] * term.normal[j];
        f[term.offset + i] += fi;
      }
    }
  }
  PetscCall(VecRestoreArray(ff->force_local, &f));
  PetscCall(VecZeroEntries(ff->force));
  PetscCall(DMLocalToGlobal(dm, ff->force_local, ADD_VALUES, ff->force));
  PetscFunctionReturn(0);
}

void FreeFieldCommit(FreeField *ff) {
  if (!ff || !ff->has_trial) return;
  for (FreeFieldSide &side : ff->sides) std::swap(side.column, side.trial);
  ff->has_trial = false;
}

double FreeFieldStableStep(const FreeField *ff, double coupling_factor) {
  double dt = 1e300;
  if (ff)
    for (const FreeFieldSide &side : ff->sides) dt = std::min(dt, side.column.stableStep(coupling_factor));
  return dt;
}

PetscErrorCode FreeFieldDestroy(FreeField **ff) {
  PetscFunctionBeginUser;
  if (!*ff) PetscFunctionReturn(0);
  PetscCall(VecDestroy(&(*ff)->force));
  PetscCall(VecDestroy(&(*ff)->force_local));
  delete *ff;
  *ff = nullptr;
  PetscFunctionReturn(0);
}

} // namespace slipwave::input

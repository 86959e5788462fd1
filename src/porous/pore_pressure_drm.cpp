#include "slipwave/porous/pore_pressure_drm.hpp"

namespace slipwave::porous {

PetscErrorCode PorePressureDrmCreate(PorePressure *pp, const input::Drm *drm, const fem::BulkOperator &bulk) {
  PetscFunctionBeginUser;
  std::vector<PetscInt> index(bulk.cellCount(), -1);
  for (size_t i = 0; i < pp->cells.size(); ++i) index[pp->cells[i]] = (PetscInt)i;
  for (PetscInt e : input::DrmLayerOf(drm).elements) pp->drm_cell.push_back(index[e]);
  for (Vec *v : {&pp->drm_volume, &pp->drm_volume_trial, &pp->drm_flow, &pp->drm_flow_trial, &pp->drm_source, &pp->drm_source_previous}) {
    PetscCall(VecDuplicate(pp->p, v));
    PetscCall(VecZeroEntries(*v));
  }
  PetscFunctionReturn(0);
}

namespace {

// Visits every saturated layer element: its matrices alpha Q (nen x nen*dim) and kappa H,
// its u0 and p0 restricted to its e nodes (side 0) and to its b nodes (side 1), its node
// flags and the local offsets of its nodes in u and in p.
template <class Visit>
void forEachSaturatedElement(const PorePressure &pp, const input::DrmLayer &layer, Visit visit) {
  const PetscInt nen = pp.nen, dim = pp.dim, nd = nen * dim;
  std::vector<double> u_part(2 * nd), p_part(2 * nen);
  for (size_t ei = 0; ei < pp.drm_cell.size(); ++ei) {
    const PetscInt c = pp.drm_cell[ei];
    if (c < 0) continue;
    const size_t *nodes = &layer.element_node[ei * nen];
    const char   *is_b  = &layer.element_node_is_b[ei * nen];
    for (PetscInt a = 0; a < nen; ++a) {
      const int side = is_b[a] ? 1 : 0;
      for (int s = 0; s < 2; ++s) {
        p_part[s * nen + a] = s == side ? layer.p0[ei * nen + a] : 0.0;
        for (PetscInt i = 0; i < dim; ++i) u_part[s * nd + a * dim + i] = s == side ? layer.u0[dim * nodes[a] + i] : 0.0;
      }
    }
    const size_t m = (size_t)pp.cell_matrix[c];
    visit(&pp.coupling[m * nen * nd], &pp.diffusion[m * nen * nen], u_part.data(), p_part.data(), is_b, &pp.cell_u[c * nen], &pp.cell_p[c * nen]);
  }
}

} // namespace

PetscErrorCode PorePressureDrmSource(PorePressure *pp, const input::Drm *drm) {
  const input::DrmLayer layer = input::DrmLayerOf(drm);
  const PetscInt        nen = pp->nen, nd = nen * pp->dim;
  PetscFunctionBeginUser;
  // G and r of the trial, as local sums over this rank's layer elements.
  Vec pair[2] = {pp->drm_volume_trial, pp->drm_flow_trial};
  for (int k = 0; k < 2; ++k) {
    PetscScalar *x;
    PetscCall(VecZeroEntries(pp->q_local));
    PetscCall(VecGetArray(pp->q_local, &x));
    forEachSaturatedElement(*pp, layer, [&](const double *Q, const double *H, const double *u_part, const double *p_part, const char *is_b, const PetscInt *, const PetscInt *cell_p) {
      for (PetscInt a = 0; a < nen; ++a) {
        // A b row takes the e part (side 0) with a plus sign for G, minus for r; an e row the
        // b part (side 1) with the opposite signs.
        const int other = is_b[a] ? 0 : 1;
        double    sum   = 0;
        if (k == 0)
          for (PetscInt j = 0; j < nd; ++j) sum += Q[a * nd + j] * u_part[other * nd + j];
        else
          for (PetscInt b = 0; b < nen; ++b) sum -= H[a * nen + b] * p_part[other * nen + b];
        x[cell_p[a]] += is_b[a] ? sum : -sum;
      }
    });
    PetscCall(VecRestoreArray(pp->q_local, &x));
    PetscCall(VecZeroEntries(pair[k]));
    PetscCall(DMLocalToGlobal(pp->pdm, pp->q_local, ADD_VALUES, pair[k]));
  }
  // W = -(G(t) - G(t_n)) + h r(t_n), h from the committed time (zero before the first commit).
  const double h = pp->started ? layer.time - pp->t : 0.0;
  PetscCall(VecWAXPY(pp->drm_source, -1.0, pp->drm_volume_trial, pp->drm_volume));
  PetscCall(VecAXPY(pp->drm_source, h, pp->drm_flow));
  PetscFunctionReturn(0);
}

PetscErrorCode PorePressureDrmForce(PorePressure *pp, const input::Drm *drm, DM dm, Vec f) {
  const input::DrmLayer layer = input::DrmLayerOf(drm);
  const PetscInt        nen = pp->nen, dim = pp->dim, nd = nen * dim;
  Vec                   f_local, f_global;
  PetscScalar          *fl;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dm, &f_local));
  PetscCall(DMGetGlobalVector(dm, &f_global));
  PetscCall(VecZeroEntries(f_local));
  PetscCall(VecGetArray(f_local, &fl));
  forEachSaturatedElement(*pp, layer, [&](const double *Q, const double *, const double *, const double *p_part, const char *is_b, const PetscInt *cell_u, const PetscInt *) {
    for (PetscInt b = 0; b < nen; ++b) {
      const int other = is_b[b] ? 0 : 1;
      for (PetscInt j = 0; j < dim; ++j) {
        double sum = 0; // (alpha Q^T p0_part) at dof (b, j)
        for (PetscInt a = 0; a < nen; ++a) sum += Q[a * nd + b * dim + j] * p_part[other * nen + a];
        fl[cell_u[b] + j] += is_b[b] ? sum : -sum;
      }
    }
  });
  PetscCall(VecRestoreArray(f_local, &fl));
  PetscCall(VecZeroEntries(f_global));
  PetscCall(DMLocalToGlobal(dm, f_local, ADD_VALUES, f_global));
  PetscCall(VecAXPY(f, 1.0, f_global));
  PetscCall(DMRestoreGlobalVector(dm, &f_global));
  PetscCall(DMRestoreLocalVector(dm, &f_local));
  PetscFunctionReturn(0);
}

} // namespace slipwave::porous

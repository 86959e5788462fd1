#include "slipwave/porous/pore_pressure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>

#include "slipwave/fem/node_fields.hpp"
#include "slipwave/fem/spectral_biot.hpp"
#include "slipwave/fem/spectral_kernels.hpp"
#include "slipwave/numerics/gll_basis.hpp"
#include "slipwave/physics/cavitation.hpp"
#include "slipwave/physics/split_diffusion_step.hpp"

namespace slipwave::porous {
namespace {

// Adds local per-node values into a global vector of the pressure layout (overwritten).
PetscErrorCode localToGlobalSum(DM pdm, Vec local, Vec global) {
  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(global));
  PetscCall(DMLocalToGlobal(pdm, local, ADD_VALUES, global));
  PetscFunctionReturn(0);
}

// The per-step cell loops, with the node count and dimension as compile-time constants so
// the small products unroll, and, like the bulk loop (fem/bulk_operator.cpp), runs of kBatch
// consecutive cells that share their matrices (every cell of a box-mesh region) done
// together: each cell's values in one SIMD lane, the matrix entry broadcast. Without this the
// two loops cost 2.5x the bulk force per flop.
constexpr int kBatch = 8;
typedef double BatchVec __attribute__((vector_size(kBatch * sizeof(double))));
union Lanes {
  BatchVec v;
  double   d[kBatch];
};

// Length of the run of cells from c sharing cell c's matrices, at most kBatch.
inline size_t runLength(const PetscInt *matrix, size_t c, size_t ncell) {
  size_t run = 1;
  while (run < (size_t)kBatch && c + run < ncell && matrix[c + run] == matrix[c]) ++run;
  return run;
}

// q_a += sum (alpha Q)_a,bj u_bj: alpha Q u per pressure node.
template <int NEN, int DIM>
void addCouplingTimesU(size_t ncell, const PetscInt *matrix, const PetscInt *cell_u, const PetscInt *cell_p, const double *pool, const PetscScalar *u, PetscScalar *q) {
  constexpr int N = NEN * DIM;
  size_t        c = 0;
  while (c < ncell) {
    const double *__restrict Q   = pool + (size_t)matrix[c] * NEN * N;
    const size_t             run = runLength(matrix, c, ncell);
    if (run < (size_t)kBatch) {
      for (size_t i = c; i < c + run; ++i) {
        double ue[N];
        for (int b = 0; b < NEN; ++b)
          for (int j = 0; j < DIM; ++j) ue[b * DIM + j] = PetscRealPart(u[cell_u[i * NEN + b] + j]);
        for (int r = 0; r < NEN; ++r) {
          double sum = 0;
          for (int k = 0; k < N; ++k) sum += Q[r * N + k] * ue[k];
          q[cell_p[i * NEN + r]] += sum;
        }
      }
      c += run;
      continue;
    }
    Lanes ue[N], acc[NEN];
    for (int l = 0; l < kBatch; ++l)
      for (int b = 0; b < NEN; ++b)
        for (int j = 0; j < DIM; ++j) ue[b * DIM + j].d[l] = PetscRealPart(u[cell_u[(c + l) * NEN + b] + j]);
    for (int r = 0; r < NEN; ++r) {
      BatchVec sum = Q[r * N] * ue[0].v;
      for (int k = 1; k < N; ++k) sum += Q[r * N + k] * ue[k].v;
      acc[r].v = sum;
    }
    for (int l = 0; l < kBatch; ++l)
      for (int r = 0; r < NEN; ++r) q[cell_p[(c + l) * NEN + r]] += acc[r].d[l];
    c += kBatch;
  }
}

// One cell's f_bj += sum_a (alpha Q)_a,bj p_a (the skeleton force) from its nodal p.
template <int NEN, int DIM>
inline void cellCouplingTranspose(const double *__restrict Q, const double *pe, const PetscInt *cell_u, PetscScalar *f) {
  constexpr int N = NEN * DIM;
  double        fe[N] = {};
  for (int r = 0; r < NEN; ++r)
    for (int k = 0; k < N; ++k) fe[k] += Q[r * N + k] * pe[r];
  for (int b = 0; b < NEN; ++b)
    for (int j = 0; j < DIM; ++j) f[cell_u[b] + j] += fe[b * DIM + j];
}

// One cell's h_a += sum_b (kappa H)_ab p_b.
template <int NEN>
inline void cellDiffusion(const double *__restrict H, const double *pe, const PetscInt *cell_p, PetscScalar *h) {
  for (int r = 0; r < NEN; ++r) {
    double sum = 0;
    for (int b = 0; b < NEN; ++b) sum += H[r * NEN + b] * pe[b];
    h[cell_p[r]] += sum;
  }
}

// The force on the skeleton and H p from one gather of p (the pass of every step).
template <int NEN, int DIM>
void addCouplingTransposeAndDiffusion(size_t ncell, const PetscInt *matrix, const PetscInt *cell_u, const PetscInt *cell_p, const double *coupling,
                                      const double *diffusion, const PetscScalar *p, PetscScalar *f, PetscScalar *h) {
  constexpr int N = NEN * DIM;
  size_t        c = 0;
  while (c < ncell) {
    const double *__restrict Q   = coupling + (size_t)matrix[c] * NEN * N;
    const double *__restrict H   = diffusion + (size_t)matrix[c] * NEN * NEN;
    const size_t             run = runLength(matrix, c, ncell);
    if (run < (size_t)kBatch) {
      for (size_t i = c; i < c + run; ++i) {
        double pe[NEN];
        for (int r = 0; r < NEN; ++r) pe[r] = PetscRealPart(p[cell_p[i * NEN + r]]);
        cellCouplingTranspose<NEN, DIM>(Q, pe, cell_u + i * NEN, f);
        cellDiffusion<NEN>(H, pe, cell_p + i * NEN, h);
      }
      c += run;
      continue;
    }
    Lanes pe[NEN], fe[N], he[NEN];
    for (int l = 0; l < kBatch; ++l)
      for (int r = 0; r < NEN; ++r) pe[r].d[l] = PetscRealPart(p[cell_p[(c + l) * NEN + r]]);
    for (int k = 0; k < N; ++k) {
      BatchVec sum = Q[k] * pe[0].v;
      for (int r = 1; r < NEN; ++r) sum += Q[r * N + k] * pe[r].v;
      fe[k].v = sum;
    }
    for (int r = 0; r < NEN; ++r) {
      BatchVec sum = H[r * NEN] * pe[0].v;
      for (int b = 1; b < NEN; ++b) sum += H[r * NEN + b] * pe[b].v;
      he[r].v = sum;
    }
    for (int l = 0; l < kBatch; ++l) {
      for (int b = 0; b < NEN; ++b)
        for (int j = 0; j < DIM; ++j) f[cell_u[(c + l) * NEN + b] + j] += fe[b * DIM + j].d[l];
      for (int r = 0; r < NEN; ++r) h[cell_p[(c + l) * NEN + r]] += he[r].d[l];
    }
    c += kBatch;
  }
}

// H p alone (the diffusion sub-steps after the first).
template <int NEN>
void addDiffusion(size_t ncell, const PetscInt *matrix, const PetscInt *cell_p, const double *diffusion, const PetscScalar *p, PetscScalar *h) {
  for (size_t i = 0; i < ncell; ++i) {
    double pe[NEN];
    for (int r = 0; r < NEN; ++r) pe[r] = PetscRealPart(p[cell_p[i * NEN + r]]);
    cellDiffusion<NEN>(diffusion + (size_t)matrix[i] * NEN * NEN, pe, cell_p + i * NEN, h);
  }
}

// Degree p > 1: the same products element by element through the sum-factorised kernels of
// fem/spectral_biot.hpp, from each element's GLL factors (pp.degree > 1).
struct SpectralFactors {
  const double *D, *coupling, *diffusion, *jinv;
  size_t        stride_w, stride_j; // per distinct matrix: weights, J^{-1} entries
  SpectralFactors(const PorePressure &pp)
      : D(pp.gll_derivative.data()), coupling(pp.coupling_weight.data()), diffusion(pp.diffusion_weight.data()), jinv(pp.inverse_jacobian.data()),
        stride_w((size_t)pp.nen), stride_j((size_t)pp.nen * pp.dim * pp.dim) {}
};

void spectralCouplingTimesU(const PorePressure &pp, const PetscScalar *u, PetscScalar *q) {
  const SpectralFactors f(pp);
  const PetscInt        nq = pp.nen, dim = pp.dim;
  double                ue[fem::kMaxSpectralDofs], out[fem::kMaxSpectralNodes];
  for (size_t i = 0; i < pp.cells.size(); ++i) {
    const size_t m = (size_t)pp.cell_matrix[i];
    for (PetscInt a = 0; a < nq; ++a)
      for (PetscInt j = 0; j < dim; ++j) ue[a * dim + j] = PetscRealPart(u[pp.cell_u[i * nq + a] + j]);
    fem::spectralDivergence((int)dim, (int)pp.degree, f.D, f.coupling + m * f.stride_w, f.jinv + m * f.stride_j, ue, out);
    for (PetscInt a = 0; a < nq; ++a) q[pp.cell_p[i * nq + a]] += out[a];
  }
}

// f += alpha Q^T p and (with h) h += kappa H p.
void spectralCouplingTransposeAndDiffusion(const PorePressure &pp, const PetscScalar *p, PetscScalar *f, PetscScalar *h) {
  const SpectralFactors s(pp);
  const PetscInt        nq = pp.nen, dim = pp.dim;
  double                pe[fem::kMaxSpectralNodes], fe[fem::kMaxSpectralDofs], he[fem::kMaxSpectralNodes];
  for (size_t i = 0; i < pp.cells.size(); ++i) {
    const size_t m = (size_t)pp.cell_matrix[i];
    for (PetscInt a = 0; a < nq; ++a) pe[a] = PetscRealPart(p[pp.cell_p[i * nq + a]]);
    if (f) {
      fem::spectralDivergenceTranspose((int)dim, (int)pp.degree, s.D, s.coupling + m * s.stride_w, s.jinv + m * s.stride_j, pe, fe);
      for (PetscInt b = 0; b < nq; ++b)
        for (PetscInt j = 0; j < dim; ++j) f[pp.cell_u[i * nq + b] + j] += fe[b * dim + j];
    }
    fem::spectralDiffusion((int)dim, (int)pp.degree, s.D, s.diffusion + m * s.stride_w, s.jinv + m * s.stride_j, pe, he);
    for (PetscInt a = 0; a < nq; ++a) h[pp.cell_p[i * nq + a]] += he[a];
  }
}

void couplingTimesU(const PorePressure &pp, const PetscScalar *u, PetscScalar *q) {
  if (pp.degree > 1) return spectralCouplingTimesU(pp, u, q);
  const size_t n = pp.cells.size();
  const PetscInt *m = pp.cell_matrix.data(), *cu = pp.cell_u.data(), *cp = pp.cell_p.data();
  switch (pp.nen * pp.dim) {
  case 6: addCouplingTimesU<3, 2>(n, m, cu, cp, pp.coupling.data(), u, q); break;
  case 8: addCouplingTimesU<4, 2>(n, m, cu, cp, pp.coupling.data(), u, q); break;
  case 12: addCouplingTimesU<4, 3>(n, m, cu, cp, pp.coupling.data(), u, q); break;
  case 24: addCouplingTimesU<8, 3>(n, m, cu, cp, pp.coupling.data(), u, q); break;
  default: break;
  }
}

void couplingTransposeAndDiffusion(const PorePressure &pp, const PetscScalar *p, PetscScalar *f, PetscScalar *h) {
  if (pp.degree > 1) return spectralCouplingTransposeAndDiffusion(pp, p, f, h);
  const size_t n = pp.cells.size();
  const PetscInt *m = pp.cell_matrix.data(), *cu = pp.cell_u.data(), *cp = pp.cell_p.data();
  const double   *Q = pp.coupling.data(), *H = pp.diffusion.data();
  switch (pp.nen * pp.dim) {
  case 6: addCouplingTransposeAndDiffusion<3, 2>(n, m, cu, cp, Q, H, p, f, h); break;
  case 8: addCouplingTransposeAndDiffusion<4, 2>(n, m, cu, cp, Q, H, p, f, h); break;
  case 12: addCouplingTransposeAndDiffusion<4, 3>(n, m, cu, cp, Q, H, p, f, h); break;
  case 24: addCouplingTransposeAndDiffusion<8, 3>(n, m, cu, cp, Q, H, p, f, h); break;
  default: break;
  }
}

void diffusionTimes(const PorePressure &pp, const PetscScalar *p, PetscScalar *h) {
  if (pp.degree > 1) return spectralCouplingTransposeAndDiffusion(pp, p, nullptr, h);
  const size_t n = pp.cells.size();
  const PetscInt *m = pp.cell_matrix.data(), *cp = pp.cell_p.data();
  switch (pp.nen) {
  case 3: addDiffusion<3>(n, m, cp, pp.diffusion.data(), p, h); break;
  case 4: addDiffusion<4>(n, m, cp, pp.diffusion.data(), p, h); break;
  case 8: addDiffusion<8>(n, m, cp, pp.diffusion.data(), p, h); break;
  default: break;
  }
}

// The diffusion part of the step of size h from the committed p_n (cached until the commit):
// p_star and Hbar, with S (p_star - p_n) = -h Hbar on free nodes.
PetscErrorCode diffuse(PorePressure *pp, double h) {
  PetscFunctionBeginUser;
  // The ledger asks with the TS's step, the RHS with t_{n+1} - t_n: equal up to round-off.
  if (pp->diffused_h >= 0 && std::fabs(pp->diffused_h - h) <= 1e-12 * h) PetscFunctionReturn(0);
  pp->substeps = PorePressureSubsteps(pp, h);
  const double sub = h / (double)pp->substeps;
  PetscCall(VecCopy(pp->p, pp->p_star));
  PetscCall(VecZeroEntries(pp->Hbar));
  for (PetscInt k = 0; k < pp->substeps && h > 0; ++k) {
    PetscScalar       *q, *ps, *hb;
    const PetscScalar *pl, *hl, *inv;
    // H p^k: for k = 0 the pass that formed the last force left H p_n; later ones are summed
    // over ranks into Hbar_trial (a free work vector here).
    Vec Hpk = pp->Hp;
    if (k > 0) {
      PetscCall(DMGlobalToLocal(pp->pdm, pp->p_star, INSERT_VALUES, pp->p_local));
      PetscCall(VecZeroEntries(pp->q_local));
      PetscCall(VecGetArray(pp->q_local, &q));
      PetscCall(VecGetArrayRead(pp->p_local, &pl));
      diffusionTimes(*pp, pl, q);
      PetscCall(VecRestoreArrayRead(pp->p_local, &pl));
      PetscCall(VecRestoreArray(pp->q_local, &q));
      PetscCall(localToGlobalSum(pp->pdm, pp->q_local, pp->Hbar_trial));
      Hpk = pp->Hbar_trial;
    }
    PetscInt n;
    PetscCall(VecGetLocalSize(pp->p_star, &n));
    PetscCall(VecGetArray(pp->p_star, &ps));
    PetscCall(VecGetArray(pp->Hbar, &hb));
    PetscCall(VecGetArrayRead(Hpk, &hl));
    PetscCall(VecGetArrayRead(pp->inv_storage, &inv));
    for (PetscInt i = 0; i < n; ++i) {
      hb[i] += hl[i] / (double)pp->substeps;
      ps[i] -= sub * inv[i] * hl[i];
    }
    PetscCall(VecRestoreArrayRead(pp->inv_storage, &inv));
    PetscCall(VecRestoreArrayRead(Hpk, &hl));
    PetscCall(VecRestoreArray(pp->Hbar, &hb));
    PetscCall(VecRestoreArray(pp->p_star, &ps));
  }
  pp->diffused_h = h;
  PetscFunctionReturn(0);
}

// Element matrices (or, at degree p > 1, their GLL factors) per distinct bulk element matrix,
// the element lists and their node offsets.
PetscErrorCode buildCells(DM pdm, const fem::BulkOperator &bulk, PorePressure *pp) {
  PetscSection section;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(pdm, &section));
  pp->degree     = bulk.degree();
  pp->bound_kind = bulk.eigenBoundKind();
  pp->nen        = bulk.nodesPerElement();
  pp->dim        = bulk.dimension();
  const PetscInt nen = pp->nen, dim = pp->dim, nd = nen * dim, p = pp->degree;
  if (p > 1) {
    double x[numerics::kMaxSpectralDegree + 1], w[numerics::kMaxSpectralDegree + 1];
    pp->gll_derivative.resize((size_t)(p + 1) * (p + 1));
    numerics::gllPointsWeights((int)p, x, w);
    numerics::lagrangeDerivativeMatrix((int)p, x, pp->gll_derivative.data());
  }
  std::map<PetscInt, PetscInt> index; // bulk matrix -> ours
  for (PetscInt e = 0; e < bulk.elementCount(); ++e) {
    const SaturatedRegion &r = pp->regions[bulk.elementRegion(e)];
    if (!r.saturated) continue;
    auto found = index.find(bulk.elementMatrix(e));
    if (found == index.end()) {
      const PetscInt k = (PetscInt)index.size();
      found            = index.emplace(bulk.elementMatrix(e), k).first;
      pp->storage_element.resize((size_t)(k + 1) * nen);
      pp->matrix_region.push_back(bulk.elementRegion(e));
      double *S = &pp->storage_element[(size_t)k * nen];
      if (p == 1) {
        pp->coupling.resize((size_t)(k + 1) * nen * nd);
        pp->diffusion.resize((size_t)(k + 1) * nen * nen);
        double *Q = &pp->coupling[(size_t)k * nen * nd], *H = &pp->diffusion[(size_t)k * nen * nen];
        fem::elementCoupling(bulk.shape(), bulk.elementCoordinates(e), Q);
        fem::elementDiffusion(bulk.shape(), bulk.elementCoordinates(e), H);
        fem::elementLumpedMass(bulk.shape(), bulk.elementCoordinates(e), 1.0 / r.M, S);
        for (PetscInt i = 0; i < nen * nd; ++i) Q[i] *= r.alpha;
        for (PetscInt i = 0; i < nen * nen; ++i) H[i] *= r.kappa;
      } else {
        // GLL collocation: the storage is w|J| / M, diagonal without lumping.
        std::vector<double> wdet(nen);
        pp->inverse_jacobian.resize((size_t)(k + 1) * nen * dim * dim);
        // The bulk operator accepted every element (SpectralOperator::Setup), so this succeeds.
        PetscCheck(fem::spectralGeometry((int)dim, (int)p, bulk.elementCoordinates(e), wdet.data(), &pp->inverse_jacobian[(size_t)k * nen * dim * dim]), PETSC_COMM_SELF,
                   PETSC_ERR_PLIB, "element %" PetscInt_FMT ": singular map", e);
        for (PetscInt a = 0; a < nen; ++a) {
          pp->coupling_weight.push_back(r.alpha * wdet[a]);
          pp->diffusion_weight.push_back(r.kappa * wdet[a]);
          S[a] = wdet[a] / r.M;
        }
      }
    }
    pp->cells.push_back(e);
    pp->cell_matrix.push_back(found->second);
    for (PetscInt a = 0; a < nen; ++a) {
      PetscInt off;
      PetscCall(PetscSectionGetOffset(section, bulk.elementVertex(e, a), &off));
      pp->cell_p.push_back(off);
      pp->cell_u.push_back(bulk.elementNodeOffset(e, a));
    }
  }
  PetscFunctionReturn(0);
}

// The Darcy matrix kappa H of distinct matrix m, dense: degree 1 the stored one; degree p > 1
// built into *buffer from the GLL factors (kept while m repeats, as along a region's elements;
// *buffered: the matrix in the buffer, -1 for none).
const double *denseDiffusion(const PorePressure &pp, PetscInt m, std::vector<double> *buffer, PetscInt *buffered) {
  const size_t nen = (size_t)pp.nen;
  if (pp.degree == 1) return &pp.diffusion[(size_t)m * nen * nen];
  if (*buffered != m) {
    buffer->resize(nen * nen);
    fem::spectralDiffusionMatrix((int)pp.dim, (int)pp.degree, &pp.diffusion_weight[(size_t)m * nen], &pp.inverse_jacobian[(size_t)m * nen * pp.dim * pp.dim],
                                 buffer->data());
    *buffered = m;
  }
  return buffer->data();
}

// Lumped storage, the free mask, the inflow, and the explicit diffusion limit over free nodes.
PetscErrorCode assembleNodal(DM dm, const std::vector<std::string> &boundaries, PorePressure *pp) {
  Vec          drained_local, inflow_local, drained, rows;
  PetscScalar *a;
  PetscFunctionBeginUser;
  const PetscInt nen = pp->nen;
  PetscCall(DMCreateGlobalVector(pp->pdm, &pp->storage));
  for (Vec *v : {&pp->inv_storage, &pp->free_mask, &pp->inflow, &pp->p, &pp->p_trial, &pp->Qu, &pp->Qu_trial, &pp->p_star, &pp->Hbar, &pp->Hbar_trial, &pp->Hbar_previous, &pp->Hp, &pp->Hp_trial}) {
    PetscCall(VecDuplicate(pp->storage, v));
    PetscCall(VecZeroEntries(*v));
  }
  PetscCall(DMCreateLocalVector(pp->pdm, &pp->p_local));
  PetscCall(VecDuplicate(pp->p_local, &pp->q_local));
  PetscCall(VecDuplicate(pp->p_local, &drained_local));
  PetscCall(VecDuplicate(pp->p_local, &inflow_local));
  PetscCall(VecDuplicate(pp->storage, &drained));
  PetscCall(VecDuplicate(pp->storage, &rows));
  // Storage and the Gershgorin rows of H.
  PetscCall(VecZeroEntries(pp->q_local));
  PetscCall(VecZeroEntries(pp->p_local));
  {
    PetscScalar        *h;
    std::vector<double> buffer;
    PetscInt            buffered = -1;
    PetscCall(VecGetArray(pp->q_local, &a));
    PetscCall(VecGetArray(pp->p_local, &h));
    for (size_t i = 0; i < pp->cells.size(); ++i) {
      const double *S = &pp->storage_element[(size_t)pp->cell_matrix[i] * nen], *H = denseDiffusion(*pp, pp->cell_matrix[i], &buffer, &buffered);
      for (PetscInt r = 0; r < nen; ++r) {
        a[pp->cell_p[i * nen + r]] += S[r];
        for (PetscInt c = 0; c < nen; ++c) h[pp->cell_p[i * nen + r]] += std::fabs(H[r * nen + c]);
      }
    }
    PetscCall(VecRestoreArray(pp->p_local, &h));
    PetscCall(VecRestoreArray(pp->q_local, &a));
  }
  PetscCall(localToGlobalSum(pp->pdm, pp->q_local, pp->storage));
  PetscCall(localToGlobalSum(pp->pdm, pp->p_local, rows));
  PetscCall(VecZeroEntries(drained_local));
  PetscCall(VecZeroEntries(inflow_local));
  PetscCall(PorePressureReadFluidBoundaries(dm, pp->pdm, boundaries, pp->regions, drained_local, inflow_local, pp));
  PetscCall(localToGlobalSum(pp->pdm, drained_local, drained));
  PetscCall(localToGlobalSum(pp->pdm, inflow_local, pp->inflow));
  {
    PetscInt           n;
    const PetscScalar *s, *d, *h;
    PetscScalar       *inv, *mask;
    PetscCall(VecGetLocalSize(pp->storage, &n));
    PetscCall(VecGetArrayRead(pp->storage, &s));
    PetscCall(VecGetArrayRead(drained, &d));
    PetscCall(VecGetArrayRead(rows, &h));
    PetscCall(VecGetArray(pp->inv_storage, &inv));
    PetscCall(VecGetArray(pp->free_mask, &mask));
    for (PetscInt i = 0; i < n; ++i) {
      const bool free = PetscRealPart(s[i]) > 0 && PetscRealPart(d[i]) == 0;
      mask[i]         = free ? 1.0 : 0.0;
      inv[i]          = free ? 1.0 / s[i] : 0.0;
      if (free) pp->dt_diffusion = std::min(pp->dt_diffusion, physics::explicitDiffusionStepOfRow(PetscRealPart(s[i]), PetscRealPart(h[i])));
    }
    PetscCall(VecRestoreArray(pp->free_mask, &mask));
    PetscCall(VecRestoreArray(pp->inv_storage, &inv));
    PetscCall(VecRestoreArrayRead(rows, &h));
    PetscCall(VecRestoreArrayRead(drained, &d));
    PetscCall(VecRestoreArrayRead(pp->storage, &s));
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &pp->dt_diffusion, 1, MPI_DOUBLE, MPI_MIN, PetscObjectComm((PetscObject)dm)));
  for (Vec *v : {&drained_local, &inflow_local, &drained, &rows}) PetscCall(VecDestroy(v));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode PorePressureCreate(DM dm, const fem::BulkOperator &bulk, const std::vector<std::string> &boundaries, std::vector<SaturatedRegion> regions,
                                  double gravity, const double *gravity_direction, PorePressure **out) {
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscFunctionBeginUser;
  auto *pp    = new PorePressure();
  pp->regions = std::move(regions);
  PetscBool subcycle = PETSC_TRUE, water_table = PETSC_FALSE;
  PetscReal elevation = 0;
  char      cavitation[64] = "-100e3";
  PetscOptionsBegin(comm, "", "Pore pressure of saturated regions", "slipwave");
  PetscCall(PetscOptionsBool("-pore_pressure_subcycle", "sub-step the explicit pore-pressure diffusion within each step instead of lowering the step to its limit",
                             "PorePressureCreate", subcycle, &subcycle, nullptr));
  PetscCall(PetscOptionsReal("-water_table", "elevation of the free water surface [m], measured against -gravity_direction (with -gravity > 0; hydrostatic pressure below it)",
                             "PorePressureCreate", elevation, &elevation, &water_table));
  PetscCall(PetscOptionsString("-fluid_cavitation_pressure",
                               "cavitation limit of the total pore pressure [Pa, gauge: relative to the atmospheric pressure on the water table], -1e9 <= limit <= 0, or none (default -100e3, about water's vapour pressure)",
                               "PorePressureCreate", cavitation, cavitation, sizeof cavitation, nullptr));
  PetscOptionsEnd();
  pp->cavitation = std::string(cavitation) != "none";
  if (pp->cavitation) {
    char *end                = nullptr;
    pp->cavitation_pressure  = std::strtod(cavitation, &end);
    // Water holds no absolute pressure far below zero, and the limit is gauge (0: atmospheric).
    PetscCheck(end != cavitation && *end == '\0' && std::isfinite(pp->cavitation_pressure) && pp->cavitation_pressure >= -1e9 && pp->cavitation_pressure <= 0, comm,
               PETSC_ERR_USER_INPUT, "-fluid_cavitation_pressure = %s; allowed: -1e9 <= limit <= 0 Pa (gauge) or none", cavitation);
  }
  PetscCheck(gravity == 0 || water_table, comm, PETSC_ERR_USER_INPUT,
             "-gravity = %g with a saturated region (-material_<r>_saturated) needs -water_table; allowed: the elevation [m] of the free water surface", gravity);
  PetscCheck(!water_table || gravity > 0, comm, PETSC_ERR_USER_INPUT, "-water_table = %g m needs gravity; allowed: with -gravity > 0", (double)elevation);
  pp->subcycle              = subcycle;
  pp->water_table           = water_table;
  pp->water_table_elevation = elevation;
  double rho_f              = -1;
  for (const SaturatedRegion &r : pp->regions)
    if (r.saturated) {
      PetscCheck(!water_table || rho_f < 0 || r.biot.fluid_density == rho_f, comm, PETSC_ERR_USER_INPUT,
                 "-material_<r>_fluid_density differs between saturated regions (%g and %g kg/m^3) under one -water_table; allowed: one fluid density", rho_f,
                 r.biot.fluid_density);
      rho_f = r.biot.fluid_density;
    }
  PetscCall(fem::NodeFieldCreateDM(dm, 1, &pp->pdm));
  PetscCall(buildCells(pp->pdm, bulk, pp));
  PetscCall(assembleNodal(dm, boundaries, pp));
  PetscCall(VecDuplicate(pp->p, &pp->cavity));
  PetscCall(VecDuplicate(pp->p, &pp->cavity_trial));
  PetscCall(VecZeroEntries(pp->cavity));
  PetscCall(VecZeroEntries(pp->cavity_trial));
  if (pp->cavitation) {
    // The volume each node stands for: the lumped storage times the region's M.
    PetscScalar *vl;
    PetscCall(VecZeroEntries(pp->p_local));
    PetscCall(VecGetArray(pp->p_local, &vl));
    for (size_t i = 0; i < pp->cells.size(); ++i)
      for (PetscInt a = 0; a < pp->nen; ++a)
        vl[pp->cell_p[i * pp->nen + a]] += pp->storage_element[(size_t)pp->cell_matrix[i] * pp->nen + a] * pp->regions[bulk.elementRegion(pp->cells[i])].M;
    PetscCall(VecRestoreArray(pp->p_local, &vl));
    PetscCall(VecDuplicate(pp->p, &pp->node_volume));
    PetscCall(VecDuplicate(pp->p, &pp->cavity_fraction));
    PetscCall(localToGlobalSum(pp->pdm, pp->p_local, pp->node_volume));
    // Node coordinates in the pressure layout, for the report's "where".
    for (PetscInt d = 0; d < pp->dim; ++d) {
      PetscScalar *xl;
      PetscCall(VecZeroEntries(pp->p_local));
      PetscCall(VecGetArray(pp->p_local, &xl));
      for (size_t i = 0; i < pp->cells.size(); ++i) {
        const double *x = bulk.elementCoordinates(pp->cells[i]);
        for (PetscInt a = 0; a < pp->nen; ++a) xl[pp->cell_p[i * pp->nen + a]] = x[a * pp->dim + d];
      }
      PetscCall(VecRestoreArray(pp->p_local, &xl));
      PetscCall(VecDuplicate(pp->p, &pp->node_coordinates[d]));
      PetscCall(DMLocalToGlobal(pp->pdm, pp->p_local, INSERT_VALUES, pp->node_coordinates[d]));
    }
  }
  PetscCall(VecDuplicate(pp->p, &pp->p_hydrostatic));
  PetscCall(VecDuplicate(pp->p, &pp->p_total));
  PetscCall(VecDuplicate(pp->p, &pp->p_total_trial));
  PetscCall(VecZeroEntries(pp->p_hydrostatic));
  if (water_table) {
    // p_h = rho_f g (elevation - z)+ at the nodes of saturated cells, z = -x . g_hat. At and
    // above the water table the pore pressure is atmospheric: those nodes are drained.
    PetscScalar *ph, *above;
    Vec          above_global;
    PetscCall(VecZeroEntries(pp->p_local));
    PetscCall(VecZeroEntries(pp->q_local));
    PetscCall(VecGetArray(pp->p_local, &ph));
    PetscCall(VecGetArray(pp->q_local, &above));
    for (size_t i = 0; i < pp->cells.size(); ++i) {
      const double *x = bulk.elementCoordinates(pp->cells[i]);
      for (PetscInt a = 0; a < pp->nen; ++a) {
        double z = 0;
        for (PetscInt d = 0; d < pp->dim; ++d) z -= x[a * pp->dim + d] * gravity_direction[d];
        ph[pp->cell_p[i * pp->nen + a]]    = rho_f * gravity * std::max(0.0, elevation - z);
        // 2 on the table (within round-off of its elevation), 1 above it.
        above[pp->cell_p[i * pp->nen + a]] = z >= elevation ? (z <= elevation + 1e-9 * std::max(1.0, std::fabs(elevation)) ? 2.0 : 1.0) : 0.0;
      }
    }
    PetscCall(VecRestoreArray(pp->q_local, &above));
    PetscCall(VecRestoreArray(pp->p_local, &ph));
    PetscCall(DMLocalToGlobal(pp->pdm, pp->p_local, INSERT_VALUES, pp->p_hydrostatic));
    PetscCall(VecDuplicate(pp->p, &above_global));
    PetscCall(DMLocalToGlobal(pp->pdm, pp->q_local, INSERT_VALUES, above_global));
    {
      // Nodes on the table that no fluid boundary drained already: a noflow interface may
      // seal them again (PorePressureInterfaceFluid).
      PetscInt           n;
      PetscScalar       *at;
      const PetscScalar *ab, *mask;
      PetscCall(VecDuplicate(pp->p, &pp->at_water_table));
      PetscCall(VecGetLocalSize(pp->p, &n));
      PetscCall(VecGetArray(pp->at_water_table, &at));
      PetscCall(VecGetArrayRead(above_global, &ab));
      PetscCall(VecGetArrayRead(pp->free_mask, &mask));
      for (PetscInt i = 0; i < n; ++i) at[i] = PetscRealPart(ab[i]) > 1.5 && PetscRealPart(mask[i]) > 0 ? 1.0 : 0.0;
      PetscCall(VecRestoreArrayRead(pp->free_mask, &mask));
      PetscCall(VecRestoreArrayRead(above_global, &ab));
      PetscCall(VecRestoreArray(pp->at_water_table, &at));
    }
    PetscCall(PorePressureDrainNodes(pp, above_global));
    PetscCall(VecDestroy(&above_global));
    pp->drained.push_back("the water table and above");
  }
  // Until the first trial (and through the geostatic stage) interfaces see the hydrostatic p.
  PetscCall(VecCopy(pp->p_hydrostatic, pp->p_total_trial));
  *out = pp;
  PetscFunctionReturn(0);
}

PetscErrorCode PorePressureAddHydrostaticForce(PorePressure *pp, DM dm, Vec f) {
  Vec                f_local, f_global;
  PetscScalar       *fl, *q;
  const PetscScalar *pl;
  PetscFunctionBeginUser;
  PetscCall(DMGlobalToLocal(pp->pdm, pp->p_hydrostatic, INSERT_VALUES, pp->p_local));
  PetscCall(DMGetLocalVector(dm, &f_local));
  PetscCall(VecZeroEntries(f_local));
  PetscCall(VecZeroEntries(pp->q_local));
  PetscCall(VecGetArray(f_local, &fl));
  PetscCall(VecGetArray(pp->q_local, &q)); // H p_h lands here and is not used: p_h drives no flow
  PetscCall(VecGetArrayRead(pp->p_local, &pl));
  couplingTransposeAndDiffusion(*pp, pl, fl, q);
  PetscCall(VecRestoreArrayRead(pp->p_local, &pl));
  PetscCall(VecRestoreArray(pp->q_local, &q));
  PetscCall(VecRestoreArray(f_local, &fl));
  PetscCall(VecDuplicate(f, &f_global));
  PetscCall(VecZeroEntries(f_global));
  PetscCall(DMLocalToGlobal(dm, f_local, ADD_VALUES, f_global));
  PetscCall(DMRestoreLocalVector(dm, &f_local));
  PetscCall(VecAXPY(f, 1.0, f_global));
  PetscCall(VecDestroy(&f_global));
  PetscFunctionReturn(0);
}

PetscErrorCode PorePressureTotal(PorePressure *pp) {
  PetscFunctionBeginUser;
  // A drained node's excess pressure is 0. p holds it at 0 on every drained node but one whose
  // gap opened at the last commit: that node keeps p_n until the next step, whose energy
  // sums release it (PorePressureEnergy), while its pressure is already the hydrostatic one.
  PetscCall(VecPointwiseMult(pp->p_total, pp->free_mask, pp->p));
  PetscCall(VecAXPY(pp->p_total, 1.0, pp->p_hydrostatic));
  PetscFunctionReturn(0);
}

PetscErrorCode PorePressureDestroy(PorePressure **pore) {
  PetscFunctionBeginUser;
  if (!*pore) PetscFunctionReturn(0);
  PorePressure *pp = *pore;
  for (Vec *v : {&pp->storage, &pp->inv_storage, &pp->free_mask, &pp->inflow, &pp->p, &pp->p_trial, &pp->Qu, &pp->Qu_trial, &pp->p_star, &pp->Hbar, &pp->Hbar_trial, &pp->Hbar_previous, &pp->Hp, &pp->Hp_trial, &pp->p_hydrostatic, &pp->p_total, &pp->p_total_trial, &pp->at_water_table, &pp->sealed_free_mask, &pp->sealed_inv_storage,
                 &pp->cavity, &pp->cavity_trial, &pp->drm_volume, &pp->drm_volume_trial, &pp->drm_flow, &pp->drm_flow_trial, &pp->drm_source, &pp->drm_source_previous, &pp->node_coordinates[0], &pp->node_coordinates[1], &pp->node_coordinates[2], &pp->node_volume, &pp->cavity_fraction, &pp->p_local, &pp->q_local})
    PetscCall(VecDestroy(v));
  PetscCall(DMDestroy(&pp->pdm));
  delete pp;
  *pore = nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode PorePressureTrial(PorePressure *pp, DM dm, const PetscScalar *u, PetscReal t, Vec f_pore) {
  PetscScalar *q;
  PetscFunctionBeginUser;
  // alpha Q u_{n+1}.
  PetscCall(VecZeroEntries(pp->q_local));
  PetscCall(VecGetArray(pp->q_local, &q));
  couplingTimesU(*pp, u, q);
  PetscCall(VecRestoreArray(pp->q_local, &q));
  PetscCall(localToGlobalSum(pp->pdm, pp->q_local, pp->Qu_trial));
  if (!pp->started) {
    // The first evaluation is the initial state: its alpha Q u is the reference.
    PetscCall(VecCopy(pp->Qu_trial, pp->Qu));
    pp->t       = t;
    pp->started = true;
  }
  // p_{n+1} = p* - S^{-1} [alpha Q (u_{n+1} - u_n) - h q - W] on free nodes; 0 elsewhere (W:
  // the DRM's volume source, porous/pore_pressure_drm.hpp; none without DRM).
  const double h = t - pp->t;
  PetscCall(diffuse(pp, h));
  PetscCall(VecCopy(pp->Hbar, pp->Hbar_trial));
  {
    PetscInt           n;
    PetscScalar       *pt;
    const PetscScalar *ps, *qt, *qc, *in, *inv, *mask, *w = nullptr;
    PetscCall(VecGetLocalSize(pp->p, &n));
    if (pp->drm_source) PetscCall(VecGetArrayRead(pp->drm_source, &w));
    PetscCall(VecGetArray(pp->p_trial, &pt));
    PetscCall(VecGetArrayRead(pp->p_star, &ps));
    PetscCall(VecGetArrayRead(pp->Qu_trial, &qt));
    PetscCall(VecGetArrayRead(pp->Qu, &qc));
    PetscCall(VecGetArrayRead(pp->inflow, &in));
    PetscCall(VecGetArrayRead(pp->inv_storage, &inv));
    PetscCall(VecGetArrayRead(pp->free_mask, &mask));
    for (PetscInt i = 0; i < n; ++i) pt[i] = mask[i] * (ps[i] - inv[i] * ((qt[i] - qc[i]) - h * in[i] - (w ? w[i] : 0.0)));
    if (w) PetscCall(VecRestoreArrayRead(pp->drm_source, &w));
    if (pp->cavitation) {
      // The floor on free nodes (a drained node holds p = 0 and no cavity: water fills it).
      PetscScalar       *vt;
      const PetscScalar *vn, *ph, *S;
      PetscCall(VecGetArray(pp->cavity_trial, &vt));
      PetscCall(VecGetArrayRead(pp->cavity, &vn));
      PetscCall(VecGetArrayRead(pp->p_hydrostatic, &ph));
      PetscCall(VecGetArrayRead(pp->storage, &S));
      for (PetscInt i = 0; i < n; ++i) {
        vt[i] = 0;
        if (PetscRealPart(mask[i]) == 0) continue;
        const physics::CavitatedPressure c = physics::cavitationFloor(PetscRealPart(pt[i] - inv[i] * vn[i]), pp->cavitation_pressure - PetscRealPart(ph[i]), PetscRealPart(S[i]));
        pt[i] = c.p;
        vt[i] = c.cavity;
      }
      PetscCall(VecRestoreArrayRead(pp->storage, &S));
      PetscCall(VecRestoreArrayRead(pp->p_hydrostatic, &ph));
      PetscCall(VecRestoreArrayRead(pp->cavity, &vn));
      PetscCall(VecRestoreArray(pp->cavity_trial, &vt));
    }
    PetscCall(VecRestoreArrayRead(pp->free_mask, &mask));
    PetscCall(VecRestoreArrayRead(pp->inv_storage, &inv));
    PetscCall(VecRestoreArrayRead(pp->inflow, &in));
    PetscCall(VecRestoreArrayRead(pp->Qu, &qc));
    PetscCall(VecRestoreArrayRead(pp->Qu_trial, &qt));
    PetscCall(VecRestoreArrayRead(pp->p_star, &ps));
    PetscCall(VecRestoreArray(pp->p_trial, &pt));
  }
  pp->t_trial = t;
  PetscCall(VecWAXPY(pp->p_total_trial, 1.0, pp->p_hydrostatic, pp->p_trial));
  // f_pore = alpha Q^T p and H p at the trial pressure (H p starts the next step's diffusion).
  Vec                f_local;
  PetscScalar       *f;
  const PetscScalar *pl;
  PetscCall(DMGlobalToLocal(pp->pdm, pp->p_trial, INSERT_VALUES, pp->p_local));
  PetscCall(DMGetLocalVector(dm, &f_local));
  PetscCall(VecZeroEntries(f_local));
  PetscCall(VecZeroEntries(pp->q_local));
  PetscCall(VecGetArray(f_local, &f));
  PetscCall(VecGetArray(pp->q_local, &q));
  PetscCall(VecGetArrayRead(pp->p_local, &pl));
  couplingTransposeAndDiffusion(*pp, pl, f, q);
  PetscCall(VecRestoreArrayRead(pp->p_local, &pl));
  PetscCall(VecRestoreArray(pp->q_local, &q));
  PetscCall(VecRestoreArray(f_local, &f));
  PetscCall(VecZeroEntries(f_pore));
  PetscCall(DMLocalToGlobal(dm, f_local, ADD_VALUES, f_pore));
  PetscCall(DMRestoreLocalVector(dm, &f_local));
  PetscCall(localToGlobalSum(pp->pdm, pp->q_local, pp->Hp_trial));
  PetscFunctionReturn(0);
}

// Degree p > 1: sub-steps that keep the diffusion's amplification non-negative, which the
// stable step's coupling factor assumes (PorePressureCouplingFactor).
PetscInt PorePressureSubsteps(const PorePressure *pp, double h) { return physics::diffusionSubstepsOfDegree((int)pp->degree, h, pp->dt_diffusion, pp->subcycle); }

double PorePressureCouplingFactor(const PorePressure *pp, double h) {
  return pp->degree > 1 ? physics::splitCouplingFactor(h, pp->dt_diffusion, pp->subcycle) : 1.0;
}

PetscErrorCode PorePressureDiffuseStep(PorePressure *pp, PetscReal h) { return diffuse(pp, h); }

PetscErrorCode PorePressureCommit(PorePressure *pp) {
  PetscFunctionBeginUser;
  if (!pp) PetscFunctionReturn(0);
  if (pp->cavitation) {
    // The step's work on the cavities of the nodes free in it (free_mask is still the
    // trial's: gaps drain after the commit), and the cavities now open.
    PetscInt           n;
    const PetscScalar *p0, *p1, *v0, *v1, *mask, *x[3] = {nullptr, nullptr, nullptr};
    pp->cavity_work_step = 0;
    pp->cavities_local   = 0;
    PetscCall(VecGetLocalSize(pp->p, &n));
    PetscCall(VecGetArrayRead(pp->p, &p0));
    PetscCall(VecGetArrayRead(pp->p_trial, &p1));
    PetscCall(VecGetArrayRead(pp->cavity, &v0));
    PetscCall(VecGetArrayRead(pp->cavity_trial, &v1));
    PetscCall(VecGetArrayRead(pp->free_mask, &mask));
    for (PetscInt d = 0; d < pp->dim; ++d) PetscCall(VecGetArrayRead(pp->node_coordinates[d], &x[d]));
    for (PetscInt i = 0; i < n; ++i) {
      if (PetscRealPart(mask[i]) == 0) continue;
      pp->cavity_work_step += physics::cavityWork(PetscRealPart(p0[i]), PetscRealPart(p1[i]), PetscRealPart(v0[i]), PetscRealPart(v1[i]));
      if (PetscRealPart(v1[i]) <= 0) continue;
      ++pp->cavities_local;
      if (PetscRealPart(v1[i]) > pp->largest_cavity) {
        pp->largest_cavity      = PetscRealPart(v1[i]);
        pp->largest_cavity_time = pp->t_trial;
        for (PetscInt d = 0; d < pp->dim; ++d) pp->largest_cavity_at[d] = PetscRealPart(x[d][i]);
      }
    }
    for (PetscInt d = 0; d < pp->dim; ++d) PetscCall(VecRestoreArrayRead(pp->node_coordinates[d], &x[d]));
    PetscCall(VecRestoreArrayRead(pp->free_mask, &mask));
    PetscCall(VecRestoreArrayRead(pp->cavity_trial, &v1));
    PetscCall(VecRestoreArrayRead(pp->cavity, &v0));
    PetscCall(VecRestoreArrayRead(pp->p_trial, &p1));
    PetscCall(VecRestoreArrayRead(pp->p, &p0));
    std::swap(pp->cavity, pp->cavity_trial);
  }
  std::swap(pp->p, pp->p_trial);
  std::swap(pp->Qu, pp->Qu_trial);
  std::swap(pp->Hbar_previous, pp->Hbar_trial);
  std::swap(pp->Hp, pp->Hp_trial);
  if (pp->drm_source) {
    std::swap(pp->drm_volume, pp->drm_volume_trial);
    std::swap(pp->drm_flow, pp->drm_flow_trial);
    std::swap(pp->drm_source_previous, pp->drm_source);
  }
  pp->t          = pp->t_trial;
  pp->diffused_h = -1;
  PetscFunctionReturn(0);
}

namespace {
// rows += the local per-dof rows in f_local (displacement layout), summed over the ranks.
PetscErrorCode addLocalRows(DM dm, Vec f_local, Vec rows) {
  Vec extra;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(rows, &extra));
  PetscCall(VecZeroEntries(extra));
  PetscCall(DMLocalToGlobal(dm, f_local, ADD_VALUES, extra));
  PetscCall(VecAXPY(rows, 1.0, extra));
  PetscCall(VecDestroy(&extra));
  PetscFunctionReturn(0);
}

// Degree p > 1 (PorePressureAddUndrainedRows): lambda_m alpha w|J| on each dof of each node of
// each element, lambda_m the bound of distinct matrix m's stiffening over diag(alpha w|J|):
// that of the elastic element with lambda = alpha M on the weights alpha w|J| (lambda alpha w|J|
// = alpha^2 M w|J|), mu = 0 and unit density.
PetscErrorCode addSpectralUndrainedRows(PorePressure *pp, DM dm, Vec rows) {
  const PetscInt      nen = pp->nen, dim = pp->dim;
  std::vector<double> bound(pp->matrix_region.size(), -1.0);
  Vec                 f_local;
  PetscScalar        *f;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dm, &f_local));
  PetscCall(VecZeroEntries(f_local));
  PetscCall(VecGetArray(f_local, &f));
  for (size_t i = 0; i < pp->cells.size(); ++i) {
    const PetscInt m = pp->cell_matrix[i];
    const double  *w = &pp->coupling_weight[(size_t)m * nen];
    if (bound[m] < 0) {
      const SaturatedRegion &r = pp->regions[pp->matrix_region[m]];
      bound[m] = fem::spectralElementEigenBound((int)dim, (int)pp->degree, w, &pp->inverse_jacobian[(size_t)m * nen * dim * dim], fem::LameParameters{r.alpha * r.M, 0.0},
                                                1.0, pp->bound_kind);
    }
    for (PetscInt a = 0; a < nen; ++a)
      for (PetscInt j = 0; j < dim; ++j) f[pp->cell_u[i * nen + a] + j] += bound[m] * w[a];
  }
  PetscCall(VecRestoreArray(f_local, &f));
  PetscCall(addLocalRows(dm, f_local, rows));
  PetscCall(DMRestoreLocalVector(dm, &f_local));
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode PorePressureAddUndrainedRows(PorePressure *pp, DM dm, Vec rows) {
  const PetscInt nen = pp->nen, dim = pp->dim, nd = nen * dim;
  Vec            w, f_local;
  PetscScalar   *q, *f;
  const PetscScalar *wl;
  PetscFunctionBeginUser;
  if (pp->degree > 1) {
    PetscCall(addSpectralUndrainedRows(pp, dm, rows));
    PetscFunctionReturn(0);
  }
  // w_a = sum_k |alpha Q_ak| / S_a on free pressure nodes.
  PetscCall(VecDuplicate(pp->storage, &w));
  PetscCall(VecZeroEntries(pp->q_local));
  PetscCall(VecGetArray(pp->q_local, &q));
  for (size_t i = 0; i < pp->cells.size(); ++i) {
    const double *Q = &pp->coupling[(size_t)pp->cell_matrix[i] * nen * nd];
    for (PetscInt r = 0; r < nen; ++r)
      for (PetscInt k = 0; k < nd; ++k) q[pp->cell_p[i * nen + r]] += std::fabs(Q[r * nd + k]);
  }
  PetscCall(VecRestoreArray(pp->q_local, &q));
  PetscCall(localToGlobalSum(pp->pdm, pp->q_local, w));
  PetscCall(VecPointwiseMult(w, w, pp->inv_storage));
  PetscCall(DMGlobalToLocal(pp->pdm, w, INSERT_VALUES, pp->q_local));
  // rows_(b,j) += sum_a |alpha Q_a,bj| w_a  >=  sum_(c,k) |(alpha^2 Q^T S^-1 Q)_(bj),(ck)|.
  PetscCall(DMGetLocalVector(dm, &f_local));
  PetscCall(VecZeroEntries(f_local));
  PetscCall(VecGetArray(f_local, &f));
  PetscCall(VecGetArrayRead(pp->q_local, &wl));
  for (size_t i = 0; i < pp->cells.size(); ++i) {
    const double *Q = &pp->coupling[(size_t)pp->cell_matrix[i] * nen * nd];
    for (PetscInt b = 0; b < nen; ++b)
      for (PetscInt j = 0; j < dim; ++j)
        for (PetscInt r = 0; r < nen; ++r) f[pp->cell_u[i * nen + b] + j] += std::fabs(Q[r * nd + b * dim + j]) * PetscRealPart(wl[pp->cell_p[i * nen + r]]);
  }
  PetscCall(VecRestoreArrayRead(pp->q_local, &wl));
  PetscCall(VecRestoreArray(f_local, &f));
  PetscCall(addLocalRows(dm, f_local, rows));
  PetscCall(DMRestoreLocalVector(dm, &f_local));
  PetscCall(VecDestroy(&w));
  PetscFunctionReturn(0);
}

namespace {
// (1/2) [p S p - h p (alpha Q v_{n+1/2}) - h p Hbar + h p q] summed over the nodes held this
// step that still hold p_n != 0 (PorePressureEnergy).
PetscErrorCode gapReleasedEnergy(PorePressure *pp, DM dm, PetscReal h, Vec v, Vec a, double *released) {
  Vec                v_half, v_local, Qv;
  PetscScalar       *q;
  const PetscScalar *vl;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(v, &v_half));
  PetscCall(VecWAXPY(v_half, 0.5 * h, a, v));
  PetscCall(DMGetLocalVector(dm, &v_local));
  PetscCall(DMGlobalToLocal(dm, v_half, INSERT_VALUES, v_local));
  PetscCall(VecZeroEntries(pp->q_local));
  PetscCall(VecGetArray(pp->q_local, &q));
  PetscCall(VecGetArrayRead(v_local, &vl));
  couplingTimesU(*pp, vl, q);
  PetscCall(VecRestoreArrayRead(v_local, &vl));
  PetscCall(VecRestoreArray(pp->q_local, &q));
  PetscCall(DMRestoreLocalVector(dm, &v_local));
  PetscCall(VecDestroy(&v_half));
  PetscCall(VecDuplicate(pp->p, &Qv));
  PetscCall(localToGlobalSum(pp->pdm, pp->q_local, Qv));
  PetscInt           n;
  const PetscScalar *p, *S, *hp, *in, *mask, *qv;
  double             sum = 0;
  PetscCall(VecGetLocalSize(pp->p, &n));
  PetscCall(VecGetArrayRead(pp->p, &p));
  PetscCall(VecGetArrayRead(pp->storage, &S));
  PetscCall(VecGetArrayRead(pp->Hbar, &hp));
  PetscCall(VecGetArrayRead(pp->inflow, &in));
  PetscCall(VecGetArrayRead(pp->free_mask, &mask));
  PetscCall(VecGetArrayRead(Qv, &qv));
  for (PetscInt k = 0; k < n; ++k)
    if (PetscRealPart(mask[k]) == 0 && p[k] != 0.0) sum += 0.5 * PetscRealPart(p[k] * (S[k] * p[k] - h * qv[k] - h * hp[k] + h * in[k]));
  PetscCall(VecRestoreArrayRead(Qv, &qv));
  PetscCall(VecRestoreArrayRead(pp->free_mask, &mask));
  PetscCall(VecRestoreArrayRead(pp->inflow, &in));
  PetscCall(VecRestoreArrayRead(pp->Hbar, &hp));
  PetscCall(VecRestoreArrayRead(pp->storage, &S));
  PetscCall(VecRestoreArrayRead(pp->p, &p));
  PetscCall(VecDestroy(&Qv));
  PetscCallMPI(MPI_Allreduce(&sum, released, 1, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)v)));
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode PorePressureEnergy(PorePressure *pp, DM dm, PetscReal h, Vec v, Vec a, Vec f_pore, Vec free_mask, PoreEnergy *e) {
  PetscFunctionBeginUser;
  // Local sums, reduced once: 0 v_{n+1/2} . f_pore, 1 v_n . f_pore on held dofs, 2 p S p,
  // 3 p . Hbar_n, 4 p . Hbar_{n-1}, 5 p . q, 6 nodes held this step with p_n != 0, 7 the work
  // on the cavities in the step that led to t_n, 8 the nodes with a cavity at t_n, 9 p . W_{n+1/2},
  // 10 p . W_{n-1/2} (DRM's volume source, free nodes).
  PetscCall(diffuse(pp, h)); // Hbar_n of the step about to be taken
  double s[11] = {0, 0, 0, 0, 0, 0, 0, pp->cavity_work_step, (double)pp->cavities_local, 0, 0};
  pp->cavity_work_step = 0; // booked once
  {
    PetscInt           n;
    const PetscScalar *va, *aa, *fp, *mask;
    PetscCall(VecGetLocalSize(v, &n));
    PetscCall(VecGetArrayRead(v, &va));
    PetscCall(VecGetArrayRead(a, &aa));
    PetscCall(VecGetArrayRead(f_pore, &fp));
    PetscCall(VecGetArrayRead(free_mask, &mask));
    for (PetscInt k = 0; k < n; ++k) {
      s[0] += PetscRealPart((va[k] + 0.5 * h * aa[k]) * fp[k]);
      s[1] += PetscRealPart((1.0 - mask[k]) * va[k] * fp[k]);
    }
    PetscCall(VecRestoreArrayRead(free_mask, &mask));
    PetscCall(VecRestoreArrayRead(f_pore, &fp));
    PetscCall(VecRestoreArrayRead(a, &aa));
    PetscCall(VecRestoreArrayRead(v, &va));
  }
  {
    PetscInt           n;
    const PetscScalar *p, *S, *hp, *hq, *q, *mask;
    PetscCall(VecGetLocalSize(pp->p, &n));
    PetscCall(VecGetArrayRead(pp->p, &p));
    PetscCall(VecGetArrayRead(pp->storage, &S));
    PetscCall(VecGetArrayRead(pp->Hbar, &hp));
    PetscCall(VecGetArrayRead(pp->Hbar_previous, &hq));
    PetscCall(VecGetArrayRead(pp->inflow, &q));
    PetscCall(VecGetArrayRead(pp->free_mask, &mask));
    for (PetscInt k = 0; k < n; ++k) {
      s[2] += PetscRealPart(p[k] * S[k] * p[k]);
      s[3] += PetscRealPart(p[k] * hp[k]);
      s[4] += PetscRealPart(p[k] * hq[k]);
      s[5] += PetscRealPart(p[k] * q[k]);
      if (PetscRealPart(mask[k]) == 0 && p[k] != 0.0) s[6] += 1;
    }
    if (pp->drm_source) {
      const PetscScalar *w, *wp;
      PetscCall(VecGetArrayRead(pp->drm_source, &w));
      PetscCall(VecGetArrayRead(pp->drm_source_previous, &wp));
      for (PetscInt k = 0; k < n; ++k) {
        s[9] += PetscRealPart(mask[k] * p[k] * w[k]);
        s[10] += PetscRealPart(mask[k] * p[k] * wp[k]);
      }
      PetscCall(VecRestoreArrayRead(pp->drm_source_previous, &wp));
      PetscCall(VecRestoreArrayRead(pp->drm_source, &w));
    }
    PetscCall(VecRestoreArrayRead(pp->free_mask, &mask));
    PetscCall(VecRestoreArrayRead(pp->inflow, &q));
    PetscCall(VecRestoreArrayRead(pp->Hbar_previous, &hq));
    PetscCall(VecRestoreArrayRead(pp->Hbar, &hp));
    PetscCall(VecRestoreArrayRead(pp->storage, &S));
    PetscCall(VecRestoreArrayRead(pp->p, &p));
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, s, 11, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)v)));
  // The storage identity with cavities: S (p_{n+1} - p_n) gains V_{n+1} - V_n, so the shadow
  // energy below (written without them) changes by -cavityWork more than the terms it books;
  // the ledger books the cavities' work beside the Darcy dissipation.
  e->cavitation      = s[7];
  pp->cavities_now   = (PetscInt)s[8];
  pp->cavities_max   = std::max(pp->cavities_max, pp->cavities_now);
  if (pp->cavities_now > 0) {
    if (pp->cavitation_first < 0) pp->cavitation_first = pp->t;
    pp->cavitation_last = pp->t;
  }
  // S p_{n+1} = S p_n - h alpha Q v_{n+1/2} - h (Hbar_n - q) + W_{n+1/2} on free nodes, p = 0
  // on the others, and p_n . alpha Q v = v . alpha Q^T p_n = v . f_pore.
  e->storage    = 0.5 * (s[2] - h * s[0] - h * s[3] + h * s[5] + s[9]);
  e->drm_input  = 0.5 * (s[9] + s[10]);
  e->darcy      = 0.5 * h * (s[3] + s[4]);
  if (s[6] > 0) {
    // Nodes drained from this step on while holding p_n (a gap opened over them): the sums
    // above gave each the storage equation's F_{n+1/2}; it holds none, so that energy leaves.
    double released = 0;
    PetscCall(gapReleasedEnergy(pp, dm, h, v, a, &released));
    e->storage -= released;
    e->darcy += released;
  }
  e->inflow     = h * s[5];
  e->held_power = s[1];
  PetscFunctionReturn(0);
}

PetscErrorCode PorePressureCavityFraction(PorePressure *pp) {
  PetscInt           n;
  PetscScalar       *fr;
  const PetscScalar *v, *vol;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(pp->cavity, &n));
  PetscCall(VecGetArray(pp->cavity_fraction, &fr));
  PetscCall(VecGetArrayRead(pp->cavity, &v));
  PetscCall(VecGetArrayRead(pp->node_volume, &vol));
  for (PetscInt i = 0; i < n; ++i) fr[i] = PetscRealPart(vol[i]) > 0 ? v[i] / vol[i] : 0.0;
  PetscCall(VecRestoreArrayRead(pp->node_volume, &vol));
  PetscCall(VecRestoreArrayRead(pp->cavity, &v));
  PetscCall(VecRestoreArray(pp->cavity_fraction, &fr));
  PetscFunctionReturn(0);
}

PetscErrorCode PorePressureCavitationReport(const PorePressure *pp, MPI_Comm comm, double work, std::string *line) {
  PetscFunctionBeginUser;
  char buf[512];
  if (!pp->cavitation) {
    *line = "cavitation: none (-fluid_cavitation_pressure none: the pore pressure has no lower limit)";
    PetscFunctionReturn(0);
  }
  if (pp->cavities_max == 0) {
    std::snprintf(buf, sizeof buf, "cavitation: none (the total pore pressure stayed above -fluid_cavitation_pressure = %g Pa)", pp->cavitation_pressure);
    *line = buf;
    PetscFunctionReturn(0);
  }
  // The largest cavity over the ranks, with its time and place from the rank that holds it.
  struct {
    double      value;
    PetscMPIInt rank;
  } mine{pp->largest_cavity, 0}, top;
  PetscCallMPI(MPI_Comm_rank(comm, &mine.rank));
  PetscCallMPI(MPI_Allreduce(&mine, &top, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm));
  double where[4] = {pp->largest_cavity_time, pp->largest_cavity_at[0], pp->largest_cavity_at[1], pp->largest_cavity_at[2]};
  PetscCallMPI(MPI_Bcast(where, 4, MPI_DOUBLE, top.rank, comm));
  const std::string at = pp->dim == 2 ? "(" + std::to_string(where[1]) + ", " + std::to_string(where[2]) + ")"
                                      : "(" + std::to_string(where[1]) + ", " + std::to_string(where[2]) + ", " + std::to_string(where[3]) + ")";
  std::snprintf(buf, sizeof buf,
                "cavitation (-fluid_cavitation_pressure = %g Pa): pore pressure held at the limit from t = %.4g to %.4g s, at most %" PetscInt_FMT " nodes at once (%" PetscInt_FMT
                " at the end); largest cavity %.3g m^3%s at t = %.4g s, node %s m; work on the cavities %.4g J (energy.csv cavitation_work)",
                pp->cavitation_pressure, pp->cavitation_first, pp->cavitation_last, pp->cavities_max, pp->cavities_now, top.value, pp->dim == 2 ? " per m" : "", where[0],
                at.c_str(), work);
  *line = buf;
  PetscFunctionReturn(0);
}

} // namespace slipwave::porous

#include "slipwave/fem/spectral_operator.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include "slipwave/fem/geometry_key.hpp"
#include "slipwave/fem/spectral_force_kernel.hpp"
#include "slipwave/numerics/gll_basis.hpp"

namespace slipwave::fem {
namespace {

// Explicit vector types, as in the Q1 loop: the default tuning vectorises at 128 bits only.
constexpr int kBatch = 8;
static_assert(sizeof(SpectralOperator::FactorLanes) == kBatch * sizeof(double), "one factor vector per lane batch");
typedef double BatchVec __attribute__((vector_size(kBatch * sizeof(double))));

// Kinds of groups of a Subset's plan.
enum GroupKind : PetscInt { kShared = 0, kLanes = 1, kSingle = 2 };

struct Tables {
  const PetscInt       *node_offset, *region;
  const double         *wdet, *jinv, *D;
  const RegionMaterial *materials, *record_material; // per region, per record
};

using Subset = SpectralOperator::Subset;

// f += K u over the plan of s. Batches are gathered transposed (lane b = element b), pushed
// through the kernel once, and scattered in element order (elements share nodes).
template <int P, int DIM>
void applyPlan(const Subset &s, const Tables &t, const PetscScalar *__restrict u, PetscScalar *__restrict f) {
  constexpr int NQ = SpectralShape<P, DIM>::NQ;
  BatchVec      ue[DIM * NQ], fe[DIM * NQ];
  for (size_t g = 0; g + 2 < s.groups.size(); g += 3) {
    const PetscInt  kind = s.groups[g], data = s.groups[g + 2];
    const PetscInt *elements = s.elements.data() + s.groups[g + 1];
    if (kind == kSingle) {
      const PetscInt *__restrict off = t.node_offset + (size_t)elements[0] * NQ;
      const LameParameters &m        = t.record_material[data].lame;
      double                ve[DIM * NQ], vf[DIM * NQ];
      for (int q = 0; q < NQ; ++q)
        for (int c = 0; c < DIM; ++c) ve[c * NQ + q] = u[off[q] + c];
      spectralForce<P, DIM, double>(t.D, t.wdet + (size_t)data * NQ, t.jinv + (size_t)data * NQ * DIM * DIM, m.lambda, m.mu, ve, vf);
      for (int q = 0; q < NQ; ++q)
        for (int c = 0; c < DIM; ++c) f[off[q] + c] += vf[c * NQ + q];
      continue;
    }
    for (int b = 0; b < kBatch; ++b) {
      const PetscInt *__restrict off = t.node_offset + (size_t)elements[b] * NQ;
      for (int q = 0; q < NQ; ++q)
        for (int c = 0; c < DIM; ++c) ue[c * NQ + q][b] = u[off[q] + c];
    }
    if (kind == kShared) {
      const LameParameters &m = t.record_material[data].lame;
      spectralForce<P, DIM, BatchVec>(t.D, t.wdet + (size_t)data * NQ, t.jinv + (size_t)data * NQ * DIM * DIM, m.lambda, m.mu, ue, fe);
    } else {
      const LameParameters &m     = t.materials[t.region[elements[0]]].lame;
      const BatchVec       *lanes = reinterpret_cast<const BatchVec *>(s.lane_factors.data()) + data;
      spectralForce<P, DIM, BatchVec, BatchVec>(t.D, lanes, lanes + NQ, m.lambda, m.mu, ue, fe);
    }
    for (int b = 0; b < kBatch; ++b) {
      const PetscInt *__restrict off = t.node_offset + (size_t)elements[b] * NQ;
      for (int q = 0; q < NQ; ++q)
        for (int c = 0; c < DIM; ++c) f[off[q] + c] += fe[c * NQ + q][b];
    }
  }
}

using ApplyFn = void (*)(const Subset &, const Tables &, const PetscScalar *, PetscScalar *);

template <int DIM>
ApplyFn applyOfDegree(PetscInt p) {
  switch (p) {
  case 1: return applyPlan<1, DIM>;
  case 2: return applyPlan<2, DIM>;
  case 3: return applyPlan<3, DIM>;
  case 4: return applyPlan<4, DIM>;
  case 5: return applyPlan<5, DIM>;
  case 6: return applyPlan<6, DIM>;
  case 7: return applyPlan<7, DIM>;
  case 8: return applyPlan<8, DIM>;
  default: return nullptr;
  }
}

} // namespace

PetscErrorCode SpectralOperator::Setup(PetscInt dim, PetscInt degree, PetscInt nelem, const double *coords, const PetscInt *node_offset, const PetscInt *region,
                                       const std::vector<RegionMaterial> &materials) {
  PetscFunctionBeginUser;
  PetscCheck((dim == 2 || dim == 3) && degree >= 1 && degree <= numerics::kMaxSpectralDegree, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "spectral elements: dimension %" PetscInt_FMT " degree %" PetscInt_FMT "; allowed: dimension 2 or 3, degree 1 to %d", dim, degree, numerics::kMaxSpectralDegree);
  dim_ = dim, degree_ = degree, nelem_ = nelem, nq_ = spectralNodeCount((int)dim, (int)degree);
  materials_ = materials;
  node_offset_.assign(node_offset, node_offset + (size_t)nelem * nq_);
  region_.assign(region, region + nelem);
  coords_.assign(coords, coords + (size_t)nelem * nq_ * dim);
  double x[kMaxSpectralNodes1D], w[kMaxSpectralNodes1D];
  D_.resize((degree + 1) * (degree + 1));
  numerics::gllPointsWeights((int)degree, x, w);
  numerics::lagrangeDerivativeMatrix((int)degree, x, D_.data());

  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (size_t a = 0; a < (size_t)nelem * nq_; ++a)
    for (PetscInt i = 0; i < dim; ++i) lo[i] = std::min(lo[i], coords[a * dim + i]), hi[i] = std::max(hi[i], coords[a * dim + i]);
  double extent = 0;
  for (PetscInt i = 0; i < dim; ++i) extent = std::max(extent, hi[i] - lo[i]);
  // The same sharing rule as the Q1 operator: relative positions rounded to 1e-12 of the extent.
  const double quantum = 1e-12 * (extent > 0 ? extent : 1.0);

  std::unordered_map<std::string, PetscInt> seen;
  record_.resize(nelem);
  record_material_.clear();
  wdet_.clear();
  jinv_.clear();
  for (PetscInt e = 0; e < nelem; ++e) {
    PetscCheck(region[e] >= 0 && region[e] < (PetscInt)materials.size(), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "spectral element %" PetscInt_FMT " has region %" PetscInt_FMT " of %zu", e,
               region[e], materials.size());
    const double *xe = elementCoordinates(e);
    std::string   key = geometryKey(region[e], xe, (int)nq_, (int)dim, quantum);
    auto found = seen.find(key);
    if (found != seen.end()) {
      record_[e] = found->second;
      continue;
    }
    const PetscInt r = (PetscInt)record_material_.size();
    seen.emplace(std::move(key), r);
    record_[e] = r;
    record_material_.push_back(materials[region[e]]);
    wdet_.resize((size_t)(r + 1) * nq_);
    jinv_.resize((size_t)(r + 1) * nq_ * dim * dim);
    PetscCheck(spectralGeometry((int)dim, (int)degree, xe, &wdet_[(size_t)r * nq_], &jinv_[(size_t)r * nq_ * dim * dim]), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
               "spectral element %" PetscInt_FMT " (first node at %g %g %g) is folded or degenerate: det J vanishes or changes sign at its GLL nodes", e, xe[0], xe[1],
               dim == 3 ? xe[2] : 0.0);
  }
  std::vector<PetscInt> all(nelem);
  for (PetscInt e = 0; e < nelem; ++e) all[e] = e;
  all_ = subset(all);
  PetscFunctionReturn(0);
}

void SpectralOperator::addStiffnessTimes(const PetscScalar *u, PetscScalar *f) const {
  addStiffnessTimes(all_, u, f);
}

SpectralOperator::Subset SpectralOperator::subset(const std::vector<PetscInt> &elements) const {
  Subset         s;
  const PetscInt n = (PetscInt)elements.size(), nf = nq_ * (1 + dim_ * dim_);
  s.elements       = elements;
  PetscInt i       = 0;
  while (i < n) {
    const PetscInt r   = record_[elements[i]];
    PetscInt       run = 1, same_region = 1;
    while (run < kBatch && i + run < n && record_[elements[i + run]] == r) ++run;
    while (same_region < kBatch && i + same_region < n && region_[elements[i + same_region]] == region_[elements[i]]) ++same_region;
    if (run == kBatch) {
      s.groups.insert(s.groups.end(), {kShared, i, r});
      i += kBatch;
    } else if (same_region == kBatch) {
      // Lane b's factors at node q: wdet in vector q, jinv entry j in vector nq + q dim^2 + j.
      const size_t offset = s.lane_factors.size();
      s.lane_factors.resize(offset + nf);
      FactorLanes *block = &s.lane_factors[offset];
      for (int b = 0; b < kBatch; ++b) {
        const PetscInt rb = record_[elements[i + b]];
        for (PetscInt q = 0; q < nq_; ++q) block[q].lane[b] = wdet_[(size_t)rb * nq_ + q];
        for (PetscInt j = 0; j < nq_ * dim_ * dim_; ++j) block[nq_ + j].lane[b] = jinv_[(size_t)rb * nq_ * dim_ * dim_ + j];
      }
      s.groups.insert(s.groups.end(), {kLanes, i, (PetscInt)offset});
      i += kBatch;
    } else {
      s.groups.insert(s.groups.end(), {kSingle, i, r});
      i += 1;
    }
  }
  return s;
}

void SpectralOperator::addStiffnessTimes(const Subset &s, const PetscScalar *u, PetscScalar *f) const {
  const Tables  t{node_offset_.data(), region_.data(), wdet_.data(), jinv_.data(), D_.data(), materials_.data(), record_material_.data()};
  const ApplyFn fn = dim_ == 2 ? applyOfDegree<2>(degree_) : applyOfDegree<3>(degree_);
  fn(s, t, u, f);
}

void SpectralOperator::addLumpedMass(PetscScalar *mass, bool deforming_only) const {
  for (PetscInt e = 0; e < nelem_; ++e) {
    const PetscInt r = record_[e];
    if (deforming_only && !record_material_[r].deforms) continue;
    for (PetscInt a = 0; a < nq_; ++a)
      for (PetscInt c = 0; c < dim_; ++c) mass[node_offset_[e * nq_ + a] + c] += record_material_[r].rho * wdet_[(size_t)r * nq_ + a];
  }
}

void SpectralOperator::addStiffnessRowAbsSums(PetscScalar *rowabs) const {
  const PetscInt      n = nq_ * dim_;
  std::vector<double> sums((size_t)distinctGeometries() * n);
  for (PetscInt r = 0; r < distinctGeometries(); ++r)
    spectralElementRowAbsSums((int)dim_, (int)degree_, &wdet_[(size_t)r * nq_], &jinv_[(size_t)r * nq_ * dim_ * dim_], record_material_[r].lame, &sums[(size_t)r * n]);
  for (PetscInt e = 0; e < nelem_; ++e)
    for (PetscInt a = 0; a < nq_; ++a)
      for (PetscInt c = 0; c < dim_; ++c) rowabs[node_offset_[e * nq_ + a] + c] += sums[(size_t)record_[e] * n + a * dim_ + c];
}

double SpectralOperator::maxElementEigenBound(EigenBoundKind kind) const {
  double bound = 0;
  for (PetscInt r = 0; r < distinctGeometries(); ++r)
    if (record_material_[r].deforms)
      bound = std::max(bound, spectralElementEigenBound((int)dim_, (int)degree_, &wdet_[(size_t)r * nq_], &jinv_[(size_t)r * nq_ * dim_ * dim_], record_material_[r].lame,
                                                      record_material_[r].rho, kind));
  return bound;
}

void SpectralOperator::elementStiffness(PetscInt e, double *K) const {
  const PetscInt r = record_[e];
  spectralElementStiffness((int)dim_, (int)degree_, &wdet_[(size_t)r * nq_], &jinv_[(size_t)r * nq_ * dim_ * dim_], record_material_[r].lame, K);
}

void SpectralOperator::elementForce(PetscInt e, const double *ue, double *fe) const {
  const PetscInt r = record_[e];
  spectralElementForce((int)dim_, (int)degree_, D_.data(), &wdet_[(size_t)r * nq_], &jinv_[(size_t)r * nq_ * dim_ * dim_], record_material_[r].lame, ue, fe);
}

void SpectralOperator::stressAt(PetscInt e, const double *xi, const PetscScalar *u, double *sigma, const LameParameters *lame) const {
  double ue[kMaxSpectralDofs];
  for (PetscInt a = 0; a < nq_; ++a)
    for (PetscInt c = 0; c < dim_; ++c) ue[a * dim_ + c] = PetscRealPart(u[node_offset_[e * nq_ + a] + c]);
  // Setup checked the map at the nodes; the degree-p map of a valid element stays regular inside.
  spectralStress((int)dim_, (int)degree_, elementCoordinates(e), lame ? *lame : record_material_[record_[e]].lame, ue, xi, sigma);
}

} // namespace slipwave::fem

#include "slipwave/fem/anelastic_operator.hpp"

namespace slipwave::fem {
namespace {

constexpr int kMaxMechanisms = 8;

// One pass over the damped cells: K_U u_e (recomputed: the K u loop keeps no per-cell result,
// so the undamped path pays nothing), the trial memory variables and their force. NEN, DIM
// compile-time as in the K u loop.
template <int NEN, int DIM>
void memoryForce(const BulkOperator &bulk, const std::vector<PetscInt> &cells, const std::vector<PetscInt> &cell_model, const double *weights, PetscInt L,
                 const physics::MemoryUpdate *upd, const double *__restrict committed, double *__restrict trial, const PetscScalar *__restrict u,
                 PetscScalar *__restrict f) {
  constexpr int N      = NEN * DIM;
  const size_t  stride = (size_t)(L + 1) * N;
  double        ue[N], ku[N], fe[N], a[kMaxMechanisms], b[kMaxMechanisms];
  for (size_t i = 0; i < cells.size(); ++i) {
    const PetscInt c = cells[i];
    for (int n = 0; n < NEN; ++n)
      for (int d = 0; d < DIM; ++d) ue[n * DIM + d] = u[bulk.cellNodeOffset(c, n) + d];
    const double *__restrict K = bulk.cellStiffness(c);
    for (int r = 0; r < N; ++r) {
      double s = 0;
      for (int j = 0; j < N; ++j) s += K[r * N + j] * ue[j];
      ku[r] = s;
      fe[r] = 0;
    }
    const double *y = weights + cell_model[i] * L;
    for (PetscInt l = 0; l < L; ++l) {
      a[l] = y[l] * upd[l].end;
      b[l] = y[l] * upd[l].start;
    }
    const double *__restrict old = committed + i * stride;
    double *__restrict nw        = trial + i * stride;
    const double *__restrict ku_old = old + L * N;
    for (PetscInt l = 0; l < L; ++l) {
      const double d = upd[l].decay;
      for (int r = 0; r < N; ++r) {
        const double z = d * old[l * N + r] + a[l] * ku[r] + b[l] * ku_old[r];
        nw[l * N + r]  = z;
        fe[r] += z;
      }
    }
    for (int r = 0; r < N; ++r) nw[L * N + r] = ku[r];
    for (int n = 0; n < NEN; ++n)
      for (int d = 0; d < DIM; ++d) f[bulk.cellNodeOffset(c, n) + d] += fe[n * DIM + d];
  }
}

} // namespace

void AnelasticOperator::Setup(const BulkOperator &bulk, const std::vector<physics::ConstantQModel> &region_models) {
  cells_.clear();
  cell_model_.clear();
  omega_.clear();
  weights_.clear();
  mechanisms_ = 0;
  ndof_       = bulk.nodesPerCell() * bulk.dimension();
  std::vector<PetscInt> model_of_region(region_models.size(), -1);
  PetscInt              nmodels = 0;
  for (size_t r = 0; r < region_models.size(); ++r) {
    const auto &m = region_models[r];
    if (m.omega.empty()) continue;
    omega_      = m.omega;
    mechanisms_ = (PetscInt)m.omega.size();
    weights_.insert(weights_.end(), m.weight.begin(), m.weight.end());
    model_of_region[r] = nmodels++;
  }
  for (PetscInt c = 0; c < bulk.cellCount(); ++c) {
    const PetscInt m = model_of_region[bulk.cellRegion(c)];
    if (m < 0) continue;
    cells_.push_back(c);
    cell_model_.push_back(m);
  }
  committed_.assign(cells_.size() * (mechanisms_ + 1) * ndof_, 0.0);
  trial_ = committed_;
}

void AnelasticOperator::addMemoryForce(const BulkOperator &bulk, const PetscScalar *u, double h, PetscScalar *f) {
  if (cells_.empty()) return;
  physics::MemoryUpdate upd[kMaxMechanisms];
  for (PetscInt l = 0; l < mechanisms_; ++l) upd[l] = physics::memoryUpdate(omega_[l], h);
  const double *cm = committed_.data();
  double       *tr = trial_.data();
  switch (ndof_) {
  case 6: memoryForce<3, 2>(bulk, cells_, cell_model_, weights_.data(), mechanisms_, upd, cm, tr, u, f); break;
  case 8: memoryForce<4, 2>(bulk, cells_, cell_model_, weights_.data(), mechanisms_, upd, cm, tr, u, f); break;
  case 12: memoryForce<4, 3>(bulk, cells_, cell_model_, weights_.data(), mechanisms_, upd, cm, tr, u, f); break;
  case 24: memoryForce<8, 3>(bulk, cells_, cell_model_, weights_.data(), mechanisms_, upd, cm, tr, u, f); break;
  default: break;
  }
}

std::vector<double> AnelasticOperator::state() const {
  std::vector<double> s(committed_);
  s.insert(s.end(), trial_.begin(), trial_.end());
  return s;
}

bool AnelasticOperator::setState(const std::vector<double> &s) {
  if (s.size() != 2 * committed_.size()) return false;
  committed_.assign(s.begin(), s.begin() + committed_.size());
  trial_.assign(s.begin() + committed_.size(), s.end());
  return true;
}

} // namespace slipwave::fem

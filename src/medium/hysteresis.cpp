#include "slipwave/medium/hysteresis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>

#include "slipwave/numerics/gll_basis.hpp"
#include "slipwave/numerics/rounded_apart.hpp"
#include "slipwave/numerics/reference_cell.hpp"

namespace slipwave::medium {
namespace {

// The kernel's strain (tensor components; 2D: xx, yy, xy; 3D: xx, yy, zz, xy, yz, xz) from the
// displacement gradient G[i][j] = du_i/dx_j.
template <int Dim>
void strainOf(const double (*G)[3], double *eps) {
  if constexpr (Dim == 2) {
    eps[0] = G[0][0];
    eps[1] = G[1][1];
    eps[2] = 0.5 * (G[0][1] + G[1][0]);
  } else {
    eps[0] = G[0][0];
    eps[1] = G[1][1];
    eps[2] = G[2][2];
    eps[3] = 0.5 * (G[0][1] + G[1][0]);
    eps[4] = 0.5 * (G[1][2] + G[2][1]);
    eps[5] = 0.5 * (G[0][2] + G[2][0]);
  }
}

// A point of an element of degree p > 1 (a GLL node, lexicographic, x fastest): its index
// along each axis and the node stride of each axis, so that the node on line k through it
// with index m along k is node + (m - along[k]) stride[k].
struct LinePoint {
  int node, along[3], stride[3];
  LinePoint(int q, int n1) : node(q), along{q % n1, (q / n1) % n1, q / (n1 * n1)}, stride{1, n1, n1 * n1} {}
  int on(int k, int m) const { return node + (m - along[k]) * stride[k]; }
};

// Every element.
struct EveryElement {
  bool operator()(size_t, const double *) const { return false; }
};

// Runs fn(point index, element index k, point in the element, w |det J|, strain) over the
// points of the region's elements k in [first, last) on this rank (default: all of them),
// but those of an element that skip(k, its nodes' displacements) passes over. The strain is
// the model's: divided by the element's strain scale where the region has them (stresses
// and relaxation stresses come back divided by it, energies by its square: elementScale).

// Nen: the nodes of a degree-1 element (its loops unrolled), or 0 at degree p > 1.
template <int Dim, int Nen, class Fn, class Skip>
void forEachPointOf(const Hysteresis &h, const HystereticRegion &reg, const PetscScalar *u_local, Fn fn, size_t first, size_t last, Skip skip) {
  constexpr int  kStrain = physics::HystereticLayout<Dim>::kStrain;
  const PetscInt nen = Nen ? Nen : h.nodes, nq = reg.points;
  const int      n1  = (int)h.degree + 1;
  std::vector<double> u((size_t)nen * Dim);
  for (size_t k = first; k < std::min(last, reg.dofs.size() / nen); ++k) {
    for (PetscInt a = 0; a < nen; ++a)
      for (int i = 0; i < Dim; ++i) u[a * Dim + i] = PetscRealPart(u_local[reg.dofs[k * nen + a] + i]);
    if (skip(k, u.data())) continue;
    for (PetscInt q = 0; q < nq; ++q) {
      const size_t p = k * nq + q;
      double       G[3][3] = {};
      if constexpr (Nen > 0) {
        const double *dN = &reg.gradient[p * nen * Dim];
        for (PetscInt a = 0; a < nen; ++a)
          for (int i = 0; i < Dim; ++i)
            for (int j = 0; j < Dim; ++j) G[i][j] += u[a * Dim + i] * dN[a * Dim + j];
      } else {
        // du_i/dxi_k by the GLL derivative matrix along line k through q, then dxi/dx.
        const double   *Jinv = &reg.jinv[p * Dim * Dim];
        const LinePoint lp((int)q, n1);
        for (int k2 = 0; k2 < Dim; ++k2) {
          const double *Dq = &h.derivative[lp.along[k2] * n1];
          double        du[Dim] = {};
          for (int m = 0; m < n1; ++m) {
            const int a = lp.on(k2, m);
            for (int i = 0; i < Dim; ++i) du[i] += Dq[m] * u[a * Dim + i];
          }
          for (int i = 0; i < Dim; ++i)
            for (int j = 0; j < Dim; ++j) G[i][j] += du[i] * Jinv[k2 * Dim + j];
        }
      }
      double eps[kStrain];
      strainOf<Dim>(G, eps);
      if (!reg.scale.empty())
        for (int c = 0; c < kStrain; ++c) eps[c] /= reg.scale[k];
      fn(p, k, (int)q, reg.volume[p], eps);
    }
  }
}

template <int Dim, class Fn, class Skip = EveryElement>
void forEachPoint(const Hysteresis &h, const HystereticRegion &reg, const PetscScalar *u_local, Fn fn, size_t first = 0, size_t last = SIZE_MAX, Skip skip = {}) {
  // Degree 1: triangles (3 nodes), quadrilaterals and tetrahedra (4), hexahedra (8).
  if (h.degree > 1) forEachPointOf<Dim, 0>(h, reg, u_local, fn, first, last, skip);
  else if (h.nodes == 3) forEachPointOf<Dim, 3>(h, reg, u_local, fn, first, last, skip);
  else if (h.nodes == 4) forEachPointOf<Dim, 4>(h, reg, u_local, fn, first, last, skip);
  else forEachPointOf<Dim, 8>(h, reg, u_local, fn, first, last, skip);
}

// An element whose points are virgin at a zero strain (none has had a nonzero strain, the last
// force's included) and whose nodes are at rest (u exactly 0): its points' updates change
// nothing and their relaxation stress is zero (the kernel's contract), so a pass over them
// may skip it. Ahead of a wave most of a mesh is such (the explicit step moves the front by
// one element per step).
bool untouched(const HystereticRegion &reg, size_t k, const double *u, size_t values) {
  if (reg.stirred[k]) return false;
  for (size_t i = 0; i < values; ++i)
    if (u[i] != 0) return false;
  return true;
}

// Element k's strain scale (1 where the region has none): what turns the model's stress at
// the scaled strain into the point's (HystereticRegion::scale).
inline double elementScale(const HystereticRegion &reg, size_t k) { return reg.scale.empty() ? 1.0 : reg.scale[k]; }

// fe += vol B^T T at a point of a degree-1 element of Nen nodes (dN: the point's shape
// gradients; fe: the element's nodal forces, node-major), its loops unrolled.
template <int Dim, int Nen>
void scatterLinear(const double *dN, const double (*T)[3], double vol, double *fe) {
  for (int a = 0; a < Nen; ++a)
    for (int i = 0; i < Dim; ++i) {
      double s = 0;
      for (int j = 0; j < Dim; ++j) s += T[i][j] * dN[a * Dim + j];
      fe[a * Dim + i] += vol * s;
    }
}

// fe += vol B^T T at point q (index p) of an element, fe its nodal forces (node-major; T the
// symmetric stress tensor, row-major 3x3).
template <int Dim>
void scatter(const Hysteresis &h, const HystereticRegion &reg, int q, size_t p, const double (*T)[3], double vol, double *fe) {
  const PetscInt nen = h.nodes;
  if (h.degree == 1) {
    // Triangles (3 nodes), quadrilaterals and tetrahedra (4), hexahedra (8).
    const double *dN = &reg.gradient[p * nen * Dim];
    if (nen == 3) scatterLinear<Dim, 3>(dN, T, vol, fe);
    else if (nen == 4) scatterLinear<Dim, 4>(dN, T, vol, fe);
    else scatterLinear<Dim, 8>(dN, T, vol, fe);
    return;
  }
  // dN_a/dxi_k(q) is nonzero only for the nodes a on line k through q: D[q_k][a_k].
  const int       n1   = (int)h.degree + 1;
  const double   *Jinv = &reg.jinv[p * Dim * Dim];
  const LinePoint lp(q, n1);
  for (int k2 = 0; k2 < Dim; ++k2) {
    double S[Dim];
    for (int i = 0; i < Dim; ++i) {
      S[i] = 0;
      for (int j = 0; j < Dim; ++j) S[i] += T[i][j] * Jinv[k2 * Dim + j];
      S[i] *= vol;
    }
    const double *Dq = &h.derivative[lp.along[k2] * n1];
    for (int m = 0; m < n1; ++m) {
      double *fa = &fe[lp.on(k2, m) * Dim];
      for (int i = 0; i < Dim; ++i) fa[i] += Dq[m] * S[i];
    }
  }
}

// The nodal forces of a region's elements, gathered element by element (each point's B^T r
// into its element's, then the element's into f_local once): the points of an element write
// its nodes many times (4 Gauss points, 25 GLL points at p = 4), a local array rather than
// the scattered entries of f_local.
class ElementForces {
public:
  ElementForces(const Hysteresis &h, const HystereticRegion &reg, PetscScalar *f_local) : reg_(reg), f_(f_local), nen_(h.nodes), fe_((size_t)h.nodes * h.dim) {}
  ~ElementForces() { flush(); }
  // The forces of element k, zero when it is first asked for.
  double *of(size_t k) {
    if (k != element_) {
      flush();
      element_ = k;
    }
    return fe_.data();
  }

private:
  void flush() {
    if (element_ == kNone) return;
    const PetscInt *dofs = &reg_.dofs[element_ * nen_];
    const size_t    dim  = fe_.size() / nen_;
    for (PetscInt a = 0; a < nen_; ++a)
      for (size_t i = 0; i < dim; ++i) f_[dofs[a] + i] += fe_[a * dim + i];
    std::fill(fe_.begin(), fe_.end(), 0.0);
    element_ = kNone;
  }
  static constexpr size_t kNone = SIZE_MAX;
  const HystereticRegion &reg_;
  PetscScalar            *f_;
  PetscInt                nen_;
  std::vector<double>     fe_;
  size_t                  element_ = kNone;
};

// C:eps - sigma as a symmetric tensor (xx, yy, zz, xy, yz, xz) from the kernel's stress. Its
// products rounded apart (numerics/rounded_apart.hpp): the force, the relaxation it keeps for
// the constant-Q drive, a restart's first drive and the output compute it in different
// places and must round alike.
template <int Dim>
void relaxationStress(const HystereticRegion &reg, const double *eps, const double *sigma, double r[6]) {
  using numerics::roundedApart;
  const double mu2 = 2 * reg.mu;
  if constexpr (Dim == 2) {
    const double tr = roundedApart(reg.lambda * (eps[0] + eps[1]));
    r[0] = tr + roundedApart(mu2 * eps[0]) - sigma[0];
    r[1] = tr + roundedApart(mu2 * eps[1]) - sigma[1];
    r[2] = tr - sigma[3];
    r[3] = roundedApart(mu2 * eps[2]) - sigma[2];
    r[4] = r[5] = 0;
  } else {
    const double tr = roundedApart(reg.lambda * (eps[0] + eps[1] + eps[2]));
    for (int c = 0; c < 3; ++c) r[c] = tr + roundedApart(mu2 * eps[c]) - sigma[c];
    for (int c = 3; c < 6; ++c) r[c] = roundedApart(mu2 * eps[c]) - sigma[c];
  }
}

// A point's state: its header and its plastic strains (physics/hysteretic_soil.hpp).
struct PointState {
  const double *header, *plastic;
};

// The committed state of point p: the stored one, or, while the states wait for the strains
// of the accepted step (h.pending), a copy of it brought to its strain in `buffer` (the same
// update the next force makes in place, so that it is the same bits).
template <int Dim>
PointState committedState(const Hysteresis &h, const HystereticRegion &reg, size_t p, std::vector<double> &buffer) {
  constexpr int kHeader = physics::HystereticLayout<Dim>::kPlastic;
  const int     size    = physics::hystereticStateSize<Dim>(*reg.model) - kHeader;
  const double *header = &reg.header[p * kHeader], *plastic = &reg.plastic[p * size];
  if (!h.pending) return {header, plastic};
  buffer.resize(kHeader + size);
  physics::hystereticUpdate<Dim>(*reg.model, header, plastic, &reg.strain[p * physics::HystereticLayout<Dim>::kStrain], nullptr, buffer.data(), buffer.data() + kHeader,
                                 h.settles + 1);
  return {buffer.data(), buffer.data() + kHeader};
}

// fe += vol B^T r at point q (index p) of an element, r the relaxation stress (xx, yy, zz, xy,
// yz, xz), fe the element's nodal forces.
template <int Dim>
void scatterRelaxation(const Hysteresis &h, const HystereticRegion &reg, int q, size_t p, const double *r, double vol, double *fe) {
  // Tensor rows (xx, xy, xz), (xy, yy, yz), (xz, yz, zz) of r.
  const double T[3][3] = {{r[0], r[3], r[5]}, {r[3], r[1], r[4]}, {r[5], r[4], r[2]}};
  scatter<Dim>(h, reg, q, p, T, vol, fe);
}

// The relaxation stress a point keeps for HysteresisAddRegionForce: its first kStress
// components (in 2D r_yz = r_xz = 0).
template <int Dim>
constexpr int kKept = physics::HystereticLayout<Dim>::kStress;

// f_local += scale f_relax of the region, the Iwan stress of each point from stress(p, eps,
// sigma); with `kept`, each point's relaxation stress kept there too.
template <int Dim, class Stress, class Skip = EveryElement>
void regionForce(const Hysteresis &h, const HystereticRegion &reg, const PetscScalar *u_local, double scale, PetscScalar *f_local, double *kept, Stress stress,
                 Skip skip = {}) {
  constexpr int kStress = physics::HystereticLayout<Dim>::kStress;
  ElementForces forces(h, reg, f_local);
  forEachPoint<Dim>(
    h, reg, u_local,
    [&](size_t p, size_t k, int q, double vol, const double *eps) {
      double sigma[kStress], r[6];
      stress(p, eps, sigma);
      relaxationStress<Dim>(reg, eps, sigma, r);
      if (!reg.scale.empty())
        for (double &rc : r) rc *= reg.scale[k];
      if (kept)
        for (int c = 0; c < kKept<Dim>; ++c) kept[p * kKept<Dim> + c] = r[c];
      scatterRelaxation<Dim>(h, reg, q, p, r, scale * vol, forces.of(k));
    },
    0, SIZE_MAX, skip);
}

// Points ahead whose plastic strains are fetched early.
constexpr size_t kAhead = 6;

// HysteresisForce of one region: each point's state first brought to the accepted step's strain
// in place (when `settle`: update number h.settles + 1), then the stress of the new strain
// evaluated from it (nothing written), the strain kept. One pass, each state read once and
// only the elements that yield written: the step is bound by this traffic
// (docs/performance.md). The untouched elements are skipped, and an element is marked stirred
// as soon as its nodes move.
template <int Dim>
void trialForce(const Hysteresis &h, HystereticRegion &reg, bool settle, const PetscScalar *u_local, PetscScalar *f_local) {
  constexpr int kStrain = physics::HystereticLayout<Dim>::kStrain, kHeader = physics::HystereticLayout<Dim>::kPlastic;
  const int     size    = physics::hystereticStateSize<Dim>(*reg.model) - kHeader;
  const size_t  points  = reg.volume.size();
  const int     n       = reg.model->surfaces();
  const double update = h.settles + 1;
  const size_t values = (size_t)h.nodes * Dim;
  double      *kept   = reg.relaxation.empty() ? nullptr : reg.relaxation.data();
  auto         skip   = [&](size_t k, const double *u) {
    if (untouched(reg, k, u, values)) return true;
    reg.stirred[k] = 1;
    return false;
  };
  regionForce<Dim>(h, reg, u_local, 1.0, f_local, kept, [&](size_t p, const double *eps, double *sigma) {
    double *header = &reg.header[p * kHeader], *plastic = &reg.plastic[p * size], *strain = &reg.strain[p * kStrain];
    // The plastic strains of a point with a head are hundreds of bytes from the last one's:
    // ask for them a few points ahead, or each such point waits for memory. Whether it has a
    // head is in its header, asked for as many points before (reading it unasked would wait).
    if (p + 2 * kAhead < points) __builtin_prefetch(&reg.header[(p + 2 * kAhead) * kHeader]);
    if (p + kAhead < points && reg.header[(p + kAhead) * kHeader + physics::HystereticLayout<Dim>::kHead] > 0)
      for (int c = 0; c < physics::HystereticLayout<Dim>::kDeviator; ++c) __builtin_prefetch(&reg.plastic[(p + kAhead) * size + c * n], 1);
    // (The update's return, the plastic work, is not booked: the ledger's dissipation is the
    // work against the relaxation force plus E_r, closed to round-off; energy_ledger.hpp.)
    if (settle) physics::hystereticSettleEvaluate<Dim>(*reg.model, header, plastic, strain, update, eps, sigma);
    else physics::hystereticUpdate<Dim>(*reg.model, header, plastic, eps, sigma, nullptr, nullptr, 0);
    for (int c = 0; c < kStrain; ++c) strain[c] = eps[c];
  }, skip);
}

// f_local += scale f_relax of the region from its committed states (evaluated, not updated).
template <int Dim>
void committedForce(const Hysteresis &h, const HystereticRegion &reg, const PetscScalar *u_local, double scale, PetscScalar *f_local) {
  std::vector<double> buffer;
  regionForce<Dim>(h, reg, u_local, scale, f_local, nullptr, [&](size_t p, const double *eps, double *sigma) {
    const PointState state = committedState<Dim>(h, reg, p, buffer);
    physics::hystereticUpdate<Dim>(*reg.model, state.header, state.plastic, eps, sigma, nullptr, nullptr, 0);
  });
}

// The same from the relaxation stresses the last force kept: the same bits (the force
// evaluated the same states at the same strains), without a strain or an update.
template <int Dim>
void keptForce(const Hysteresis &h, const HystereticRegion &reg, double scale, PetscScalar *f_local) {
  const size_t  points = (size_t)reg.points;
  ElementForces forces(h, reg, f_local);
  for (size_t k = 0; k < reg.elements.size(); ++k)
    for (size_t q = 0; q < points && reg.stirred[k]; ++q) { // (an untouched element keeps zeros)
      const size_t p = k * points + q;
      double       r[6] = {};
      std::copy(&reg.relaxation[p * kKept<Dim>], &reg.relaxation[p * kKept<Dim>] + kKept<Dim>, r);
      scatterRelaxation<Dim>(h, reg, (int)q, p, r, scale * reg.volume[p], forces.of(k));
    }
}

// Brings every point's state to its pending strain in place: what the next force would do
// first, done now for a reader of every state (the same update, so the same bits).
template <int Dim>
void settle(Hysteresis *h) {
  constexpr int kStrain = physics::HystereticLayout<Dim>::kStrain, kHeader = physics::HystereticLayout<Dim>::kPlastic;
  if (!h->pending) return;
  for (HystereticRegion &reg : h->regions) {
    const size_t size = physics::hystereticStateSize<Dim>(*reg.model) - kHeader;
    for (size_t p = 0; p < reg.volume.size(); ++p) {
      // An element not stirred is virgin at a zero strain: nothing to bring.
      if (!reg.stirred[p / reg.points]) continue;
      double *header = &reg.header[p * kHeader], *plastic = &reg.plastic[p * size];
      physics::hystereticUpdate<Dim>(*reg.model, header, plastic, &reg.strain[p * kStrain], nullptr, header, plastic, h->settles + 1);
    }
  }
  h->settles += 1;
  h->pending = false;
}

template <int Dim>
double relaxationEnergy(Hysteresis *h, const PetscScalar *u_local) {
  double              sum = 0;
  std::vector<double> buffer;
  settle<Dim>(h);
  for (const HystereticRegion &reg : h->regions) {
    // An untouched element holds no energy beyond the linear one (zero strain, virgin states).
    const size_t values = (size_t)h->nodes * Dim;
    auto         skip   = [&](size_t k, const double *u) { return untouched(reg, k, u, values); };
    forEachPoint<Dim>(
      *h, reg, u_local,
      [&](size_t p, size_t k, int, double vol, const double *eps) {
        double tr = 0, ee = 0;
        for (int c = 0; c < Dim; ++c) tr += eps[c];
        for (int c = 0; c < physics::HystereticLayout<Dim>::kStrain; ++c) ee += (c < 3 && c < Dim ? 1.0 : 2.0) * eps[c] * eps[c];
        const double     linear = 0.5 * reg.lambda * tr * tr + reg.mu * ee;
        const PointState state  = committedState<Dim>(*h, reg, p, buffer);
        const double     s2     = elementScale(reg, k) * elementScale(reg, k);
        sum += s2 * vol * (linear - physics::hystereticStoredEnergy<Dim>(*reg.model, state.header, state.plastic, eps));
      },
      0, SIZE_MAX, skip);
  }
  return sum;
}

// The mean relaxation stress (6) over the points of the region's elements [first, last) and
// their largest strain, per element, at the committed state.
template <int Dim>
void elementFields(const HystereticRegion &reg, const Hysteresis &h, const PetscScalar *u_local, size_t first, size_t last, double *mean, double *largest) {
  constexpr int       kStress = physics::HystereticLayout<Dim>::kStress;
  std::vector<double> buffer;
  std::fill(mean, mean + 6 * (last - first), 0.0);
  std::fill(largest, largest + (last - first), 0.0);
  forEachPoint<Dim>(
    h, reg, u_local,
    [&](size_t p, size_t k, int, double, const double *eps) {
      double        sigma[kStress], r[6];
      const PointState state = committedState<Dim>(h, reg, p, buffer);
      // Evaluate only (no state out): the committed state stays as it is.
      physics::hystereticUpdate<Dim>(*reg.model, state.header, state.plastic, eps, sigma, nullptr, nullptr, 0);
      relaxationStress<Dim>(reg, eps, sigma, r);
      const double scale = elementScale(reg, k);
      for (int j = 0; j < 6; ++j) mean[6 * (k - first) + j] += scale * r[j] / reg.points;
      largest[k - first] = std::max(largest[k - first], scale * physics::maxShearStrain<Dim>(*reg.model, state.header));
    },
    first, last);
}

template <int Dim>
void cellFields(const Hysteresis *h, const PetscScalar *u_local, double *relaxation, double *max_strain, double *modulus_ratio) {
  for (size_t g = 0; g < h->regions.size(); ++g) {
    const HystereticRegion &reg = h->regions[g];
    const size_t            nel = reg.elements.size();
    // Per element of the region: the mean relaxation stress and the largest strain.
    std::vector<double> mean(6 * nel), largest(nel);
    elementFields<Dim>(reg, *h, u_local, 0, nel, mean.data(), largest.data());
    // To the cells: at degree p > 1 every sub-cell of an element shows the element's values.
    for (size_t c = 0; c < h->cell_element.size(); ++c) {
      const auto [region, k] = h->element_place[h->cell_element[c]];
      if (region != (PetscInt)g) continue;
      for (int j = 0; j < 6; ++j) relaxation[6 * c + j] = mean[6 * k + j];
      max_strain[c]    = largest[k];
      modulus_ratio[c] = reg.model->secantModulusRatio(largest[k] / elementScale(reg, k));
    }
  }
}

} // namespace

PetscErrorCode HystereticElementModel(const RegionMaterialInfo &m, std::shared_ptr<const physics::HystereticSoilModel> *model) {
  PetscFunctionBeginUser;
  *model = m.model == MaterialModel::Hysteretic ? m.hysteretic.model : nullptr;
  const double mu = m.fe.lame.mu, lambda = m.fe.lame.lambda;
  // A damped region's element moduli are the unrelaxed ones (medium/attenuation.hpp): the
  // model takes them as its small-strain moduli, the same G/Gmax curve, so that it is the
  // linear element below the elastic limit and the constant-Q body acts on its stress.
  if (*model && mu != (*model)->shearModulus()) {
    physics::HystereticSurfaces surfaces;
    surfaces.count = (*model)->surfaces();
    // The same curve the options' check built a model from: it cannot fail here.
    try {
      *model = std::make_shared<const physics::HystereticSoilModel>(mu, lambda + 2.0 / 3.0 * mu, m.hysteretic.backbone, surfaces);
    } catch (const std::invalid_argument &e) {
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_PLIB, "region %s: the hysteretic model on the unrelaxed moduli: %s", m.region.c_str(), e.what());
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode HysteresisCreate(const fem::BulkOperator &bulk, const std::vector<RegionMaterialInfo> &materials, Hysteresis **out) {
  PetscFunctionBeginUser;
  *out = nullptr;
  bool any = false;
  for (const auto &m : materials) any = any || m.model == MaterialModel::Hysteretic;
  if (!any) PetscFunctionReturn(0);
  auto          *h   = new Hysteresis();
  const PetscInt dim = bulk.dimension(), nen = bulk.nodesPerElement(), degree = bulk.degree();
  h->dim    = dim;
  h->nodes  = nen;
  h->degree = degree;
  h->element_place.assign(bulk.elementCount(), {-1, -1});
  for (PetscInt c = 0; c < bulk.cellCount(); ++c) h->cell_element.push_back(bulk.cellElement(c));
  // Degree p > 1: the GLL nodes are the points, as for the spectral K (collocated quadrature).
  double x[numerics::kMaxSpectralDegree + 1], w[numerics::kMaxSpectralDegree + 1];
  const int n1 = (int)degree + 1;
  if (degree > 1) {
    numerics::gllPointsWeights((int)degree, x, w);
    h->derivative.resize((size_t)n1 * n1);
    numerics::lagrangeDerivativeMatrix((int)degree, x, h->derivative.data());
  }
  const numerics::ReferenceRule &rule = numerics::referenceRule(bulk.shape());
  for (size_t r = 0; r < materials.size(); ++r) {
    if (materials[r].model != MaterialModel::Hysteretic) continue;
    HystereticRegion reg;
    reg.region = (PetscInt)r;
    PetscCall(HystereticElementModel(materials[r], &reg.model));
    reg.lambda = materials[r].fe.lame.lambda;
    reg.mu     = materials[r].fe.lame.mu;
    // Mean: one point per cell, with the cell's mean strain (the volume average of the Gauss
    // points' gradients) and its volume.
    const bool mean = materials[r].hysteretic.points == StressPoints::Mean;
    reg.points      = degree > 1 ? nen : (mean ? 1 : rule.points);
    for (PetscInt e = 0; e < bulk.elementCount(); ++e) {
      if (bulk.elementRegion(e) != reg.region) continue;
      h->element_place[e] = {(PetscInt)h->regions.size(), (PetscInt)reg.elements.size()};
      reg.elements.push_back(e);
      for (PetscInt a = 0; a < nen; ++a) reg.dofs.push_back(bulk.elementNodeOffset(e, a));
      const double *xe = bulk.elementCoordinates(e);
      if (degree > 1) {
        for (int q = 0; q < nen; ++q) {
          double J[numerics::kMaxCellDim][numerics::kMaxCellDim] = {}, Jinv[numerics::kMaxCellDim][numerics::kMaxCellDim];
          double weight = 1;
          for (int k = 0; k < dim; ++k) {
            const int     qk = k == 0 ? q % n1 : (k == 1 ? (q / n1) % n1 : q / (n1 * n1));
            const double *Dq = &h->derivative[qk * n1];
            weight *= w[qk];
            for (int m = 0; m < n1; ++m)
              for (int i = 0; i < dim; ++i) J[i][k] += Dq[m] * xe[LinePoint(q, n1).on(k, m) * dim + i];
          }
          const double det = numerics::invertJacobian((int)dim, J, Jinv);
          for (int k = 0; k < dim; ++k)
            for (int j = 0; j < dim; ++j) reg.jinv.push_back(Jinv[k][j]);
          reg.volume.push_back(weight * std::fabs(det));
        }
        continue;
      }
      double gradient[numerics::kMaxRulePoints][numerics::kMaxCellNodes][numerics::kMaxCellDim] = {}, volume[numerics::kMaxRulePoints];
      for (int q = 0; q < rule.points; ++q) {
        double J[numerics::kMaxCellDim][numerics::kMaxCellDim], Jinv[numerics::kMaxCellDim][numerics::kMaxCellDim];
        numerics::jacobian((int)nen, (int)dim, xe, rule.dN[q], J);
        volume[q] = rule.weight[q] * std::fabs(numerics::invertJacobian((int)dim, J, Jinv));
        // dN/dx_j = sum_k dN/dxi_k dxi_k/dx_j.
        for (PetscInt a = 0; a < nen; ++a)
          for (PetscInt j = 0; j < dim; ++j)
            for (PetscInt k = 0; k < dim; ++k) gradient[q][a][j] += rule.dN[q][a][k] * Jinv[k][j];
      }
      if (mean) {
        double v = 0;
        for (int q = 0; q < rule.points; ++q) v += volume[q];
        for (PetscInt a = 0; a < nen; ++a)
          for (PetscInt j = 0; j < dim; ++j) {
            double g = 0;
            for (int q = 0; q < rule.points; ++q) g += volume[q] * gradient[q][a][j];
            reg.gradient.push_back(g / v);
          }
        reg.volume.push_back(v);
      } else {
        for (int q = 0; q < rule.points; ++q) {
          for (PetscInt a = 0; a < nen; ++a)
            for (PetscInt j = 0; j < dim; ++j) reg.gradient.push_back(gradient[q][a][j]);
          reg.volume.push_back(volume[q]);
        }
      }
    }
    const int size = dim == 2 ? physics::hystereticStateSize<2>(*reg.model) : physics::hystereticStateSize<3>(*reg.model);
    const int header = dim == 2 ? physics::HystereticLayout<2>::kPlastic : physics::HystereticLayout<3>::kPlastic;
    reg.header.assign(reg.volume.size() * header, 0.0);
    reg.plastic.assign(reg.volume.size() * (size - header), 0.0);
    reg.strain.assign(reg.volume.size() * (dim == 2 ? physics::HystereticLayout<2>::kStrain : physics::HystereticLayout<3>::kStrain), 0.0);
    reg.stirred.assign(reg.elements.size(), 0);
    // Scales of 1 until the geostatic stage sets them (HysteresisSetGeostaticStress), or a
    // checkpoint brings them back.
    if (materials[r].hysteretic.mean_stress_geostatic) reg.scale.assign(reg.elements.size(), 1.0);
    h->regions.push_back(std::move(reg));
  }
  *out = h;
  PetscFunctionReturn(0);
}

PetscErrorCode HysteresisDestroy(Hysteresis **h) {
  PetscFunctionBeginUser;
  delete *h;
  *h = nullptr;
  PetscFunctionReturn(0);
}

void HysteresisForce(Hysteresis *h, const PetscScalar *u_local, PetscScalar *f_local) {
  for (HystereticRegion &reg : h->regions) {
    if (h->dim == 2) trialForce<2>(*h, reg, h->pending, u_local, f_local);
    else trialForce<3>(*h, reg, h->pending, u_local, f_local);
  }
  if (h->pending) h->settles += 1;
  h->pending   = false;
  h->has_trial = true;
}

void HysteresisAddRegionForce(Hysteresis *h, PetscInt region, const PetscScalar *u_local, double scale, PetscScalar *f_local) {
  for (HystereticRegion &reg : h->regions) {
    if (reg.region != region) continue;
    const int kept = h->dim == 2 ? kKept<2> : kKept<3>;
    // Kept by the last force (a force since the last commit, with the region keeping): scatter.
    if (h->has_trial && !reg.relaxation.empty()) {
      if (h->dim == 2) keptForce<2>(*h, reg, scale, f_local);
      else keptForce<3>(*h, reg, scale, f_local);
      continue;
    }
    if (h->dim == 2) committedForce<2>(*h, reg, u_local, scale, f_local);
    else committedForce<3>(*h, reg, u_local, scale, f_local);
    // Asked once, asked every step: from now on the forces keep this region's stresses.
    reg.relaxation.assign(reg.volume.size() * kept, 0.0);
  }
}

void HysteresisCommit(Hysteresis *h) {
  if (!h || !h->has_trial) return;
  h->pending   = true;
  h->has_trial = false;
}

void HysteresisDiscardTrial(Hysteresis *h) {
  if (h) h->has_trial = false;
}

// Checkpoints hold each point's state as one array (header, then plastic strains), with the
// tail's age (updates since it was set) in kSince's slot: the count of updates starts again
// with the restarted run (HysteresisSetState), and the file is the same as when the state kept
// that age itself (version 10).
std::vector<double> HysteresisState(const Hysteresis *h) {
  std::vector<double> s, buffer;
  // The committed states have had the settles so far, and the pending one if any.
  const double now = h->settles + (h->pending ? 1 : 0);
  for (const HystereticRegion &reg : h->regions) {
    const size_t header = reg.header.size() / reg.volume.size(), size = reg.plastic.size() / reg.volume.size();
    for (size_t p = 0; p < reg.volume.size(); ++p) {
      const PointState state = h->dim == 2 ? committedState<2>(*h, reg, p, buffer) : committedState<3>(*h, reg, p, buffer);
      s.insert(s.end(), state.header, state.header + header);
      physics::swapTailAge(&s[s.size() - header], now);
      s.insert(s.end(), state.plastic, state.plastic + size);
    }
    // The geostatic stage is not run again on a restart: its strain scales come from here.
    s.insert(s.end(), reg.scale.begin(), reg.scale.end());
  }
  return s;
}

PetscInt HysteresisStateSize(const Hysteresis *h) {
  size_t n = 0;
  for (const HystereticRegion &reg : h->regions) n += reg.header.size() + reg.plastic.size() + reg.scale.size();
  return (PetscInt)n;
}

void HysteresisSetState(Hysteresis *h, const std::vector<double> &s) {
  auto         o     = s.begin();
  const size_t since = physics::HystereticLayout<2>::kSince;
  h->settles         = 0;
  for (HystereticRegion &reg : h->regions) {
    const size_t header = reg.header.size() / reg.volume.size(), size = reg.plastic.size() / reg.volume.size();
    std::fill(reg.stirred.begin(), reg.stirred.end(), 0);
    for (size_t p = 0; p < reg.volume.size(); ++p) {
      double *state = &reg.header[p * header];
      std::copy_n(o, header, state);
      std::copy_n(o + header, size, reg.plastic.begin() + p * size);
      o += header + size;
      // The age back to the update that set the tail, in the count that starts here.
      physics::swapTailAge(state, h->settles);
      // A point with anything in its header but that has had a strain.
      for (size_t j = 0; j < header; ++j)
        if (j != since && state[j] != 0) reg.stirred[p / reg.points] = 1;
    }
    std::copy_n(o, reg.scale.size(), reg.scale.begin());
    o += reg.scale.size();
    // No strain is pending (pending is false): the untouched elements' must be zero.
    std::fill(reg.strain.begin(), reg.strain.end(), 0.0);
    // The relaxation kept for an untouched element is zero (it is not written while skipped).
    std::fill(reg.relaxation.begin(), reg.relaxation.end(), 0.0);
  }
  h->pending   = false;
  h->has_trial = false;
}

PetscErrorCode HysteresisSetGeostaticStress(Hysteresis *h, MPI_Comm comm, const PetscScalar *u_local, const std::vector<RegionMaterialInfo> &materials,
                                            std::vector<std::string> *report) {
  PetscFunctionBeginUser;
  for (HystereticRegion &reg : h->regions) {
    if (reg.scale.empty()) continue;
    // sigma'_0 = -K tr(eps) (plane strain too: sigma_zz = lambda tr(eps), so the three normal
    // stresses sum to (3 lambda + 2 mu) tr(eps)), the volume average over the element's points.
    std::fill(reg.scale.begin(), reg.scale.end(), 1.0);
    std::vector<double> stress(reg.elements.size(), 0.0), volume(reg.elements.size(), 0.0);
    const double        bulk = reg.lambda + 2.0 / 3.0 * reg.mu;
    const auto          add  = [&](size_t, size_t k, int, double vol, const double *eps) {
      double tr = 0;
      for (int c = 0; c < h->dim; ++c) tr += eps[c];
      stress[k] -= vol * bulk * tr;
      volume[k] += vol;
    };
    if (h->dim == 2) forEachPoint<2>(*h, reg, u_local, add);
    else forEachPoint<3>(*h, reg, u_local, add);
    double   range[2] = {HUGE_VAL, HUGE_VAL}; // min sigma'_0, -max sigma'_0
    PetscInt floored  = 0;
    for (size_t k = 0; k < reg.elements.size(); ++k) {
      double sigma = stress[k] / volume[k];
      if (sigma < kGeostaticStressFloor) sigma = kGeostaticStressFloor, ++floored;
      reg.scale[k] = physics::darendeliStrainScale(sigma, kDarendeliReferenceStress);
      range[0]     = std::min(range[0], sigma);
      range[1]     = std::min(range[1], -sigma);
    }
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, range, 2, MPI_DOUBLE, MPI_MIN, comm));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &floored, 1, MPIU_INT, MPI_SUM, comm));
    const RegionMaterialInfo &m = materials[reg.region];
    char                      line[320];
    std::snprintf(line, sizeof line,
                  "  hysteretic region %s: sigma'_0 from the geostatic stage %.6g .. %.6g kPa, Darendeli's gamma_r %.3g .. %.3g%s", m.region.c_str(), 1e-3 * range[0],
                  -1e-3 * range[1], m.hysteretic.backbone.reference_strain * physics::darendeliStrainScale(range[0], kDarendeliReferenceStress),
                  m.hysteretic.backbone.reference_strain * physics::darendeliStrainScale(-range[1], kDarendeliReferenceStress),
                  floored ? (" (" + std::to_string(floored) + " elements below 1 kPa taken at 1 kPa)").c_str() : "");
    report->push_back(line);
  }
  PetscFunctionReturn(0);
}

double HysteresisRelaxationEnergy(Hysteresis *h, const PetscScalar *u_local) { return h->dim == 2 ? relaxationEnergy<2>(h, u_local) : relaxationEnergy<3>(h, u_local); }

void HysteresisCellFields(const Hysteresis *h, const PetscScalar *u_local, double *relaxation, double *max_strain, double *modulus_ratio) {
  if (h->dim == 2) cellFields<2>(h, u_local, relaxation, max_strain, modulus_ratio);
  else cellFields<3>(h, u_local, relaxation, max_strain, modulus_ratio);
}

void HysteresisCellRelaxation(const Hysteresis *h, const PetscScalar *u_local, PetscInt cell, double *relaxation) {
  const auto [region, k] = h->element_place[h->cell_element[cell]];
  if (region < 0) return;
  double largest;
  if (h->dim == 2) elementFields<2>(h->regions[region], *h, u_local, (size_t)k, (size_t)k + 1, relaxation, &largest);
  else elementFields<3>(h->regions[region], *h, u_local, (size_t)k, (size_t)k + 1, relaxation, &largest);
}

std::vector<std::string> HysteresisReport(const std::vector<RegionMaterialInfo> &materials) {
  std::vector<std::string> lines;
  char                     buf[512];
  for (const RegionMaterialInfo &m : materials) {
    if (m.model != MaterialModel::Hysteretic) continue;
    const HystereticSpec &s = m.hysteretic;
    std::string           curve;
    switch (s.choice) {
    case BackboneChoice::Mkz:
      std::snprintf(buf, sizeof buf, "mkz, gamma_r %.4g, s %.4g, beta %.4g", s.backbone.reference_strain, s.backbone.curvature, s.backbone.beta);
      break;
    case BackboneChoice::Darendeli:
      if (s.mean_stress_geostatic)
        std::snprintf(buf, sizeof buf, "darendeli, PI %.4g %%, OCR %.4g, sigma'_0 from the geostatic stage (the curve at 1 atm: gamma_r %.4g, a %.4g)",
                      s.darendeli.plasticity_index, s.darendeli.ocr, s.backbone.reference_strain, s.backbone.curvature);
      else
        std::snprintf(buf, sizeof buf, "darendeli, PI %.4g %%, OCR %.4g, sigma'_0 %.4g Pa: gamma_r %.4g, a %.4g", s.darendeli.plasticity_index, s.darendeli.ocr,
                      s.darendeli.mean_effective_stress, s.backbone.reference_strain, s.backbone.curvature);
      break;
    case BackboneChoice::Gqh:
      std::snprintf(buf, sizeof buf, "gqh, theta %.4g,%.4g,%.4g,%.4g,%.4g", s.backbone.theta[0], s.backbone.theta[1], s.backbone.theta[2], s.backbone.theta[3],
                    s.backbone.theta[4]);
      break;
    case BackboneChoice::Table:
      std::snprintf(buf, sizeof buf, "table %s (%zu rows; source: %s)", s.table_file.c_str(), s.backbone.table_strain.size(), s.table_source.c_str());
      break;
    }
    curve = buf;
    const physics::HystereticSoilModel &model = *s.model;
    if (s.strength > 0 && s.choice != BackboneChoice::Gqh) {
      std::snprintf(buf, sizeof buf, ", capped at tau_max %.4g Pa", s.strength);
      curve += buf;
    } else if (s.choice == BackboneChoice::Gqh) {
      std::snprintf(buf, sizeof buf, ", tau_max %.4g Pa", s.strength);
      curve += buf;
    }
    // A backbone a parallel Iwan model cannot hold was replaced by its concave majorant.
    if (model.knotDeviation() > 1e-9) {
      std::snprintf(buf, sizeof buf, " (made concave: knots moved up to %.3g %%)", 100 * model.knotDeviation());
      curve += buf;
    }
    if (s.points == StressPoints::Mean) curve += "; stress from each cell's mean strain";
    std::snprintf(buf, sizeof buf,
                  "  region %s: hysteretic soil (Masing, parallel Iwan), backbone %s; Gmax %.4g Pa, %d surfaces; G/Gmax %.3f at 1e-4, %.3f at 1e-3; "
                  "strength %.4g Pa (the model's, at the last knot %.3g)",
                  m.region.c_str(), curve.c_str(), model.shearModulus(), model.surfaces(), model.secantModulusRatio(1e-4), model.secantModulusRatio(1e-3),
                  model.strength(), model.knotStrains().back());
    lines.push_back(buf);
  }
  return lines;
}

} // namespace slipwave::medium

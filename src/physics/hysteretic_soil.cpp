#include "slipwave/physics/hysteretic_soil.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#ifdef __AVX__
#include <immintrin.h>
#endif
#include <stdexcept>
#include <string>

#include "slipwave/numerics/rounded_apart.hpp"

namespace slipwave::physics {
namespace {

// Backbone stress over Gmax (a strain).
double normalisedStress(const SoilBackbone &b, double gamma) { return gamma * modulusReduction(b, gamma); }

std::vector<double> logSpaced(double first, double last, int count) {
  std::vector<double> v(count);
  for (int k = 0; k < count; ++k) v[k] = first * std::pow(last / first, (double)k / (count - 1));
  v.back() = last;
  return v;
}

// The backbone at the knots as the model can hold it: the least concave majorant of the points
// (0, 0), (K_j, F(K_j)) after a running maximum. A parallel Iwan model has a concave,
// non-decreasing backbone (element moduli >= 0); the given curve is, for the MKZ, GQ/H and
// Darendeli forms, and then this changes nothing. A table interpolated linearly in ln gamma is
// not, at a row where its G/Gmax flattens (the slope of tau jumps up there), nor is a curve
// past a peak; the majorant is the closest admissible curve above it (HystereticSoilModel::
// knotDeviation says how far it moved a knot).
std::vector<double> admissibleKnotStress(const SoilBackbone &b, const std::vector<double> &knots) {
  const int           n = (int)knots.size();
  std::vector<double> f(n);
  for (int j = 0; j < n; ++j) f[j] = std::max(normalisedStress(b, knots[j]), j > 0 ? f[j - 1] : 0.0);
  // Upper hull by the monotone chain, the origin first.
  std::vector<double> hx = {0.0}, hy = {0.0};
  for (int j = 0; j < n; ++j) {
    while (hx.size() >= 2) {
      const size_t k = hx.size() - 1;
      // Drop the last vertex if it lies on or below the chord from the one before it to point j.
      if ((hy[k] - hy[k - 1]) * (knots[j] - hx[k - 1]) <= (f[j] - hy[k - 1]) * (hx[k] - hx[k - 1])) {
        hx.pop_back();
        hy.pop_back();
      } else {
        break;
      }
    }
    hx.push_back(knots[j]);
    hy.push_back(f[j]);
  }
  std::vector<double> h(n);
  size_t              seg = 1;
  for (int j = 0; j < n; ++j) {
    while (seg + 1 < hx.size() && hx[seg] < knots[j]) ++seg;
    // A vertex keeps its own value (no interpolation round-off at the points that stay).
    h[j] = hx[seg] == knots[j] ? hy[seg] : hy[seg - 1] + (hy[seg] - hy[seg - 1]) * (knots[j] - hx[seg - 1]) / (hx[seg] - hx[seg - 1]);
  }
  return h;
}

// Where the line of slope Gmax from the origin meets the first chord (knots 0 and 1) extended
// back: the model's elastic limit for these knots. A backbone still linear at knot 0 (no
// deficit) or a first chord of slope Gmax keeps the model elastic up to knot 0 itself.
double chordElasticLimit(const SoilBackbone &b, const std::vector<double> &knots) {
  const std::vector<double> f = admissibleKnotStress(b, knots);
  const double              g0 = knots[0], slope = (f[1] - f[0]) / (knots[1] - g0), deficit = g0 - f[0];
  if (deficit <= 0 || slope >= 1) return g0;
  return g0 - deficit / (1 - slope);
}

void require(bool ok, const std::string &what) {
  if (!ok) throw std::invalid_argument("hysteretic soil: " + what);
}

} // namespace

// The piecewise-linear backbone. With knots K_0 < ... < K_{N-1} (log-spaced up to last_knot)
// the model's backbone is, in stress over Gmax:
//   slope 1 (Gmax) from 0 to gamma_e, then the chord K_0-K_1 extended back to meet that line
//   at gamma_e, then the chords K_{j-1}-K_j, and flat beyond K_{N-1}.
// Its kinks gamma_e, K_1, ..., K_{N-1} are the N yield strains, and the slope drop at each kink
// is that element's modulus (the slopes sum telescopically to Gmax). It equals the backbone at
// every knot, K_0 included (K_0 lies on the extended chord), and is linear with slope Gmax
// below gamma_e. K_0 is placed so that gamma_e = elastic_limit: a chord through K_0 interpolates
// the small-strain tail that Gmax gamma alone would overstate (putting the first kink on the
// backbone at the elastic limit instead makes the next chord steeper than the one before
// it for hyperbolic curves: a negative element modulus). gamma_e grows with K_0 (between K_0/r
// and K_0 for a hyperbola, r the knot ratio), so bisection in ln K_0 finds it.
HystereticSoilModel::HystereticSoilModel(double shear_modulus, double bulk_modulus, const SoilBackbone &backbone, const HystereticSurfaces &surfaces)
    : shear_modulus_(shear_modulus), bulk_modulus_(bulk_modulus), strength_(0) {
  const int n = surfaces.count;
  require(shear_modulus > 0 && std::isfinite(shear_modulus), "Gmax must be > 0");
  require(bulk_modulus > 0 && std::isfinite(bulk_modulus), "the bulk modulus must be > 0");
  require(n >= 2 && n <= 1000, "the number of surfaces must be 2 to 1000");
  const double limit = surfaces.elastic_limit, last = surfaces.last_knot;
  require(limit > 0 && last > 8 * limit && std::isfinite(last), "needs 0 < elastic limit < last knot / 8");

  double lo = std::log(limit), hi = std::log(std::min(8 * limit, std::sqrt(limit * last)));
  if (chordElasticLimit(backbone, logSpaced(limit, last, n)) >= limit) {
    hi = lo; // still linear at the elastic limit: the first knot is the elastic limit
  } else {
    require(chordElasticLimit(backbone, logSpaced(std::exp(hi), last, n)) >= limit,
            "the backbone softens too fast below the elastic limit (raise the number of surfaces or lower the elastic limit)");
    for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
      const double mid = 0.5 * (lo + hi);
      (chordElasticLimit(backbone, logSpaced(std::exp(mid), last, n)) >= limit ? hi : lo) = mid;
    }
  }
  // The upper end of the bracket: the elastic limit is reached or passed, never short of it.
  knots_ = logSpaced(std::exp(hi), last, n);

  const std::vector<double> f = admissibleKnotStress(backbone, knots_);
  knot_deviation_ = 0;
  for (int j = 0; j < n; ++j) {
    const double given = normalisedStress(backbone, knots_[j]);
    knot_deviation_ = std::max(knot_deviation_, std::fabs(f[j] - given) / given);
  }
  std::vector<double> kink(n), slope(n + 1);
  kink[0] = chordElasticLimit(backbone, knots_);
  slope[0] = 1;
  for (int j = 1; j < n; ++j) {
    kink[j] = knots_[j];
    slope[j] = (f[j] - f[j - 1]) / (knots_[j] - knots_[j - 1]);
  }
  slope[n] = 0;
  modulus_.resize(n);
  yield_strain_ = kink;
  for (int j = 0; j < n; ++j) {
    // The majorant's slopes fall; what is left is the round-off of a straight stretch.
    modulus_[j] = shear_modulus * std::max(0.0, slope[j] - slope[j + 1]);
  }
  twice_modulus_.resize(n);
  radius_.resize(n);
  for (int j = 0; j < n; ++j) {
    twice_modulus_[j] = 2 * modulus_[j];
    radius_[j] = yield_strain_[j] / std::sqrt(2.0); // |e - p| of simple shear gamma: gamma / sqrt(2)
    strength_ += modulus_[j] * yield_strain_[j];
  }
  tail_modulus_.assign(n + 1, 0.0);
  for (int j = n - 1; j >= 0; --j) tail_modulus_[j] = tail_modulus_[j + 1] + twice_modulus_[j];
}

double HystereticSoilModel::backboneStress(double gamma) const {
  double tau = 0;
  for (int j = 0; j < surfaces(); ++j) tau += modulus_[j] * std::min(gamma, yield_strain_[j]);
  return tau;
}

double HystereticSoilModel::secantModulusRatio(double gamma) const { return gamma > 0 ? backboneStress(gamma) / (shear_modulus_ * gamma) : 1.0; }

namespace {

// Deviatoric strain in the state's components (xx, yy, xy [, yz, xz]) and the trace.
template <int Dim>
double deviator(const double *strain, double *e) {
  if constexpr (Dim == 2) {
    const double tr = strain[0] + strain[1], m = tr / 3;
    e[0] = strain[0] - m;
    e[1] = strain[1] - m;
    e[2] = strain[2];
    return tr;
  } else {
    const double tr = strain[0] + strain[1] + strain[2], m = tr / 3;
    e[0] = strain[0] - m;
    e[1] = strain[1] - m;
    e[2] = strain[3];
    e[3] = strain[4];
    e[4] = strain[5];
    return tr;
  }
}

// d:d of a deviator in the state's components (d_zz = -(d_xx + d_yy)).
template <int Dim>
inline double contracted(const double *d) {
  double shear = d[2] * d[2];
  if constexpr (Dim == 3) shear += d[3] * d[3] + d[4] * d[4];
  const double zz = d[0] + d[1];
  return d[0] * d[0] + d[1] * d[1] + zz * zz + 2 * shear;
}

} // namespace

namespace {

// Four elements at a time in explicit vector types: the sums over the elements are reductions
// that the compiler vectorises only when allowed to reorder them (-ffast-math), which the
// project does not use. The order of the sums is fixed (four lanes, then lane 0 + 1 + 2 + 3,
// then the remainder in element order), so a point's answer does not depend on the caller.
typedef double    Lanes __attribute__((vector_size(4 * sizeof(double))));
typedef long long Mask __attribute__((vector_size(4 * sizeof(double))));

inline Lanes loadLanes(const double *p) {
  Lanes v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void storeLanes(double *p, Lanes v) { std::memcpy(p, &v, sizeof v); }
inline Lanes broadcast(double x) { return Lanes{x, x, x, x}; }
// sqrt of each lane: one instruction where AVX is there (std::sqrt per lane is not vectorised
// without -fno-math-errno).
inline Lanes laneSqrt(Lanes x) {
#ifdef __AVX__
  return (Lanes)_mm256_sqrt_pd((__m256d)x);
#else
  return Lanes{std::sqrt(x[0]), std::sqrt(x[1]), std::sqrt(x[2]), std::sqrt(x[3])};
#endif
}

// A returned d is rounded apart (numerics/rounded_apart.hpp): one pass uses it once (the
// settle's p = e - d), another twice (the update's p and stress), and they must agree.
using numerics::roundedApart;

// An element counts as elastic in a tail only with this share of its radius to spare: the
// slack and the strains are rounded, and the tail must not hold an element that a sweep would
// return by more than round-off.
constexpr double kSlackShare = 1 - 1e-12;
// Groups of four elements of the largest model (1000 surfaces), the remainder one more.
constexpr int kMaxGroups = 1000 / 4 + 1;

// Element i of the scalar remainder: returns its dissipation, adds its stress 2 G_i d to s and,
// with slack, lowers *slack to its r_i - |e - p_i| after the update (-1 if it yields). Not
// inlined: one compiled copy of this arithmetic for every pass (inlined, the compiler
// vectorises and fuses its scalar sums differently in each, and the bits would differ).
template <int Dim>
__attribute__((noinline)) double updateElement(int n, int i, double two_g, double r, const double *e, const double *p_in, double *p_out, double *s, double *slack) {
  constexpr int kDev = HystereticLayout<Dim>::kDeviator;
  double        d[kDev], dissipation = 0;
  for (int c = 0; c < kDev; ++c) d[c] = e[c] - p_in[c * n + i];
  const double n2 = contracted<Dim>(d);
  if (n2 > r * r) {
    // Radial return onto |d| = r: p moves along d by |d| - r.
    const double norm = std::sqrt(n2), scale = r / norm;
    for (int c = 0; c < kDev; ++c) {
      d[c] = roundedApart(d[c] * scale);
      if (p_out) p_out[c * n + i] = e[c] - d[c];
    }
    dissipation = two_g * r * (norm - r);
    if (slack) *slack = -1;
  } else if (slack) {
    *slack = std::min(*slack, r * kSlackShare - std::sqrt(n2));
  }
  for (int c = 0; c < kDev; ++c) s[c] += two_g * d[c];
  return dissipation;
}

// A group of four elements (lanes) with plastic strains p at the deviatoric strain e4:
// d = e - p and n2 = d:d; where a lane yields (n2 > r^2, the mask `yields`) its norm |d| and
// d returned onto |d| = r. Returns whether one yields (else norm and the returns are not set).
// The one place of this arithmetic, so that every pass over the elements rounds alike.
template <int Dim>
inline bool returnGroup(const Lanes *e4, const Lanes *p, Lanes r, Lanes *d, Lanes &n2, Mask &yields, Lanes &norm) {
  constexpr int kDev = HystereticLayout<Dim>::kDeviator;
  for (int c = 0; c < kDev; ++c) d[c] = e4[c] - p[c];
  const Lanes zz = d[0] + d[1];
  Lanes       shear = d[2] * d[2];
  if constexpr (Dim == 3) shear += d[3] * d[3] + d[4] * d[4];
  n2 = d[0] * d[0] + d[1] * d[1] + zz * zz + 2 * shear;
  yields = n2 > r * r;
  if (!(yields[0] | yields[1] | yields[2] | yields[3])) return false;
  norm = laneSqrt(n2);
  const Lanes scale = yields ? r / norm : broadcast(1);
  for (int c = 0; c < kDev; ++c) d[c] = roundedApart(d[c] * scale);
  return true;
}

// Elements [0, end) (end a multiple of four, or N) at the deviatoric strain e: their stress
// sum 2 G_i (e - p_i) into s, their dissipation returned; with p_out (p_in itself) the ones
// that yield are returned onto their surface in place; with slack, per group of four (and the
// remainder) the smallest r_i - |e - p_i| after the update, -1 where one yields.
template <int Dim>
double sweep(const HystereticSoilModel &model, const double *p_in, double *p_out, const double *e, int end, double *s, double *slack) {
  constexpr int kDev = HystereticLayout<Dim>::kDeviator;
  const int     n = model.surfaces();
  const double *two_g = model.twiceModulus(), *radius = model.radius();
  Lanes         e4[kDev], s4[kDev], dissipation4 = broadcast(0);
  for (int c = 0; c < kDev; ++c) {
    e4[c] = broadcast(e[c]);
    s4[c] = broadcast(0);
  }
  int i = 0, g = 0;
  for (; i + 4 <= end; i += 4, ++g) {
    Lanes p[kDev], d[kDev], n2, norm;
    Mask  yields;
    for (int c = 0; c < kDev; ++c) p[c] = loadLanes(p_in + c * n + i);
    const Lanes r = loadLanes(radius + i), g2 = loadLanes(two_g + i);
    Lanes       spare = broadcast(-1);
    if (returnGroup<Dim>(e4, p, r, d, n2, yields, norm)) {
      // The yielding lanes move onto their surface (p = e - d); no dissipation elsewhere.
      if (p_out)
        for (int c = 0; c < kDev; ++c) storeLanes(p_out + c * n + i, yields ? e4[c] - d[c] : p[c]);
      dissipation4 += g2 * r * (yields ? norm - r : broadcast(0));
      if (slack) spare = yields ? broadcast(-1) : r * kSlackShare - norm;
    } else if (slack) {
      spare = r * kSlackShare - laneSqrt(n2);
    }
    if (slack) slack[g] = std::min(std::min(spare[0], spare[1]), std::min(spare[2], spare[3]));
    for (int c = 0; c < kDev; ++c) s4[c] += g2 * d[c];
  }
  double dissipation = dissipation4[0] + dissipation4[1] + dissipation4[2] + dissipation4[3];
  for (int c = 0; c < kDev; ++c) s[c] = s4[c][0] + s4[c][1] + s4[c][2] + s4[c][3];
  if (slack && i < end) slack[g] = std::numeric_limits<double>::infinity();
  for (; i < end; ++i) dissipation += updateElement<Dim>(n, i, two_g[i], radius[i], e, p_in, p_out, s, slack ? &slack[g] : nullptr);
  return dissipation;
}

// Two sweeps in one pass: elements [0, settle_end) brought to the deviatoric strain e_settle in
// place (as sweep with p_out = p, no slack), then elements [0, evaluate_end) evaluated at
// e_evaluate from the result (as sweep without p_out), settle_end <= evaluate_end: each element
// both visit is read once. The stress of the second into s; the dissipation of the first
// returned. The same arithmetic in the same order as the two sweeps, so the same bits.
template <int Dim>
double settleEvaluateSweep(const HystereticSoilModel &model, double *plastic, const double *e_settle, int settle_end, const double *e_evaluate, int evaluate_end,
                           double *s) {
  constexpr int kDev = HystereticLayout<Dim>::kDeviator;
  const int     n = model.surfaces();
  const double *two_g = model.twiceModulus(), *radius = model.radius();
  Lanes         e1[kDev], e2[kDev], s4[kDev], dissipation4 = broadcast(0);
  for (int c = 0; c < kDev; ++c) {
    e1[c] = broadcast(e_settle[c]);
    e2[c] = broadcast(e_evaluate[c]);
    s4[c] = broadcast(0);
  }
  int i = 0;
  for (; i + 4 <= evaluate_end; i += 4) {
    Lanes p[kDev], d[kDev], n2, norm;
    Mask  yields;
    for (int c = 0; c < kDev; ++c) p[c] = loadLanes(plastic + c * n + i);
    const Lanes r = loadLanes(radius + i), g2 = loadLanes(two_g + i);
    if (i < settle_end && returnGroup<Dim>(e1, p, r, d, n2, yields, norm)) {
      for (int c = 0; c < kDev; ++c) {
        p[c] = yields ? e1[c] - d[c] : p[c];
        storeLanes(plastic + c * n + i, p[c]);
      }
      dissipation4 += g2 * r * (yields ? norm - r : broadcast(0));
    }
    returnGroup<Dim>(e2, p, r, d, n2, yields, norm);
    for (int c = 0; c < kDev; ++c) s4[c] += g2 * d[c];
  }
  double dissipation = dissipation4[0] + dissipation4[1] + dissipation4[2] + dissipation4[3], unused[kDev] = {};
  for (int c = 0; c < kDev; ++c) s[c] = s4[c][0] + s4[c][1] + s4[c][2] + s4[c][3];
  for (int k = i; k < settle_end; ++k) dissipation += updateElement<Dim>(n, k, two_g[k], radius[k], e_settle, plastic, plastic, unused, nullptr);
  for (; i < evaluate_end; ++i) updateElement<Dim>(n, i, two_g[i], radius[i], e_evaluate, plastic, nullptr, s, nullptr);
  return dissipation;
}

// After a sweep of every element to e, in place: the tail for the next updates. A tail from
// element k = 4 g holds while |e' - e| <= m_k, the smallest slack from k on; it costs k element
// visits per update and a sweep (about 1.5 N, the slacks' roots included) each time the strain
// leaves it, every m_k / rate updates, with rate the drift of the strain per update measured
// since the last sweep. The k of least cost k + 1.5 N rate / m_k is kept (N: no tail, a sweep
// every update, 1.5 N).
template <int Dim>
void chooseTail(const HystereticSoilModel &model, double *state, const double *p, const double *e, double update, double rate, const double *slack) {
  using L = HystereticLayout<Dim>;
  const int n = model.surfaces(), groups = n / 4;
  double    best_cost = 1.5 * n, best_slack = 0, m = n % 4 ? slack[groups] : std::numeric_limits<double>::infinity();
  int       best = n;
  for (int g = groups; g >= 0 && m > 0; --g) {
    if (g < groups) m = std::min(m, slack[g]);
    if (4 * g == n || m <= 0) continue;
    const double cost = 4 * g + 1.5 * n * rate / m;
    if (cost <= best_cost) {
      best_cost = cost;
      best = 4 * g;
      best_slack = m;
    }
  }
  state[L::kHead] = best;
  state[L::kSlack] = best_slack;
  state[L::kSince] = update;
  const double *two_g = model.twiceModulus();
  for (int c = 0; c < L::kDeviator; ++c) {
    double tail = 0;
    for (int j = best; j < n; ++j) tail += two_g[j] * p[c * n + j];
    state[L::kReference + c] = e[c];
    state[L::kTailStress + c] = tail;
  }
  double energy = 0;
  for (int j = best; j < n; ++j) {
    double pj[L::kDeviator];
    for (int c = 0; c < L::kDeviator; ++c) pj[c] = p[c * n + j];
    energy += 0.5 * two_g[j] * contracted<Dim>(pj);
  }
  state[L::kTailEnergy] = energy;
}

// The stress (the strain's components, sigma_zz also in 2D) from the trace and the
// deviatoric stress s.
template <int Dim>
void writeStress(const HystereticSoilModel &model, double tr, const double *s, double *stress) {
  const double p = model.bulkModulus() * tr;
  if constexpr (Dim == 2) {
    stress[0] = p + s[0];
    stress[1] = p + s[1];
    stress[2] = s[2];
    stress[3] = p - (s[0] + s[1]);
  } else {
    stress[0] = p + s[0];
    stress[1] = p + s[1];
    stress[2] = p - (s[0] + s[1]);
    stress[3] = s[2];
    stress[4] = s[3];
    stress[5] = s[4];
  }
}

// The header's largest equivalent shear strain after an update to the deviatoric strain e,
// written only where it grows (a point at rest leaves the line clean). The root only where it
// may: sqrt(x) <= m for x <= m^2 (a correctly rounded root of the rounded square of m is m,
// where m^2 is a normal number).
template <int Dim>
void keepLargestStrain(double *header, const double *e) {
  const double x = 2 * contracted<Dim>(e), largest = header[HystereticLayout<Dim>::kMaxStrain];
  if (x <= largest * largest && largest >= 1e-150) return;
  const double gamma = std::sqrt(x);
  if (gamma > largest) header[HystereticLayout<Dim>::kMaxStrain] = gamma;
}

} // namespace

template <int Dim>
double hystereticUpdate(const HystereticSoilModel &model, const double *state_in, const double *plastic_in, const double *strain, double *stress, double *state_out,
                        double *plastic_out, double update) {
  using L = HystereticLayout<Dim>;
  constexpr int kDev = L::kDeviator;
  const int     n = model.surfaces();
  if (state_out && state_out != state_in) {
    std::copy(state_in, state_in + L::kPlastic, state_out);
    state_in = state_out;
  }
  if (plastic_out && plastic_out != plastic_in) {
    std::copy(plastic_in, plastic_in + kDev * n, plastic_out);
    plastic_in = plastic_out;
  }
  double       e[kDev], drift[kDev];
  const double tr = deviator<Dim>(strain, e);
  for (int c = 0; c < kDev; ++c) drift[c] = e[c] - state_in[L::kReference + c];
  const double slack = state_in[L::kSlack], drift2 = contracted<Dim>(drift);
  const bool   tail_holds = drift2 <= slack * slack;
  const int    head = tail_holds ? (int)state_in[L::kHead] : n;
  double       s[kDev], group_slack[kMaxGroups];
  const bool   refresh = state_out && !tail_holds;
  const double dissipation = sweep<Dim>(model, plastic_in, plastic_out, e, head, s, refresh ? group_slack : nullptr);
  if (tail_holds)
    for (int c = 0; c < kDev; ++c) s[c] += model.tailModulus()[head] * e[c] - state_in[L::kTailStress + c];

  if (stress) writeStress<Dim>(model, tr, s, stress);
  if (state_out) {
    keepLargestStrain<Dim>(state_out, e);
    // The drift per update since the tail was set (the updates in between all held it).
    if (!tail_holds) chooseTail<Dim>(model, state_out, plastic_out, e, update, std::sqrt(drift2) / (update - state_out[L::kSince]), group_slack);
  }
  return dissipation;
}

template <int Dim>
double hystereticSettleEvaluate(const HystereticSoilModel &model, double *header, double *plastic, const double *settled, double update, const double *strain, double *stress) {
  using L = HystereticLayout<Dim>;
  constexpr int kDev = L::kDeviator;
  double        e1[kDev], drift[kDev];
  deviator<Dim>(settled, e1);
  for (int c = 0; c < kDev; ++c) drift[c] = e1[c] - header[L::kReference + c];
  const double slack = header[L::kSlack];
  // The settle leaves the tail: it sweeps every element and sets the next tail, from which the
  // stress is then evaluated (rare: a point sets its tail for the updates to come).
  if (!(contracted<Dim>(drift) <= slack * slack)) {
    const double dissipation = hystereticUpdate<Dim>(model, header, plastic, settled, nullptr, header, plastic, update);
    hystereticUpdate<Dim>(model, header, plastic, strain, stress, nullptr, nullptr, 0);
    return dissipation;
  }
  // The tail holds for the settle: it keeps the header's tail, so the evaluation's tail test
  // is against the same reference and slack, and both sweep the head.
  double       e2[kDev], s[kDev];
  const double tr = deviator<Dim>(strain, e2);
  for (int c = 0; c < kDev; ++c) drift[c] = e2[c] - header[L::kReference + c];
  const bool   tail_holds = contracted<Dim>(drift) <= slack * slack;
  const int    n = model.surfaces(), head = (int)header[L::kHead];
  double       dissipation = 0;
  // No element to visit (a point at rest in its elastic range): the sweep of none sums zeros.
  if (head == 0 && tail_holds) std::fill(s, s + kDev, 0.0);
  else dissipation = settleEvaluateSweep<Dim>(model, plastic, e1, head, e2, tail_holds ? head : n, s);
  if (tail_holds)
    for (int c = 0; c < kDev; ++c) s[c] += model.tailModulus()[head] * e2[c] - header[L::kTailStress + c];
  writeStress<Dim>(model, tr, s, stress);
  keepLargestStrain<Dim>(header, e1);
  return dissipation;
}

template <int Dim>
double hystereticStoredEnergy(const HystereticSoilModel &model, const double *state, const double *plastic, const double *strain) {
  using L = HystereticLayout<Dim>;
  constexpr int kDev = L::kDeviator;
  const int     n = model.surfaces(), head = (int)state[L::kHead];
  double        e[kDev], tail[kDev];
  const double  tr = deviator<Dim>(strain, e);
  // e:P, the zz components -(xx + yy), the shears counted twice.
  for (int c = 0; c < kDev; ++c) tail[c] = state[L::kTailStress + c];
  double ep = e[0] * tail[0] + e[1] * tail[1] + (e[0] + e[1]) * (tail[0] + tail[1]);
  for (int c = 2; c < kDev; ++c) ep += 2 * e[c] * tail[c];
  double w = 0.5 * model.bulkModulus() * tr * tr + 0.5 * model.tailModulus()[head] * contracted<Dim>(e) - ep + state[L::kTailEnergy];
  for (int i = 0; i < head; ++i) {
    double d[kDev];
    for (int c = 0; c < kDev; ++c) d[c] = e[c] - plastic[c * n + i];
    w += 0.5 * model.twiceModulus()[i] * contracted<Dim>(d);
  }
  return w;
}

template <int Dim>
double equivalentShearStrain(const double *strain) {
  double e[HystereticLayout<Dim>::kDeviator];
  deviator<Dim>(strain, e);
  return std::sqrt(2 * contracted<Dim>(e));
}

template <int Dim>
double equivalentShearStress(const double *stress) {
  // The deviator of the stress in the state's components; s:s / 2 = tau^2 in simple shear.
  double sd[HystereticLayout<Dim>::kDeviator];
  if constexpr (Dim == 2) {
    const double m = (stress[0] + stress[1] + stress[3]) / 3;
    sd[0] = stress[0] - m;
    sd[1] = stress[1] - m;
    sd[2] = stress[2];
  } else {
    const double m = (stress[0] + stress[1] + stress[2]) / 3;
    sd[0] = stress[0] - m;
    sd[1] = stress[1] - m;
    sd[2] = stress[3];
    sd[3] = stress[4];
    sd[4] = stress[5];
  }
  return std::sqrt(0.5 * contracted<Dim>(sd));
}

template double hystereticUpdate<2>(const HystereticSoilModel &, const double *, const double *, const double *, double *, double *, double *, double);
template double hystereticUpdate<3>(const HystereticSoilModel &, const double *, const double *, const double *, double *, double *, double *, double);
template double hystereticSettleEvaluate<2>(const HystereticSoilModel &, double *, double *, const double *, double, const double *, double *);
template double hystereticSettleEvaluate<3>(const HystereticSoilModel &, double *, double *, const double *, double, const double *, double *);
template double hystereticStoredEnergy<2>(const HystereticSoilModel &, const double *, const double *, const double *);
template double hystereticStoredEnergy<3>(const HystereticSoilModel &, const double *, const double *, const double *);
template double equivalentShearStrain<2>(const double *);
template double equivalentShearStrain<3>(const double *);
template double equivalentShearStress<2>(const double *);
template double equivalentShearStress<3>(const double *);

} // namespace slipwave::physics

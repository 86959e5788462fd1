// Hysteretic (Masing) soil, total stress: the volumetric part elastic (bulk modulus K), the
// deviatoric part a parallel Iwan model (Iwan 1967): N elastic-perfectly-plastic von Mises
// elements in parallel, element i with shear modulus G_i and yield strain gamma_i (the
// engineering shear strain at which it yields in simple shear). The deviatoric stress is
//   s = sum_i 2 G_i (e - p_i),   |e - p_i| <= r_i = gamma_i / sqrt(2),
// with e the deviatoric strain and p_i element i's plastic strain. In simple shear the
// stress on first loading is sum_i G_i min(gamma, gamma_i), a piecewise-linear backbone with
// its kinks at the gamma_i, and a reversal after gamma_a unloads along
// tau_a - 2 F((gamma_a - gamma)/2) exactly (each element stays elastic for twice its yield
// strain): Masing's rules, without iteration. In 3D every element is a closed-form radial
// return. docs/hysteretic-soil.md states the model, its sources and its error.
//
// The model (per region, immutable) is built from Gmax, K, a backbone (soil_backbone.hpp) and
// N: the piecewise-linear backbone passes exactly through the backbone at N knot strains
// log-spaced up to last_knot (a concave backbone; see the constructor for others), starts
// with slope Gmax up to the elastic limit (so the stable step and the small-strain answer are
// those of the linear soil) and is flat (perfectly plastic) beyond the last knot.
//
// The state of a quadrature point is a plain array of hystereticStateSize(model, Dim) doubles
// (zero: the virgin, stress-free state), so a region keeps one flat vector of them, copied or
// checkpointed as it is. The update is a pure function of (model, state, total strain): it may
// write a trial state apart from the committed one, work in place, or only evaluate.
//
// Cost: a point only visits the elements that can yield. Each update that sweeps every element
// also finds a tail of elements (from `head` on) that stay elastic while the strain stays
// within a slack of this update's strain (triangle inequality: |e - p_j| <= |e - e_ref| +
// |e_ref - p_j| <= r_j); the state keeps that reference, the slack and the tail's plastic
// stress sum_{j >= head} 2 G_j p_j, so that while the strain stays within it the tail's stress
// is one multiply-add and its elements are neither read nor written. The head is chosen from
// the measured drift of the strain per update (HystereticSoilModel::tailModulus, .cpp).
#pragma once
#include <vector>

#include "slipwave/physics/soil_backbone.hpp"

namespace slipwave::physics {

// Components of the arrays the update reads and writes:
//   strain, Dim 3: xx, yy, zz, xy, yz, xz (tensor components: eps_xy = gamma_xy / 2);
//           Dim 2 (plane strain, eps_zz = eps_xz = eps_yz = 0): xx, yy, xy.
//   stress, Dim 3: xx, yy, zz, xy, yz, xz; Dim 2: xx, yy, xy, zz (the in-plane ones first, in
//           the strain's order; sigma_zz != 0 in plane strain).
//   state:  kHead (the first element of the tail, an integer), kSlack, kSince (the update
//           that set the tail, in the caller's count of updates), the reference deviatoric
//           strain (kReference, kDeviator values), the tail's plastic stress
//           sum_{j >= head} 2 G_j p_j (kTailStress, kDeviator) and energy sum_{j >= head} G_j |p_j|^2 (kTailEnergy), the largest
//           equivalent shear strain reached (kMaxStrain, output), then the plastic strains p_i
//           from kPlastic on, component-major (c * N + i), all deviators in the components
//           xx, yy, xy [, yz, xz] (zz = -(xx + yy)).
template <int Dim>
struct HystereticLayout {
  static_assert(Dim == 2 || Dim == 3, "plane strain (2) or 3D");
  static constexpr int kStrain = Dim == 2 ? 3 : 6;
  static constexpr int kStress = Dim == 2 ? 4 : 6;
  static constexpr int kDeviator = Dim == 2 ? 3 : 5;
  static constexpr int kHead = 0, kSlack = 1, kSince = 2, kReference = 3;
  static constexpr int kTailStress = kReference + kDeviator, kTailEnergy = kTailStress + kDeviator, kMaxStrain = kTailEnergy + 1, kPlastic = kMaxStrain + 1;
};

struct HystereticSurfaces {
  // N, the number of elements (surfaces): see docs/hysteretic-soil.md for its error and cost.
  int    count = 24;
  // The piecewise-linear backbone is linear (slope Gmax) up to this strain exactly.
  double elastic_limit = 1e-6;
  // The last knot; the model is perfectly plastic at tau(last_knot) beyond it.
  double last_knot = 1e-1;
};

class HystereticSoilModel {
public:
  // Throws std::invalid_argument for Gmax or K <= 0, count outside 2..1000, elastic_limit not
  // in (0, last_knot / 8), or a backbone that falls so fast below the elastic limit that no
  // first knot gives it. A backbone that is not concave and non-decreasing on the knots (a table
  // whose G/Gmax flattens between rows, a curve past a peak) is replaced there by its least
  // concave majorant, the closest curve a parallel Iwan model holds: see knotDeviation().

  HystereticSoilModel(double shear_modulus, double bulk_modulus, const SoilBackbone &backbone, const HystereticSurfaces &surfaces = {});

  int    surfaces() const { return (int)modulus_.size(); }
  double shearModulus() const { return shear_modulus_; }
  double bulkModulus() const { return bulk_modulus_; }
  // The strains where the piecewise-linear backbone equals the backbone (N of them).
  const std::vector<double> &knotStrains() const { return knots_; }
  // Element i: its shear modulus G_i (sum = Gmax) and yield strain gamma_i (ascending:
  // gamma_0 = the elastic limit, gamma_i = knot i for i >= 1; the .cpp says why).
  const std::vector<double> &elementModulus() const { return modulus_; }
  const std::vector<double> &elementYieldStrain() const { return yield_strain_; }
  // The model's backbone tau(gamma) in simple shear: sum_i G_i min(gamma, gamma_i).
  double backboneStress(double gamma) const;
  // tau(gamma) / (Gmax gamma): the secant G/Gmax of a first loading to gamma (1 at gamma = 0).
  double secantModulusRatio(double gamma) const;
  // The strength sum_i G_i gamma_i = tau(last_knot).
  double strength() const { return strength_; }
  // max over the knots of |tau_model - tau_backbone| / tau_backbone: 0 (to round-off) for a
  // concave backbone; else how far the concave majorant moved it (the options layer may warn).
  double knotDeviation() const { return knot_deviation_; }

  // Per-element constants of the update, 2 G_i and r_i = gamma_i / sqrt(2), and the tail's
  // modulus sum_{j >= k} 2 G_j for k = 0..N (N + 1 values).
  const double *twiceModulus() const { return twice_modulus_.data(); }
  const double *radius() const { return radius_.data(); }
  const double *tailModulus() const { return tail_modulus_.data(); }

private:
  double              shear_modulus_, bulk_modulus_, strength_, knot_deviation_ = 0;
  std::vector<double> knots_, modulus_, yield_strain_, twice_modulus_, radius_, tail_modulus_;
};

// Doubles per quadrature point: kDeviator * (N + 2) + 5.
template <int Dim>
int hystereticStateSize(const HystereticSoilModel &model) {
  return HystereticLayout<Dim>::kPlastic + HystereticLayout<Dim>::kDeviator * model.surfaces();
}
// Element i's plastic strain, component c, in a state.
template <int Dim>
double plasticStrain(const HystereticSoilModel &model, const double *state, int c, int i) {
  return state[HystereticLayout<Dim>::kPlastic + c * model.surfaces() + i];
}

// The update. From the state state_in and the total strain, writes the stress (unless stress
// is null) and, unless state_out is null, the new state (state_out == state_in is allowed; the
// stress is the same bits whether or not a state is written). `update` numbers the updates
// that write a state (any count that grows by one per such update, from 1 on a virgin state:
// the steps; unused without state_out, pass 0): the tail's chooser measures the strain's drift per
// update by it, and a point whose tail holds is neither read nor written beyond its header's
// tail (no counter in the state). A caller may skip the updates of a point whose state is
// virgin (zero but kSince) at a zero strain: they change nothing. Returns the energy the
// elements dissipate per unit volume in this update, sum_i R_i |dp_i| with R_i = 2 G_i r_i the
// element's yield stress (>= 0; exactly the plastic work in 1D, where the return is exact for
// any monotone increment). The strain path between the two states is taken as straight (one
// radial return per element: backward Euler, exact in 1D, first order for a path that turns).
// The same with the state in two arrays: its header (the first kPlastic doubles, which every
// update reads) and its plastic strains (read only for the elements that can yield), so that a
// region can keep its points' headers together and stream them. state_out and plastic_out are
// both null or both given (either may be its input).
template <int Dim>
double hystereticUpdate(const HystereticSoilModel &model, const double *state_in, const double *plastic_in, const double *strain, double *stress, double *state_out,
                        double *plastic_out, double update);
template <int Dim>
double hystereticUpdate(const HystereticSoilModel &model, const double *state_in, const double *strain, double *stress, double *state_out, double update) {
  constexpr int kPlastic = HystereticLayout<Dim>::kPlastic;
  return hystereticUpdate<Dim>(model, state_in, state_in + kPlastic, strain, stress, state_out, state_out ? state_out + kPlastic : nullptr, update);
}

// A point's step in one pass over its elements: its state (header, plastic), in place, brought
// to the accepted strain `settled` (update number `update`), then the stress at `strain`
// evaluated from that (the state not written by it). The same bits as
//   hystereticUpdate(model, header, plastic, settled, nullptr, header, plastic, update);
//   hystereticUpdate(model, header, plastic, strain, stress, nullptr, nullptr);
// with each element that both visit read once; returns the first's dissipation.
template <int Dim>
double hystereticSettleEvaluate(const HystereticSoilModel &model, double *header, double *plastic, const double *settled, double update, const double *strain,
                                double *stress);

// A state's kSince to the tail's age at update `now` (now - kSince: the updates since the tail
// was set), and the age back to kSince (the same map). Checkpoints keep the age, so that a
// restarted run may start its count of updates anew.
inline void swapTailAge(double *state, double now) { state[HystereticLayout<2>::kSince] = now - state[HystereticLayout<2>::kSince]; }
static_assert(HystereticLayout<2>::kSince == HystereticLayout<3>::kSince, "kSince is the same slot in 2D and 3D");

// Energy stored per unit volume at (state, strain): K tr(eps)^2 / 2 + sum_i G_i |e - p_i|^2,
// for a state that the update returned for this strain (then |e - p_i| <= r_i); the tail's
// elements from its header (sum G_j |e - p_j|^2 = T |e|^2 / 2 - e:P + E). Work done on a
// point = change of this + the dissipation the updates return. The state in two arrays as for
// the update, or in one.
template <int Dim>
double hystereticStoredEnergy(const HystereticSoilModel &model, const double *state, const double *plastic, const double *strain);
template <int Dim>
double hystereticStoredEnergy(const HystereticSoilModel &model, const double *state, const double *strain) {
  return hystereticStoredEnergy<Dim>(model, state, state + HystereticLayout<Dim>::kPlastic, strain);
}

// Equivalent (octahedral-type) shear strain sqrt(2 e:e) of a strain (= |gamma| in simple
// shear), and equivalent shear stress sqrt(s:s / 2) of a stress (= |tau| in simple shear).
template <int Dim>
double equivalentShearStrain(const double *strain);
template <int Dim>
double equivalentShearStress(const double *stress);
// The largest equivalent shear strain the point has reached (kept in its state).
template <int Dim>
double maxShearStrain(const HystereticSoilModel &, const double *state) {
  return state[HystereticLayout<Dim>::kMaxStrain];
}
// Mobilised strength: equivalent shear stress / strength (1 when every element yields).
template <int Dim>
double mobilisedStrengthRatio(const HystereticSoilModel &model, const double *stress) {
  return equivalentShearStress<Dim>(stress) / model.strength();
}

} // namespace slipwave::physics

// Mohr-Coulomb soil-structure interface law with the explicit gamma-split, for one pair of
// coincident nodes. "spec N" refers to section N of the project's interface-law
// specification, which is not part of this repository; everything the code relies on is
// stated here.
//
// Conventions (spec section 2): w_N > 0 is opening, sigma_N > 0 is tension, the tangential
// traction has the dimension of the tangential jump (1 component in 2D, 2 in 3D).
//
// This runs for every interface pair at every explicit time step, so the update lives in
// this header (inlined into the caller's loop), allocates nothing and holds no PETSc type.
//
// Normal response. The state keeps the opening u beyond the zero-stress state
// (u = w_N - w_N^p - w_N0, with w_N0 the jump of zero normal stress; u < 0 is penetration).
// While in contact sigma_N = min(E u, sigma_t): the tension cut-off is a reversible plateau
// at the tensile strength. Once u exceeds e_ini the pair is open (traction free) and stays
// open until the bodies touch again (u <= 0): the part of the step after the touch is then
// applied from zero traction, so no shear memory survives an opening.
#pragma once

#include <cmath>
#include <cstdint>

#include "slipwave/physics/friction_lag.hpp"

namespace slipwave::physics {

// Angles in radians (the options layer converts from degrees).
struct InterfaceParams {
  double E = 0.0;                // normal penalty stiffness [stress/length]
  double G = 0.0;                // tangential penalty stiffness [stress/length]
  double phi = 0.0;              // friction angle
  double psi = 0.0;              // dilatancy angle
  double c = 0.0;                // cohesion [stress]
  double e_ini = 0.0;            // interface thickness [length]
  double tensile_strength = 0.0; // tension cut-off [stress]
};

// Per-pair constants derived once from InterfaceParams, so the update does no trigonometry.
struct InterfaceLaw {
  double E, G, tan_phi, tan_psi, c, e_ini, sigma_t;
  double H;     // G + E tan(phi) tan(psi), the plastic modulus of the consistency condition
  double inv_H; // 1 / H

  explicit InterfaceLaw(const InterfaceParams &p)
      : E(p.E), G(p.G), tan_phi(std::tan(p.phi)), tan_psi(std::tan(p.psi)), c(p.c), e_ini(p.e_ini),
        sigma_t(p.tensile_strength), H(p.G + p.E * std::tan(p.phi) * std::tan(p.psi)), inv_H(1.0 / H) {}
};

// The law in effective stress, for an interface whose soil side is saturated
// (docs/saturated-soil.md): with the pore pressure p at the soil node (compression positive),
// the yield condition and the tension cut-off act on the effective normal traction
// sigma_N + p, while sigma_N, the traction the springs carry, stays the total one:
// |sigma_T| <= c - (sigma_N + p) tan(phi) = (c - p tan(phi)) - sigma_N tan(phi), and
// sigma_N + p <= sigma_t. Opening and contact stay mechanical (the jump).
inline InterfaceLaw interfaceLawWithPorePressure(InterfaceLaw law, double p) {
  law.c -= p * law.tan_phi;
  law.sigma_t -= p;
  return law;
}

enum class InterfaceStatus : std::uint8_t { Stick = 0, Slip = 1, Open = 2 };

// "stick", "slip" or "open".
const char *interfaceStatusName(InterfaceStatus status);

template <int Dim>
struct InterfaceState {
  static_assert(Dim == 2 || Dim == 3, "interfaces exist in 2D and 3D");
  static constexpr int kTangent = Dim - 1;

  double sigma_T[kTangent]; // tangential traction
  double sigma_N;           // normal traction, tension positive
  double wp_T[kTangent];    // plastic tangential jump
  double wp_N;              // plastic (dilatant) normal jump
  double opening;           // u: normal jump beyond the zero-stress state
  double slip;              // accumulated plastic slip, sum of lambda (path length)
  double dissipation;       // plastic work plus elastic energy lost at each opening
  // sigma*: the effective normal traction the friction sees, kept by a lagged law only
  // (friction_lag.hpp; an instantaneous law leaves it as it was).
  double sigma_friction;
  InterfaceStatus status;
};

// What a lagged law needs over one step (friction_lag.hpp): the lag, the pore pressure p the
// step ends with (0 on dry soil; the law passed with it is interfaceLawWithPorePressure(law,
// p)) and the step dt [s], NaN where no time passes (a static solve): sigma* = sigma' then.
struct FrictionLagStep {
  FrictionLag lag;
  double      p  = 0.0;
  double      dt = NAN;
};

// A pair in contact at rest under the normal traction sigma_N0 (validated beforehand:
// sigma_N0 <= tensile strength).
template <int Dim>
InterfaceState<Dim> interfaceInitialState(const InterfaceLaw &law, double sigma_N0) {
  InterfaceState<Dim> s{};
  s.sigma_N = sigma_N0;
  s.opening = sigma_N0 / law.E;
  s.sigma_friction = sigma_N0;
  s.status = InterfaceStatus::Stick;
  return s;
}

// True while a pair answers as a linear spring: in contact, sticking, and below the tension
// cut-off (sigma_N = E u, not the plateau). A static solve with the stick springs is exact
// only if every pair is on this branch.
template <int Dim>
bool interfaceOnLinearStickBranch(const InterfaceLaw &law, const InterfaceState<Dim> &s) {
  return s.status == InterfaceStatus::Stick && law.E * s.opening <= law.sigma_t;
}

namespace detail {

// sigma* after the part `fraction` of a lagged step, following `target`: the slip is that part
// of the tangential jump increment (NT components); no time (dt NaN) sets sigma* = target.
template <int NT>
double lagNormalTraction(const FrictionLagStep &step, double sigma_star, double target, const double *dw_T, double fraction) {
  if (!std::isfinite(step.dt)) return target;
  double slip = 0.0;
  for (int i = 0; i < NT; ++i) slip += dw_T[i] * dw_T[i];
  return laggedNormalTraction(step.lag, sigma_star, target, fraction * std::sqrt(slip), fraction * step.dt);
}

inline double yieldValue(const InterfaceLaw &law, double norm_T, double sigma_N) {
  return norm_T + sigma_N * law.tan_phi - law.c;
}

// Elastic energy a pair holds; lost when it opens (the energy of a broken bond). An open pair
// is traction-free and holds nothing, however wide it opens: its `opening` is a gap, not the
// stretch of a spring.
template <int Dim>
double storedEnergy(const InterfaceLaw &law, const InterfaceState<Dim> &s) {
  if (s.status == InterfaceStatus::Open) return 0.0;
  double tt = 0.0;
  for (int i = 0; i < Dim - 1; ++i) tt += s.sigma_T[i] * s.sigma_T[i];
  const double u = s.opening, u_t = law.sigma_t / law.E;
  const double normal = u <= u_t ? 0.5 * law.E * u * u : 0.5 * law.sigma_t * u_t + law.sigma_t * (u - u_t);
  return 0.5 * tt / law.G + normal;
}

// Upper end of {gamma in [0,1] : f(sigma_n + gamma dsigma) <= 0} along the elastic path, with
// f(gamma) = |a + gamma b| - (R0 - gamma d); called only when f(1) > 0.
// By bisection: the set is an interval containing 0 (f convex, f(0) <= 0), so keeping
// f(lo) <= 0 < f(hi) closes in on its upper end and never on the reversal root gamma = 0.
template <int NT>
double exitFractionBisect(const double *a, const double *b, double R0, double d) {
  double lo = 0.0, hi = 1.0;
  for (int it = 0; it < 60 && hi - lo > 1e-15; ++it) {
    const double mid = 0.5 * (lo + hi);
    double nn = 0.0;
    for (int i = 0; i < NT; ++i) nn += (a[i] + mid * b[i]) * (a[i] + mid * b[i]);
    (std::sqrt(nn) - (R0 - mid * d) <= 0.0 ? lo : hi) = mid;
  }
  return lo;
}

// Exact exit fraction. In 2D |a + gamma b| is piecewise linear with a kink where sigma_T
// changes sign, so f is linear on each piece and the root is exact. In 3D it is the larger
// admissible root of (|b|^2 - d^2) g^2 + 2 (a.b + R0 d) g + (|a|^2 - R0^2) = 0 (spec 5.4),
// or -1 when roundoff leaves no admissible root (the caller then bisects). 'scale' bounds
// the stress magnitudes involved.
template <int NT>
double exitFraction(const double *a, const double *b, double R0, double d, double scale) {
  if constexpr (NT == 1) {
    const double a0 = a[0], b0 = b[0];
    const double f0 = std::fabs(a0) - R0, f1 = std::fabs(a0 + b0) - R0 + d;
    double gamma;
    if (a0 * (a0 + b0) >= 0.0) {
      gamma = f0 >= 0.0 ? 0.0 : -f0 / (f1 - f0);
    } else {
      const double gk = -a0 / b0, fk = -(R0 - gk * d); // sigma_T = 0 at the kink
      if (fk <= 0.0)
        gamma = gk + (1.0 - gk) * (-fk / (f1 - fk));
      else
        gamma = f0 >= 0.0 ? 0.0 : gk * (-f0 / (fk - f0));
    }
    return gamma < 0.0 ? 0.0 : (gamma > 1.0 ? 1.0 : gamma);
  } else {
    double aa = 0.0, ab = 0.0, bb = 0.0;
    for (int i = 0; i < NT; ++i) {
      aa += a[i] * a[i];
      ab += a[i] * b[i];
      bb += b[i] * b[i];
    }
    const double A = bb - d * d, B = ab + R0 * d, C = aa - R0 * R0;
    double roots[2];
    int n = 0;
    if (std::fabs(A) <= 1e-14 * (bb + d * d)) {
      if (B != 0.0) roots[n++] = -C / (2.0 * B);
    } else {
      const double disc = B * B - A * C;
      if (disc >= 0.0) {
        // Stable pair of roots: no cancellation between B and sqrt(disc).
        const double q = -(B + std::copysign(std::sqrt(disc), B));
        roots[n++] = q / A;
        if (q != 0.0) roots[n++] = C / q;
      }
    }
    double best = -1.0;
    for (int k = 0; k < n; ++k) {
      const double g = roots[k];
      // A root of the squared equation is a root of f only where R0 - g d >= 0.
      if (g >= -1e-12 && g <= 1.0 + 1e-12 && R0 - g * d >= -1e-12 * scale && g > best) best = g;
    }
    return best < -0.5 ? -1.0 : (best < 0.0 ? 0.0 : (best > 1.0 ? 1.0 : best));
  }
}

// Contact update from the committed state s (in contact) for the increment (dw_T, dw_N).
// law is the law at the end of the step; dp the rise of the pore pressure over the step
// (interfaceLawWithPorePressure; 0 on dry soil), which moves the yield surface along the
// path as the normal traction does: the path runs from the law of the step's start
// (cohesion law.c + dp tan(phi)) to that of its end, so a state committed on the start's
// surface starts on it, and the slip a rising pressure forces is found by the consistency
// condition instead of being returned as drift. Returns the drift returned to the yield
// surface [stress].
// With `lagged` the strength is c - sigma* tan(phi) instead (friction_lag.hpp): sigma* moves
// over the step from its committed value to the lagged one, along the path as the effective
// traction does without a lag, and the plastic flow's change of sigma_N (dilatancy) reaches
// the strength only through the lag, so the plastic modulus is G.
template <int Dim>
double contactUpdate(const InterfaceLaw &law, InterfaceState<Dim> &s, const double *dw_T, double dw_N, double dp, const FrictionLagStep *lagged = nullptr) {
  constexpr int NT = Dim - 1;
  const double u_tr = s.opening + dw_N;
  // The part of the normal increment spent on the tension plateau carries no stress.
  const double sN_tr = std::fmin(law.E * u_tr, law.sigma_t);
  const double dsN = sN_tr - s.sigma_N;

  double b[NT], sT_tr[NT], nn_tr = 0.0;
  for (int i = 0; i < NT; ++i) {
    b[i] = law.G * dw_T[i];
    sT_tr[i] = s.sigma_T[i] + b[i];
    nn_tr += sT_tr[i] * sT_tr[i];
  }

  double lambda = 0.0;
  double u_new = u_tr;
  // Lagged: the cohesion on effective stress (law.c is c - p tan(phi)) and sigma* at the end.
  double c_eff = 0.0, friction_end = 0.0;
  if (lagged) {
    c_eff        = law.c + lagged->p * law.tan_phi;
    friction_end = lagNormalTraction<NT>(*lagged, s.sigma_friction, sN_tr + lagged->p, dw_T, 1.0);
  }
  // f(trial) <= 0 compared in squares: no square root on the elastic path.
  const double R_tr = lagged ? c_eff - friction_end * law.tan_phi : law.c - sN_tr * law.tan_phi;
  if (R_tr >= 0.0 && nn_tr <= R_tr * R_tr) {
    for (int i = 0; i < NT; ++i) s.sigma_T[i] = sT_tr[i];
  } else {
    // The effective normal traction changes by dsN + dp along the path (lagged: sigma* by
    // its own change).
    const double R0 = lagged ? c_eff - s.sigma_friction * law.tan_phi : law.c + dp * law.tan_phi - s.sigma_N * law.tan_phi;
    const double d  = lagged ? (friction_end - s.sigma_friction) * law.tan_phi : (dsN + dp) * law.tan_phi;
    double b_l1 = 0.0;
    for (int i = 0; i < NT; ++i) b_l1 += std::fabs(b[i]);
    const double scale = std::fabs(R0) + std::fabs(d) + b_l1;
    double gamma = exitFraction<NT>(s.sigma_T, b, R0, d, scale);
    double sT_star[NT], nn_star = 0.0;
    for (int i = 0; i < NT; ++i) {
      sT_star[i] = s.sigma_T[i] + gamma * b[i];
      nn_star += sT_star[i] * sT_star[i];
    }
    double norm_star = std::sqrt(nn_star);
    if constexpr (NT > 1) {
      if (gamma < 0.0 || std::fabs(norm_star - (R0 - gamma * d)) > 1e-10 * scale) {
        gamma = exitFractionBisect<NT>(s.sigma_T, b, R0, d);
        nn_star = 0.0;
        for (int i = 0; i < NT; ++i) {
          sT_star[i] = s.sigma_T[i] + gamma * b[i];
          nn_star += sT_star[i] * sT_star[i];
        }
        norm_star = std::sqrt(nn_star);
      }
    }
    const double rest = 1.0 - gamma;
    const double sN_star = s.sigma_N + gamma * dsN;
    // At the apex (sigma_T* = 0) the flow direction is the one the shear increment pushes to.
    double t_hat[NT];
    if (norm_star > 1e-13 * scale) {
      const double inv = 1.0 / norm_star;
      for (int i = 0; i < NT; ++i) t_hat[i] = sT_star[i] * inv;
    } else {
      double nb = 0.0;
      for (int i = 0; i < NT; ++i) nb += b[i] * b[i];
      const double inv = nb > 0.0 ? 1.0 / std::sqrt(nb) : 0.0;
      for (int i = 0; i < NT; ++i) t_hat[i] = b[i] * inv;
    }

    double t_dot_b = 0.0;
    for (int i = 0; i < NT; ++i) t_dot_b += t_hat[i] * b[i];
    // (G t.dw_T + E tan(phi) dw_N) / H on the plastic part, with total (not elastic) rates.
    lambda = lagged ? rest * (t_dot_b + d) / law.G : rest * (t_dot_b + law.tan_phi * (dsN + dp)) * law.inv_H;
    if (lambda <= 0.0) {
      lambda = 0.0; // elastic unloading from the yield surface
      for (int i = 0; i < NT; ++i) s.sigma_T[i] = sT_tr[i];
    } else {
      for (int i = 0; i < NT; ++i) {
        s.sigma_T[i] = sT_star[i] + rest * b[i] - lambda * law.G * t_hat[i];
        s.wp_T[i] += lambda * t_hat[i];
      }
      const double sN_end = sN_star + rest * dsN - lambda * law.E * law.tan_psi;
      s.wp_N += lambda * law.tan_psi;
      s.slip += lambda;
      u_new = u_tr - lambda * law.tan_psi;
      // sigma_N and the pore pressure are linear in lambda along the plastic part: the
      // trapezoid rule is exact (the cohesion's mean over it is law.c + rest dp tan(phi) / 2).
      // Lagged: the strength runs from R0 - gamma d to R_tr, and sigma_N does the normal work.
      if (lagged)
        s.dissipation += lambda * (0.5 * (R0 - gamma * d + R_tr) + 0.5 * (sN_star + sN_end) * law.tan_psi);
      else
        s.dissipation += lambda * (law.c + 0.5 * rest * dp * law.tan_phi - 0.5 * (sN_star + sN_end) * (law.tan_phi - law.tan_psi));
    }
  }
  s.opening = u_new;
  s.sigma_N = std::fmin(law.E * u_new, law.sigma_t);

  // Drift: return sigma_T radially at fixed sigma_N and book the excess as plastic slip; the
  // elastic energy removed, (|sigma_T|^2 - R^2) / 2G, is exactly the work of that slip.
  // Excesses within roundoff of the strength (relative 1e-13) are left alone.
  double drift = 0.0;
  const double R = std::fmax(lagged ? R_tr : law.c - s.sigma_N * law.tan_phi, 0.0);
  if (lagged) s.sigma_friction = friction_end;
  double nn = 0.0;
  for (int i = 0; i < NT; ++i) nn += s.sigma_T[i] * s.sigma_T[i];
  if (nn > R * R * (1.0 + 2e-13)) {
    const double norm = std::sqrt(nn);
    drift = norm - R;
    const double scale = R / norm, extra = drift / law.G;
    for (int i = 0; i < NT; ++i) {
      s.wp_T[i] += extra * s.sigma_T[i] / norm;
      s.sigma_T[i] *= scale;
    }
    s.slip += extra;
    s.dissipation += 0.5 * (norm * norm - R * R) / law.G;
  }
  s.status = (lambda > 0.0 || drift > 0.0) ? InterfaceStatus::Slip : InterfaceStatus::Stick;
  return drift;
}

} // namespace detail

// Advances one pair by the jump increment of one step: dw_T has Dim-1 components, dw_N is
// the normal one; on saturated soil law is the law at the step's end pore pressure and dp
// that pressure's rise over the step (contactUpdate). Returns the drift returned to the
// yield surface in this step [stress] (spec 5.7: the caller reports the largest one of a run).
// `lagged`: the friction sees sigma* (friction_lag.hpp); null: sigma_N + p at once.
template <int Dim>
double interfaceUpdate(const InterfaceLaw &law, InterfaceState<Dim> &s, const double *dw_T, double dw_N, double dp = 0.0,
                       const FrictionLagStep *lagged = nullptr) {
  constexpr int NT = Dim - 1;
  // A lagged friction keeps following the effective traction while the pair is open: 0 + p,
  // held at the tension cut-off (law.sigma_t is sigma_t - p), over the part `fraction` of the
  // step. A brief opening (a chattering pair) thus changes sigma* little.
  const auto lag_while_open = [&](double fraction) {
    if (lagged) s.sigma_friction = detail::lagNormalTraction<NT>(*lagged, s.sigma_friction, lagged->p + std::fmin(0.0, law.sigma_t), dw_T, fraction);
  };
  if (s.status == InterfaceStatus::Open) {
    const double u_tr = s.opening + dw_N;
    if (u_tr > 0.0) {
      s.opening = u_tr;
      lag_while_open(1.0);
      return 0.0;
    }
    // Re-contact: the step touches at the fraction beta; what follows starts from zero
    // traction with a fresh tangential reference.
    const double beta = s.opening / (s.opening - u_tr);
    const double rest = 1.0 - beta;
    double dw_rest[NT];
    for (int i = 0; i < NT; ++i) {
      dw_rest[i] = rest * dw_T[i];
      s.sigma_T[i] = 0.0;
    }
    s.sigma_N = 0.0;
    s.opening = 0.0;
    // From zero traction after the touch, the rest of the step runs with the end's law (and
    // a lagged friction over the rest of the step's time).
    lag_while_open(beta);
    if (!lagged) return detail::contactUpdate<Dim>(law, s, dw_rest, u_tr, 0.0);
    FrictionLagStep after_touch = *lagged;
    after_touch.dt *= rest;
    return detail::contactUpdate<Dim>(law, s, dw_rest, u_tr, 0.0, &after_touch);
  }
  if (s.opening + dw_N > law.e_ini) {
    // Lost with the bond: the shear energy (the tangential reference is dropped) and the
    // normal energy where the bond breaks, u = e_ini (or u now, if already beyond it). A
    // compressed pair (u < 0) passes u = 0 on its way out and gives its compression energy
    // back to the bodies through the contact force: booking it too counted it twice (a
    // chattering penalty contact booked ~half the impact energy as "dissipated").
    InterfaceState<Dim> at_break = s;
    at_break.opening = s.opening > law.e_ini ? s.opening : law.e_ini;
    s.dissipation += detail::storedEnergy<Dim>(law, at_break);
    for (int i = 0; i < NT; ++i) s.sigma_T[i] = 0.0;
    s.sigma_N = 0.0;
    s.opening += dw_N;
    s.status = InterfaceStatus::Open;
    lag_while_open(1.0);
    return 0.0;
  }
  return detail::contactUpdate<Dim>(law, s, dw_T, dw_N, dp, lagged);
}

} // namespace slipwave::physics

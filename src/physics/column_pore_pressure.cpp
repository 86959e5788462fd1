#include "slipwave/physics/column_pore_pressure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "slipwave/physics/biot.hpp"
#include "slipwave/physics/cavitation.hpp"
#include "slipwave/physics/split_diffusion_step.hpp"

namespace slipwave::physics {

std::string ColumnPorePressure::setup(const std::vector<double> &heights, const std::vector<ColumnFluidSegment> &segments, const std::vector<ColumnFluidNode> &nodes,
                                      const ColumnFluidRules &rules, const ColumnElement &given) {
  char                buf[200];
  const int           n  = (int)heights.size();
  const ColumnElement el = completeColumnElement(given);
  const int           p  = el.degree;
  if (n < 2 || (int)segments.size() != n - 1 || (int)nodes.size() != n) return "a column's pore pressure needs one fluid per segment and one per node";
  if (p < 1 || (n - 1) % p != 0 || (int)el.w.size() != p + 1 || (int)el.D.size() != (p + 1) * (p + 1))
    return "a column's pore pressure of degree p needs p segments per element, p+1 weights and a (p+1)^2 derivative matrix";
  for (int e = 0; e < n - 1; ++e) {
    const ColumnFluidSegment &s = segments[e];
    if (!(heights[e + 1] > heights[e])) {
      std::snprintf(buf, sizeof buf, "column heights must increase: z[%d] = %g after %g", e + 1, heights[e + 1], heights[e]);
      return buf;
    }
    if (s.saturated && !(s.alpha > 0 && s.alpha <= 1 && s.M > 0 && std::isfinite(s.M) && s.kappa >= 0 && std::isfinite(s.kappa))) {
      std::snprintf(buf, sizeof buf, "saturated segment %d has alpha %g, M %g Pa, kappa %g m^2/(Pa s); allowed: 0 < alpha <= 1, M > 0, kappa >= 0", e, s.alpha, s.M, s.kappa);
      return buf;
    }
    const ColumnFluidSegment &first = segments[e - e % p];
    if (s.saturated != first.saturated || (s.saturated && (s.alpha != first.alpha || s.M != first.M || s.kappa != first.kappa))) {
      std::snprintf(buf, sizeof buf, "the element of degree %d from height %g to %g has segments of different pore fluids", p, heights[e - e % p], heights[e - e % p + p]);
      return buf;
    }
  }
  if (!(rules.dt_diffusion > 0)) return "the diffusion limit must be > 0";
  storage_.clear();
  bool any = false;
  for (const ColumnFluidSegment &s : segments) any = any || s.saturated;
  if (!any) return "";
  element_  = el;
  segments_ = segments;
  rules_    = rules;
  jacobian_.resize((n - 1) / p);
  for (int E = 0; E < elementCount(); ++E) jacobian_[E] = 0.5 * (heights[(E + 1) * p] - heights[E * p]);
  stiffness_ref_.assign((size_t)(p + 1) * (p + 1), 0.0);
  for (int a = 0; a <= p; ++a)
    for (int b = 0; b <= p; ++b)
      for (int q = 0; q <= p; ++q) stiffness_ref_[a * (p + 1) + b] += el.w[q] * el.D[q * (p + 1) + a] * el.D[q * (p + 1) + b];
  storage_.assign(n, 0.0);
  for (int E = 0; E < elementCount(); ++E)
    if (elementFluid(E).saturated)
      for (int a = 0; a <= p; ++a) storage_[E * p + a] += el.w[a] * jacobian_[E] / elementFluid(E).M;
  inv_storage_.assign(n, 0.0);
  hydrostatic_.assign(n, 0.0);
  inflow_rate_.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    // A node no saturated segment touches keeps p = 0, as the main mesh's nodes with S = 0.
    if (storage_[i] > 0 && !nodes[i].drained) inv_storage_[i] = 1.0 / storage_[i];
    hydrostatic_[i] = nodes[i].hydrostatic;
    inflow_rate_[i] = inv_storage_[i] > 0 ? nodes[i].inflow_rate : 0.0;
  }
  for (std::vector<double> *x : {&p_, &qu_, &cavity_, &qu_new_, &p_star_, &hp_}) x->assign(n, 0.0);
  return "";
}

void ColumnPorePressure::couplingTimes(const double *u, int stride, std::vector<double> &q) const {
  const int p = element_.degree;
  std::fill(q.begin(), q.end(), 0.0);
  for (int E = 0; E < elementCount(); ++E) {
    if (!elementFluid(E).saturated) continue;
    for (int a = 0; a <= p; ++a) {
      double div = 0; // J times du/dz at node a
      for (int b = 0; b <= p; ++b) div += element_.D[a * (p + 1) + b] * u[(E * p + b) * stride];
      q[E * p + a] += elementFluid(E).alpha * element_.w[a] * div;
    }
  }
}

void ColumnPorePressure::diffusionTimes(const std::vector<double> &pr, std::vector<double> &hp) const {
  const int p = element_.degree;
  std::fill(hp.begin(), hp.end(), 0.0);
  for (int E = 0; E < elementCount(); ++E) {
    if (!elementFluid(E).saturated) continue;
    const double scale = elementFluid(E).kappa / jacobian_[E];
    for (int a = 0; a <= p; ++a) {
      double row = 0;
      for (int b = 0; b <= p; ++b) row += stiffness_ref_[a * (p + 1) + b] * pr[E * p + b];
      hp[E * p + a] += scale * row;
    }
  }
}

void ColumnPorePressure::start(const double *u, int stride) {
  if (!active()) return;
  couplingTimes(u, stride, qu_);
  std::fill(p_.begin(), p_.end(), 0.0);
  std::fill(cavity_.begin(), cavity_.end(), 0.0);
}

int ColumnPorePressure::substeps(double h) const { return diffusionSubstepsOfDegree(element_.degree, h, rules_.dt_diffusion, rules_.subcycle); }

void ColumnPorePressure::step(double h, const double *u, int stride) {
  if (!active()) return;
  const int    n = (int)storage_.size(), m = substeps(h);
  const double sub = h / m;
  p_star_          = p_;
  for (int k = 0; k < m && h > 0; ++k) {
    diffusionTimes(p_star_, hp_);
    for (int i = 0; i < n; ++i) p_star_[i] -= sub * inv_storage_[i] * hp_[i];
  }
  couplingTimes(u, stride, qu_new_);
  for (int i = 0; i < n; ++i) {
    const bool free = inv_storage_[i] > 0;
    double     p    = free ? p_star_[i] - inv_storage_[i] * (qu_new_[i] - qu_[i]) + h * inflow_rate_[i] : 0.0;
    double     v    = 0;
    if (free && rules_.cavitation) {
      const CavitatedPressure c = cavitationFloor(p - inv_storage_[i] * cavity_[i], rules_.cavitation_pressure - hydrostatic_[i], storage_[i]);
      p                         = c.p;
      v                         = c.cavity;
    }
    p_[i]      = p;
    cavity_[i] = v;
  }
  std::swap(qu_, qu_new_);
}

void ColumnPorePressure::addForce(double scale, double *f, int stride) const {
  const int p = element_.degree;
  for (int E = 0; E < elementCount(); ++E) {
    if (!elementFluid(E).saturated) continue;
    for (int b = 0; b <= p; ++b) {
      double pull = 0;
      for (int a = 0; a <= p; ++a) pull += element_.w[a] * element_.D[a * (p + 1) + b] * p_[E * p + a];
      f[(E * p + b) * stride] += scale * elementFluid(E).alpha * pull;
    }
  }
}

double ColumnPorePressure::diffusionLimit() const {
  const int           p = element_.degree;
  std::vector<double> row(storage_.size(), 0.0);
  for (int E = 0; E < elementCount(); ++E)
    if (elementFluid(E).saturated)
      for (int a = 0; a <= p; ++a)
        for (int b = 0; b <= p; ++b) row[E * p + a] += elementFluid(E).kappa / jacobian_[E] * std::fabs(stiffness_ref_[a * (p + 1) + b]);
  double dt = 1e300;
  for (size_t i = 0; i < storage_.size(); ++i)
    if (inv_storage_[i] > 0) dt = std::min(dt, explicitDiffusionStepOfRow(storage_[i], row[i]));
  return dt;
}

double ColumnPorePressure::undrainedRow(int node) const {
  if (!active()) return 0.0;
  // Degree 1: each saturated segment of node a contributes |alpha/2| to both of its u-nodes.
  auto saturated = [&](int e) { return e >= 0 && e < elementCount() && elementFluid(e).saturated; };
  auto w         = [&](int a) {
    double sum = 0;
    for (int e = a - 1; e <= a; ++e)
      if (saturated(e)) sum += elementFluid(e).alpha;
    return sum * inv_storage_[a];
  };
  double row = 0;
  for (int e = node - 1; e <= node; ++e)
    if (saturated(e)) row += 0.5 * elementFluid(e).alpha * (w(e) + w(e + 1));
  return row;
}

double ColumnPorePressure::undrainedModulus(int E) const {
  if (!active() || !elementFluid(E).saturated) return 0.0;
  const ColumnFluidSegment &f = elementFluid(E);
  return f.alpha * f.alpha * f.M;
}

std::vector<double> ColumnPorePressure::state() const {
  std::vector<double> s(p_);
  s.insert(s.end(), qu_.begin(), qu_.end());
  s.insert(s.end(), cavity_.begin(), cavity_.end());
  return s;
}

void ColumnPorePressure::setState(const double *s) {
  const size_t n = storage_.size();
  std::copy(s, s + n, p_.begin());
  std::copy(s + n, s + 2 * n, qu_.begin());
  std::copy(s + 2 * n, s + 3 * n, cavity_.begin());
}

} // namespace slipwave::physics

#include "slipwave/physics/column_pore_pressure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "slipwave/physics/biot.hpp"
#include "slipwave/physics/cavitation.hpp"

namespace slipwave::physics {

std::string ColumnPorePressure::setup(const std::vector<double> &heights, const std::vector<ColumnFluidSegment> &segments, const std::vector<ColumnFluidNode> &nodes,
                                      const ColumnFluidRules &rules) {
  char      buf[200];
  const int n = (int)heights.size();
  if (n < 2 || (int)segments.size() != n - 1 || (int)nodes.size() != n) return "a column's pore pressure needs one fluid per segment and one per node";
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
  }
  if (!(rules.dt_diffusion > 0)) return "the diffusion limit must be > 0";
  storage_.clear();
  bool any = false;
  for (const ColumnFluidSegment &s : segments) any = any || s.saturated;
  if (!any) return "";
  length_.resize(n - 1);
  for (int e = 0; e < n - 1; ++e) length_[e] = heights[e + 1] - heights[e];
  segments_ = segments;
  rules_    = rules;
  storage_.assign(n, 0.0);
  for (int e = 0; e < n - 1; ++e)
    if (segments_[e].saturated)
      for (int a = 0; a < 2; ++a) storage_[e + a] += length_[e] / (2 * segments_[e].M);
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
  std::fill(q.begin(), q.end(), 0.0);
  for (size_t e = 0; e < length_.size(); ++e) {
    if (!segments_[e].saturated) continue;
    const double half = 0.5 * segments_[e].alpha * (u[(e + 1) * stride] - u[e * stride]);
    q[e] += half;
    q[e + 1] += half;
  }
}

void ColumnPorePressure::diffusionTimes(const std::vector<double> &p, std::vector<double> &hp) const {
  std::fill(hp.begin(), hp.end(), 0.0);
  for (size_t e = 0; e < length_.size(); ++e) {
    if (!segments_[e].saturated) continue;
    const double flux = segments_[e].kappa / length_[e] * (p[e] - p[e + 1]);
    hp[e] += flux;
    hp[e + 1] -= flux;
  }
}

void ColumnPorePressure::start(const double *u, int stride) {
  if (!active()) return;
  couplingTimes(u, stride, qu_);
  std::fill(p_.begin(), p_.end(), 0.0);
  std::fill(cavity_.begin(), cavity_.end(), 0.0);
}

int ColumnPorePressure::substeps(double h) const { return diffusionSubsteps(h, rules_.dt_diffusion, rules_.subcycle); }

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
  for (size_t e = 0; e < length_.size(); ++e) {
    if (!segments_[e].saturated) continue;
    const double half = scale * 0.5 * segments_[e].alpha * (p_[e] + p_[e + 1]);
    f[e * stride] -= half;
    f[(e + 1) * stride] += half;
  }
}

double ColumnPorePressure::diffusionLimit() const {
  double dt = 1e300;
  for (size_t i = 0; i < storage_.size(); ++i) {
    if (!(inv_storage_[i] > 0)) continue;
    double row = 0;
    for (size_t e = (i > 0 ? i - 1 : 0); e <= i && e < length_.size(); ++e)
      if (segments_[e].saturated) row += 2 * segments_[e].kappa / length_[e];
    dt = std::min(dt, explicitDiffusionStepOfRow(storage_[i], row));
  }
  return dt;
}

double ColumnPorePressure::undrainedRow(int node) const {
  if (!active()) return 0.0;
  // w_a: each saturated segment of node a contributes |alpha/2| to both of its u-nodes.
  auto w = [&](int a) {
    double sum = 0;
    for (int e = a - 1; e <= a; ++e)
      if (e >= 0 && e < (int)length_.size() && segments_[e].saturated) sum += segments_[e].alpha;
    return sum * inv_storage_[a];
  };
  double row = 0;
  for (int e = node - 1; e <= node; ++e)
    if (e >= 0 && e < (int)length_.size() && segments_[e].saturated) row += 0.5 * segments_[e].alpha * (w(e) + w(e + 1));
  return row;
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

// The free-field column's pore pressure (physics/column_pore_pressure) alone and inside the
// column (physics/free_field_column): its storage, coupling and Darcy sums, one step worked
// by hand, the undrained limit (the undrained P modulus, the undrained wave), sub-stepping,
// the cavitation floor, drained and dry nodes, the stable step and the checkpoint state.
#include <cmath>
#include <cstdio>
#include <vector>

#include "slipwave/physics/biot.hpp"
#include "slipwave/physics/column_pore_pressure.hpp"
#include "slipwave/physics/elastic_material.hpp"
#include "slipwave/physics/free_field_column.hpp"
#include "slipwave/physics/source_time_function.hpp"
#include "slipwave/physics/split_diffusion_step.hpp"
#include "gll_column.hpp"
#include "unit_check.hpp"

using slipwave::physics::ColumnFluidNode;
using slipwave::physics::ColumnFluidRules;
using slipwave::physics::ColumnFluidSegment;
using slipwave::physics::ColumnPorePressure;
using slipwave::physics::ElasticMaterial;
using slipwave::physics::FreeFieldColumn;

namespace {

std::vector<double> uniformHeights(double H, int n) {
  std::vector<double> z(n + 1);
  for (int i = 0; i <= n; ++i) z[i] = H * i / n;
  return z;
}

// Three segments: saturated (L 1), saturated (L 2, other numbers), dry (L 1).
// S = sum of L/(2M) over saturated neighbours, 0 at the node between dry segments only; the
// coupling of u = eps z sums to alpha eps over the saturated length; uniform p with no
// drainage and a skeleton at rest stays exactly uniform (H's rows sum to zero).
void sums() {
  const std::vector<double>             z{0, 1, 3, 4};
  const std::vector<ColumnFluidSegment> seg{{true, 0.8, 1e9, 1e-9}, {true, 0.6, 2e9, 3e-9}, {false, 0, 0, 0}};
  ColumnPorePressure                    col;
  unit::check(col.setup(z, seg, std::vector<ColumnFluidNode>(4), ColumnFluidRules()).empty() && col.active(), "three-segment setup");
  unit::near(col.storage(0), 1 / 2e9, 1e-15, 0, "storage of the base: L/(2M) of its segment");
  unit::near(col.storage(1), 1 / 2e9 + 2 / 4e9, 1e-15, 0, "storage between two saturated segments: the sum of their L/(2M)");
  unit::near(col.storage(2), 2 / 4e9, 1e-15, 0, "storage at a saturated/dry contact: the saturated side's only");
  unit::check(col.storage(3) == 0 && !col.free(3), "a node of dry segments only stores nothing and is not free");
  unit::check(col.alpha(0) == 0.8 && col.alpha(2) == 0, "alpha per segment, 0 in a dry one");
  // Coupling through one undrained step (kappa 0 would be needed for exactness: take h = 0
  // so the diffusion does nothing): p_i = -(alpha Q u)_i / S_i.
  const double        eps = 1e-4;
  std::vector<double> u{0, eps * 1, eps * 3, eps * 4};
  std::vector<double> rest(4, 0.0);
  col.start(rest.data(), 1);
  col.step(0.0, u.data(), 1);
  double sum = 0;
  for (int i = 0; i < 4; ++i) sum -= col.pressure(i) * col.storage(i);
  unit::near(sum, 0.8 * eps * 1 + 0.6 * eps * 2, 1e-14, 0, "sum of alpha Q u over the nodes = sum of alpha eps L over saturated segments");
  // A uniform pressure, skeleton at rest, no drained node: unchanged by any diffusion.
  ColumnPorePressure uniform;
  uniform.setup(z, seg, std::vector<ColumnFluidNode>(4), ColumnFluidRules());
  std::vector<double> state = uniform.state();
  for (int i = 0; i < 3; ++i) state[i] = 5e4;
  uniform.setState(state.data());
  for (int k = 0; k < 10; ++k) uniform.step(1e3, rest.data(), 1);
  unit::check(uniform.pressure(0) == 5e4 && uniform.pressure(1) == 5e4 && uniform.pressure(2) == 5e4, "uniform p, noflow ends, skeleton at rest: unchanged (H rows sum to zero)");
  // A prescribed inflow raises its free node's pressure by h q/S per step (k = 0, skeleton at
  // rest); a drained node ignores it.
  std::vector<ColumnFluidNode> inflow(4);
  inflow[0].inflow_rate = 2e3;
  inflow[2]             = {true, 0, 2e3};
  ColumnPorePressure fed;
  fed.setup(z, {{true, 0.8, 1e9, 0}, {true, 0.6, 2e9, 0}, {false, 0, 0, 0}}, inflow, ColumnFluidRules());
  fed.start(rest.data(), 1);
  for (int k = 0; k < 5; ++k) fed.step(0.01, rest.data(), 1);
  unit::near(fed.pressure(0), 5 * 0.01 * 2e3, 1e-14, 0, "inflow: p rises by h q/S per step");
  unit::check(fed.pressure(1) == 0 && fed.pressure(2) == 0, "inflow: nothing elsewhere (k = 0), and a drained node ignores its own");
}

// Two saturated segments, heights 0, 1, 3; alpha 0.8, M 1e9, kappa 1e-9; top drained. Start at
// rest, step to u = (0, 1e-3, 3e-3): alpha Q u = (4e-4, 4e-4 + 8e-4, 8e-4), S = (5e-10,
// 1.5e-9, 1e-9), so p = (-8e5, -8e5, 0). A second step of h = 0.1 s with the skeleton at rest
// only diffuses: H p = (0, -4e-4, 4e-4) (segment 1: kappa/2 (p_1 - p_2)), so
// p_1 = -8e5 + 0.1 * 4e-4 / 1.5e-9 = -773333.33..., p_0 unchanged. Force on the skeleton:
// f_0 = -0.4 (p_0 + p_1), f_1 = 0.4 (p_0 + p_1) - 0.4 (p_1 + p_2), f_2 = 0.4 (p_1 + p_2).
void byHand() {
  ColumnPorePressure                    col;
  const std::vector<ColumnFluidSegment> seg(2, {true, 0.8, 1e9, 1e-9});
  std::vector<ColumnFluidNode>          nodes(3);
  nodes[2].drained = true;
  unit::check(col.setup({0, 1, 3}, seg, nodes, ColumnFluidRules()).empty(), "two-segment setup");
  std::vector<double> rest(3, 0.0), u{0, 1e-3, 3e-3};
  col.start(rest.data(), 1);
  col.step(0.1, u.data(), 1);
  unit::near(col.pressure(0), -8e5, 1e-14, 0, "by hand: p_0 after the strain step");
  unit::near(col.pressure(1), -8e5, 1e-14, 0, "by hand: p_1 after the strain step");
  unit::check(col.pressure(2) == 0, "by hand: the drained top holds p = 0");
  col.step(0.1, u.data(), 1);
  unit::near(col.pressure(0), -8e5, 1e-14, 0, "by hand: p_0 after diffusion (no gradient below it)");
  unit::near(col.pressure(1), -8e5 + 0.1 * 4e-4 / 1.5e-9, 1e-14, 0, "by hand: p_1 after diffusion towards the drained top");
  const double p0 = col.pressure(0), p1 = col.pressure(1);
  std::vector<double> f(3, 0.0);
  col.addForce(1.0, f.data(), 1);
  unit::near(f[0], -0.4 * (p0 + p1), 1e-14, 0, "by hand: force on the base node");
  unit::near(f[1], 0.4 * (p0 + p1) - 0.4 * p1, 1e-14, 0, "by hand: force on the middle node");
  unit::near(f[2], 0.4 * p1, 1e-14, 0, "by hand: force on the top node");
  unit::near(col.diffusionLimit(), 2 * 5e-10 / 2e-9, 1e-14, 0, "own diffusion limit: 2 S / sum |H| of the base node (the middle one allows 1 s)");
}

// k = 0, uniform strain eps: p = -alpha M eps at every node, the pore force vanishes inside
// and is -alpha^2 M eps on the top, so the top carries (E + alpha^2 M) eps: the undrained P
// modulus.
void undrainedModulus() {
  const double                          alpha = 0.9, M = 4e9, eps = -2e-4;
  ColumnPorePressure                    col;
  col.setup(uniformHeights(10, 7), std::vector<ColumnFluidSegment>(7, {true, alpha, M, 0}), std::vector<ColumnFluidNode>(8), ColumnFluidRules());
  std::vector<double> rest(8, 0.0), u(8), f(8, 0.0);
  for (int i = 0; i < 8; ++i) u[i] = eps * 10 * i / 7;
  col.start(rest.data(), 1);
  col.step(1e-3, u.data(), 1);
  double worst = 0;
  for (int i = 0; i < 8; ++i) worst = std::max(worst, std::fabs(col.pressure(i) + alpha * M * eps));
  unit::near(worst, 0, 0, 1e-12 * alpha * M * std::fabs(eps), "k = 0, uniform strain: p = -alpha M eps at every node");
  col.addForce(1.0, f.data(), 1);
  double inner = 0;
  for (int i = 1; i < 7; ++i) inner = std::max(inner, std::fabs(f[i]));
  unit::near(inner, 0, 0, 1e-12 * alpha * alpha * M * std::fabs(eps), "k = 0, uniform strain: no pore force inside");
  unit::near(f[7], -alpha * alpha * M * eps, 1e-13, 0, "k = 0, uniform strain: pore force on the top -alpha^2 M eps (undrained modulus E + alpha^2 M)");
}

// The column with a saturated skeleton (vp 400) and k = 0 carries the undrained P wave: its
// surface velocity is 2 v_in(t - H/c_u), c_u the undrained speed. The SV bound is the dry
// closed-form check's (test_free_field_column: 1.5 %, 4.6e-3 here); the undrained wave has
// 340 nodes per wavelength at the Ricker's top frequency (13.8 Hz), so its dispersion error is
// ~1e-5 (2.3e-5 measured) and a bound of 1e-3 would catch a speed off by 0.1 %. The base takes
// the undrained impedance, so the incident wave doubles and leaves again (an impedance off
// by 1 % would leave 5e-3 of the peak behind); the SV wave leaves p and the vertical chain
// exactly at rest.
void undrainedWave() {
  const ElasticMaterial m{2000, 400, 200};
  const double          H = 100, alpha = 1, M = 2.2e9 / 0.4;
  const auto            lm = slipwave::physics::lame(m);
  const double          cu = slipwave::physics::undrainedPWaveSpeed(lm.lambda + 2 * lm.mu / 3, lm.mu, alpha, M, m.rho);
  const int             n  = 278;
  for (int p_wave = 0; p_wave < 2; ++p_wave) {
    FreeFieldColumn col;
    unit::check(col.setup(2, uniformHeights(H, n), std::vector<ElasticMaterial>(n, m), 0, 0).empty(), "saturated column setup");
    col.setInput(p_wave ? 1 : 0, p_wave);
    unit::check(col.setPorePressure(std::vector<ColumnFluidSegment>(n, {true, alpha, M, 0}), std::vector<ColumnFluidNode>(n + 1), ColumnFluidRules()).empty() && col.saturated(),
                "saturated column: pore pressure set up");
    const slipwave::physics::RickerWavelet w{0.1, 5, 0.24};
    const double h = 0.9 * col.stableStep(), c = p_wave ? cu : m.vs, t_end = 0.24 + 3 * H / c + 0.5;
    col.start(0, slipwave::physics::velocity(w, 0));
    double num = 0, den = 0, late = 0, peak = 0, other = 0;
    const int top = col.nodeCount() - 1, comp = p_wave ? 1 : 0;
    while (col.time() < t_end) {
      const double t = col.time() + h;
      col.step(h, slipwave::physics::velocity(w, t));
      const double got = col.velocity(top, comp), want = 2 * slipwave::physics::velocity(w, t - H / c);
      peak = std::max(peak, std::fabs(got));
      if (t < 0.24 + H / c + 0.4) num += (got - want) * (got - want), den += want * want;
      if (t > 0.24 + 3 * H / c + 0.4) late = std::max(late, std::fabs(got));
      other = std::max(other, std::fabs(col.velocity(top, 1 - comp)));
      if (!p_wave)
        for (int i = 0; i <= top; ++i) other = std::max(other, std::fabs(col.pore().pressure(i)));
    }
    char what[200];
    const double bound = p_wave ? 1e-3 : 1.5e-2;
    std::snprintf(what, sizeof what, "%s, k = 0: surface velocity = 2 v_in(t - H/c) at c = %s, L2 error %.3e <= %.1e", p_wave ? "P" : "SV",
                  p_wave ? "the undrained vp 1706" : "vs", std::sqrt(num / den), bound);
    unit::check(std::sqrt(num / den) <= bound, what);
    std::snprintf(what, sizeof what, "%s, k = 0: motion after the wave left the base %.2e of the peak <= 1e-3", p_wave ? "P" : "SV", late / peak);
    unit::check(late / peak <= 1e-3, what);
    unit::check(other == 0.0, p_wave ? "P: the horizontal chain stays exactly at rest" : "SV: the vertical chain and p stay exactly at rest");
  }
}

// One step of h with m diffusion sub-steps is m steps of h/m with the skeleton at rest, bit
// for bit; the count is ceil(h / (0.9 dt_diffusion)), 1 without sub-cycling.
void substeps() {
  const std::vector<ColumnFluidSegment> seg(5, {true, 1, 5e9, 1e-6});
  std::vector<ColumnFluidNode>          nodes(6);
  nodes[5].drained = true;
  const double h = 1e-3, m = 7;
  ColumnFluidRules rules;
  rules.dt_diffusion = h / (0.9 * m) * 1.0001;
  ColumnPorePressure a, b;
  a.setup(uniformHeights(5, 5), seg, nodes, rules);
  b = a;
  unit::check(a.substeps(h) == 7 && a.substeps(h / m) == 1, "sub-steps: ceil(h / (0.9 dt_diffusion))");
  std::vector<double> rest(6, 0.0), u{0, -1e-4, -2e-4, -3e-4, -4e-4, -5e-4};
  a.start(rest.data(), 1);
  b.start(rest.data(), 1);
  a.step(h, u.data(), 1);
  b.step(h, u.data(), 1);
  a.step(h, u.data(), 1);
  for (int k = 0; k < m; ++k) b.step(h / m, u.data(), 1);
  unit::check(a.state() == b.state() && a.pressure(0) != 0, "one step of 7 sub-steps = 7 steps of h/7 with the skeleton at rest, bit for bit");
  rules.subcycle = false;
  ColumnPorePressure c;
  c.setup(uniformHeights(5, 5), seg, nodes, rules);
  unit::check(c.substeps(h) == 1, "without sub-cycling: one diffusion step per step");
}

// Cavitation: extension past the limit holds the total pressure p_h + p at the limit and opens
// a cavity S (limit - p_h - p_closed); compressing back closes the cavity before p rises. A
// drained node holds p = 0 and no cavity.
void cavitation() {
  const double                          alpha = 1, M = 1e9, ph = 2e4;
  ColumnFluidRules                      rules;
  rules.cavitation          = true;
  rules.cavitation_pressure = -1e5;
  std::vector<ColumnFluidNode> nodes(3, {false, ph, 0});
  nodes[2].drained = true;
  ColumnPorePressure col;
  col.setup({0, 1, 2}, std::vector<ColumnFluidSegment>(2, {true, alpha, M, 0}), nodes, rules);
  std::vector<double> rest(3, 0.0), pull{0, 5e-4, 1e-3}, back{0, 2e-4, 4e-4};
  col.start(rest.data(), 1);
  col.step(1e-3, pull.data(), 1); // uniform strain 5e-4: p_closed = -alpha M eps = -5e5
  const double floor = -1e5 - ph;
  unit::near(col.pressure(0), floor, 1e-15, 0, "cavitation: p held at the limit less p_h");
  unit::near(col.cavity(0), col.storage(0) * (floor + 5e5), 1e-14, 0, "cavitation: cavity S (floor - p_closed)");
  unit::check(col.pressure(2) == 0 && col.cavity(2) == 0, "cavitation: a drained node holds p = 0 and no cavity");
  col.step(1e-3, back.data(), 1); // back to strain 2e-4: p_closed = -2e5, still below the floor
  unit::near(col.pressure(0), floor, 1e-15, 0, "cavitation: compressing back, the cavity closes first (p still at the limit)");
  unit::near(col.cavity(0), col.storage(0) * (floor + 2e5), 1e-14, 0, "cavitation: the cavity shrinks to S (floor - p_closed)");
  col.step(1e-3, rest.data(), 1);
  unit::check(col.cavity(0) == 0 && std::fabs(col.pressure(0)) <= 1e-9, "cavitation: back at rest, the cavity closed and p = 0");
}

// The undrained Gershgorin rows are the main mesh's bound (4 alpha^2 M / L inside a uniform
// column): the saturated column's step is that of a dry column of the undrained modulus.
// The checkpoint state continues bit for bit.
void stepAndState() {
  const ElasticMaterial m{2000, 400, 200};
  const double          alpha = 1, M = 5.5e9;
  const auto            lm = slipwave::physics::lame(m);
  const double          cu = slipwave::physics::undrainedPWaveSpeed(lm.lambda + 2 * lm.mu / 3, lm.mu, alpha, M, m.rho);
  FreeFieldColumn       wet, dry;
  wet.setup(2, uniformHeights(10, 10), std::vector<ElasticMaterial>(10, m), 0, 0);
  wet.setPorePressure(std::vector<ColumnFluidSegment>(10, {true, alpha, M, 1e-9}), std::vector<ColumnFluidNode>(11), ColumnFluidRules());
  unit::near(wet.pore().undrainedRow(5), 4 * alpha * alpha * M / 1.0, 1e-14, 0, "undrained row of an inner node: 4 alpha^2 M / L");
  dry.setup(2, uniformHeights(10, 10), std::vector<ElasticMaterial>(10, ElasticMaterial{2000, cu, 200}), 0, 0);
  unit::near(wet.stableStep(), dry.stableStep(), 1e-12, 0, "saturated column's stable step = a dry column's of the undrained vp");
  wet.setInput(1, true);
  wet.start(0, 0.1);
  for (int k = 0; k < 50; ++k) wet.step(1e-4, 0.1);
  FreeFieldColumn copy = wet;
  copy.start(0, 0);
  unit::check(copy.setState(wet.state()), "saturated column: state restored");
  wet.step(1e-4, 0.1);
  copy.step(1e-4, 0.1);
  unit::check(copy.state() == wet.state() && wet.pore().pressure(0) != 0, "saturated column: the restored column continues bit-identically");
  unit::check(!dry.setState(wet.state()), "saturated column: its state does not fit a dry column");
}


// Degree p = 2, 4 (GLL-collocated pressure, as the main mesh's at p > 1): the storage of an
// element sums to L/M; a uniform or linear p makes no Darcy flux at inner nodes (H's rows sum
// to 0, and the GLL rule integrates a linear p's gradient exactly); the undrained step's force
// undrained uniform strain gives p = -alpha M eps at every node; one element's undrained force
// alpha Q^T S^-1 alpha Q u is its stiffness with modulus alpha^2 M, alpha^2 M / J sum_q w_q
// D_qa D_qb u_b, worked here from the element's tables (the stable step's bound); the sub-step
// count is the split rule's (even); a column whose element mixes two fluids is refused; and
// the stable step with the coupling factor c is that of a dry column of P modulus
// lambda + 2 mu + c alpha^2 M (the element bound scales with the modulus).
void higherDegree() {
  const double          alpha = 0.9, M = 2e9, H = 6;
  const ElasticMaterial m{2000, 400, 200};
  for (int p : {2, 4}) {
    const auto          el = gllElement(p);
    const int           ne = 3, n = ne * p + 1;
    const auto          z  = gllHeights(H, ne, el);
    const double        J  = H / ne / 2;
    ColumnPorePressure  col;
    char                what[160];
    std::snprintf(what, sizeof what, "degree %d: setup", p);
    unit::check(col.setup(z, std::vector<ColumnFluidSegment>(n - 1, {true, alpha, M, 0}), std::vector<ColumnFluidNode>(n), ColumnFluidRules(), el).empty(), what);
    double total = 0;
    for (int i = 0; i < n; ++i) total += col.storage(i);
    std::snprintf(what, sizeof what, "degree %d: storage sums to H/M", p);
    unit::near(total, H / M, 1e-14, 0, what);
    // Undrained (kappa = 0), one step from rest to a uniform strain eps: p = -alpha M eps at
    // every node (no fluid content change), the GLL derivative being exact on a linear u.
    std::vector<double> u(n), zero(n, 0.0);
    const double        eps = 1e-4;
    for (int i = 0; i < n; ++i) u[i] = eps * z[i];
    col.start(zero.data(), 1);
    col.step(1e-3, u.data(), 1);
    double err = 0;
    for (int i = 0; i < n; ++i) err = std::max(err, std::fabs(col.pressure(i) + alpha * M * eps));
    std::snprintf(what, sizeof what, "degree %d: undrained uniform strain: p = -alpha M eps at every node (error %.1e Pa of %.1e)", p, err, alpha * M * eps);
    unit::check(err <= 1e-12 * alpha * M * eps, what);
    // One element, u = sin(z): the undrained force alpha Q^T S^-1 alpha Q u is the element's
    // stiffness with modulus alpha^2 M, alpha^2 M / J sum_q w_q D_qa D_qb u_b (S is the
    // element's own here; assembled over elements it is the sum, which this bounds).
    {
      const auto         z1 = gllHeights(H / ne, 1, el);
      ColumnPorePressure one;
      one.setup(z1, std::vector<ColumnFluidSegment>(p, {true, alpha, M, 0}), std::vector<ColumnFluidNode>(p + 1), ColumnFluidRules(), el);
      std::vector<double> u1(p + 1), f(p + 1, 0.0);
      for (int i = 0; i <= p; ++i) u1[i] = 1e-4 * std::sin(z1[i]);
      one.start(zero.data(), 1);
      one.step(1e-3, u1.data(), 1);
      one.addForce(-1.0, f.data(), 1);
      double peak = 0;
      err         = 0;
      for (int a = 0; a <= p; ++a) {
        double k_u = 0;
        for (int b = 0; b <= p; ++b)
          for (int q = 0; q <= p; ++q) k_u += alpha * alpha * M / J * el.w[q] * el.D[q * (p + 1) + a] * el.D[q * (p + 1) + b] * u1[b];
        err  = std::max(err, std::fabs(f[a] - k_u));
        peak = std::max(peak, std::fabs(k_u));
      }
      std::snprintf(what, sizeof what, "degree %d: one element's undrained force = its stiffness of modulus alpha^2 M (error %.1e of %.1e)", p, err, peak);
      unit::check(err <= 1e-12 * peak, what);
    }
    // Darcy: uniform and linear p, sealed column at rest: inner nodes unchanged.
    ColumnPorePressure flow;
    std::vector<ColumnFluidNode> nodes(n);
    flow.setup(z, std::vector<ColumnFluidSegment>(n - 1, {true, alpha, M, 1e-9}), nodes, ColumnFluidRules{1e300, true, false, 0}, el);
    std::vector<double> state = flow.state();
    for (int i = 0; i < n; ++i) state[i] = 1e3 + 50 * z[i];
    flow.setState(state.data());
    flow.step(1e-3, zero.data(), 1);
    err = 0;
    for (int i = 1; i < n - 1; ++i) err = std::max(err, std::fabs(flow.pressure(i) - (1e3 + 50 * z[i])));
    std::snprintf(what, sizeof what, "degree %d: a linear p makes no flux at inner nodes (largest change %.1e Pa)", p, err);
    unit::check(err <= 1e-9, what);
    std::snprintf(what, sizeof what, "degree %d: sub-steps by the split rule (even)", p);
    ColumnPorePressure sub;
    sub.setup(z, std::vector<ColumnFluidSegment>(n - 1, {true, alpha, M, 1e-9}), nodes, ColumnFluidRules{1e-3, true, false, 0}, el);
    unit::check(sub.substeps(0.02) == slipwave::physics::splitDiffusionSubsteps(0.02, 1e-3, true) && sub.substeps(0.02) % 2 == 0, what);
    std::vector<ColumnFluidSegment> mixed(n - 1, {true, alpha, M, 0});
    mixed[1] = {true, alpha, 2 * M, 0};
    std::snprintf(what, sizeof what, "degree %d: an element with two fluids is refused", p);
    unit::check(!ColumnPorePressure().setup(z, mixed, nodes, ColumnFluidRules(), el).empty(), what);
    // The stable step with the coupling factor.
    for (double c : {1.0, 2.0}) {
      FreeFieldColumn wet, dry;
      wet.setup(2, z, std::vector<ElasticMaterial>(n - 1, m), 0, 0, el);
      wet.setPorePressure(std::vector<ColumnFluidSegment>(n - 1, {true, alpha, M, 1e-9}), nodes, ColumnFluidRules());
      const auto   lm  = slipwave::physics::lame(m);
      const double vpc = std::sqrt((lm.lambda + 2 * lm.mu + c * alpha * alpha * M) / m.rho);
      dry.setup(2, z, std::vector<ElasticMaterial>(n - 1, ElasticMaterial{2000, vpc, 200}), 0, 0, el);
      std::snprintf(what, sizeof what, "degree %d: stable step with c = %g = a dry column's of modulus lambda + 2 mu + c alpha^2 M", p, c);
      unit::near(wet.stableStep(c), dry.stableStep(), 1e-12, 0, what);
    }
  }
}

} // namespace

int main() {
  sums();
  byHand();
  undrainedModulus();
  undrainedWave();
  substeps();
  cavitation();
  stepAndState();
  higherDegree();
  return unit::failures();
}

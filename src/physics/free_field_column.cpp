#include "slipwave/physics/free_field_column.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "slipwave/physics/stable_time_step.hpp"

namespace slipwave::physics {

std::string FreeFieldColumn::setup(int dim, const std::vector<double> &heights, const std::vector<ElasticMaterial> &materials, double alpha, double beta) {
  char buf[200];
  if (dim != 2 && dim != 3) return "the dimension must be 2 or 3";
  if (heights.size() < 2) return "a free-field column needs at least two node heights";
  if (materials.size() != heights.size() - 1) return "a free-field column needs one material per segment";
  for (size_t i = 1; i < heights.size(); ++i)
    if (!(heights[i] > heights[i - 1])) {
      std::snprintf(buf, sizeof buf, "free-field column heights must increase: z[%zu] = %g after %g", i, heights[i], heights[i - 1]);
      return buf;
    }
  for (const ElasticMaterial &m : materials) {
    const std::string p = elasticMaterialProblem(m);
    if (!p.empty()) return p;
  }
  if (!(alpha >= 0) || !(beta >= 0)) return "Rayleigh coefficients must be >= 0";
  dim_   = dim;
  z_     = heights;
  mat_   = materials;
  alpha_ = alpha;
  beta_  = beta;
  const int n = (int)z_.size();
  mass_.assign(n, 0.0);
  k_.assign((n - 1) * dim_, 0.0);
  for (int e = 0; e < n - 1; ++e) {
    const double L = z_[e + 1] - z_[e];
    const auto   lm = lame(mat_[e]);
    mass_[e] += mat_[e].rho * L / 2;
    mass_[e + 1] += mat_[e].rho * L / 2;
    for (int c = 0; c < dim_; ++c) k_[e * dim_ + c] = (c == dim_ - 1 ? lm.lambda + 2 * lm.mu : lm.mu) / L;
  }
  modulus_factor_.assign(n - 1, 1.0);
  memory_omega_.clear();
  memory_weight_.clear();
  zeta_.clear();
  spring_old_.clear();
  base_dashpot_.assign(dim_, 0.0);
  for (int c = 0; c < dim_; ++c) base_dashpot_[c] = mat_[0].rho * (c == dim_ - 1 ? mat_[0].vp : mat_[0].vs);
  for (std::vector<double> *x : {&u_, &v_, &a_, &v_half_, &a_star_, &work_}) x->assign(n * dim_, 0.0);
  started_ = false;
  return "";
}

std::string FreeFieldColumn::setAttenuation(const std::vector<ConstantQModel> &models, const std::vector<double> &factor) {
  const int nseg = (int)z_.size() - 1;
  if ((int)models.size() != nseg || (int)factor.size() != nseg) return "a free-field column needs one attenuation model and factor per segment";
  for (const ConstantQModel &m : models)
    if (!m.omega.empty()) memory_omega_ = m.omega;
  const size_t L = memory_omega_.size();
  memory_weight_.assign(nseg * L, 0.0);
  for (int e = 0; e < nseg; ++e) {
    if (!models[e].omega.empty() && models[e].omega != memory_omega_) return "damped free-field segments must share the relaxation frequencies";
    for (size_t l = 0; l < models[e].weight.size(); ++l) memory_weight_[e * L + l] = models[e].weight[l];
    modulus_factor_[e] = factor[e];
    for (int c = 0; c < dim_; ++c) k_[e * dim_ + c] *= factor[e];
  }
  zeta_.assign(nseg * dim_ * L, 0.0);
  spring_old_.assign(nseg * dim_, 0.0);
  return "";
}

void FreeFieldColumn::setInput(int component, bool p_wave) {
  input_component_ = component;
  input_impedance_ = mat_.empty() ? 0.0 : mat_[0].rho * (p_wave ? mat_[0].vp : mat_[0].vs);
}

void FreeFieldColumn::internalForce(const std::vector<double> &x, std::vector<double> &f) const {
  std::fill(f.begin(), f.end(), 0.0);
  const int n = (int)z_.size();
  for (int e = 0; e < n - 1; ++e)
    for (int c = 0; c < dim_; ++c) {
      const double s = k_[e * dim_ + c] * (x[(e + 1) * dim_ + c] - x[e * dim_ + c]);
      f[e * dim_ + c] -= s;
      f[(e + 1) * dim_ + c] += s;
    }
}

// The springs' memory over a step of h ending at u_ (spring forces k_U Δu linear in time from
// spring_old_), and its force on the nodes: each spring pulls with k_U Δu - sum_l zeta_l.
void FreeFieldColumn::memoryForce(double h, std::vector<double> &f) {
  const size_t L = memory_omega_.size();
  if (L == 0) return;
  MemoryUpdate upd[8];
  for (size_t l = 0; l < L; ++l) upd[l] = memoryUpdate(memory_omega_[l], h);
  const int nseg = (int)z_.size() - 1;
  for (int e = 0; e < nseg; ++e)
    for (int c = 0; c < dim_; ++c) {
      const int    j      = e * dim_ + c;
      const double spring = k_[j] * (u_[(e + 1) * dim_ + c] - u_[e * dim_ + c]);
      double       total  = 0;
      for (size_t l = 0; l < L; ++l) {
        const double y = memory_weight_[e * L + l];
        double      &z = zeta_[j * L + l];
        z              = upd[l].decay * z + y * (upd[l].end * spring + upd[l].start * spring_old_[j]);
        total += z;
      }
      spring_old_[j] = spring;
      f[e * dim_ + c] += total;
      f[(e + 1) * dim_ + c] -= total;
    }
}

// a* already holds M^{-1}(f_in - K u - beta K v_half); solve the centred nodal damping
// (1 + s D) v = v_half + s a*, a = a* - D v (s = 0 at the start: v stays as given).
void FreeFieldColumn::nodalDamping(double s, double) {
  const int n = (int)z_.size();
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < dim_; ++c) {
      const int    k = i * dim_ + c;
      const double D = (i == 0 ? base_dashpot_[c] / mass_[i] : 0.0) + alpha_;
      if (s > 0) v_[k] = D != 0.0 ? (v_half_[k] + s * a_star_[k]) / (1.0 + s * D) : v_half_[k] + s * a_star_[k];
      a_[k] = a_star_[k] - D * v_[k];
    }
}

void FreeFieldColumn::start(double t0, double v_in0) {
  std::fill(u_.begin(), u_.end(), 0.0);
  std::fill(v_.begin(), v_.end(), 0.0);
  std::fill(v_half_.begin(), v_half_.end(), 0.0);
  std::fill(zeta_.begin(), zeta_.end(), 0.0);
  std::fill(spring_old_.begin(), spring_old_.end(), 0.0);
  t_ = t0;
  // a* = M^{-1} f_in (u = v = 0).
  std::fill(a_star_.begin(), a_star_.end(), 0.0);
  if (input_component_ >= 0) a_star_[input_component_] = 2 * input_impedance_ * v_in0 / mass_[0];
  nodalDamping(0.0, v_in0);
  started_ = true;
}

void FreeFieldColumn::step(double h, double v_in_new) {
  const int n = (int)z_.size() * dim_;
  for (int k = 0; k < n; ++k) {
    v_half_[k] = v_[k] + 0.5 * h * a_[k];
    u_[k] += h * v_half_[k];
  }
  internalForce(u_, a_star_);
  memoryForce(h, a_star_);
  if (beta_ > 0) {
    internalForce(v_half_, work_);
    for (int k = 0; k < n; ++k) a_star_[k] += beta_ * work_[k];
  }
  // a_star_ holds K u - memory (+ beta K v_half); form M^{-1}(f_in - that).
  for (int k = 0; k < n; ++k) {
    const double f_in = (k == input_component_) ? 2 * input_impedance_ * v_in_new : 0.0;
    a_star_[k] = (1.0 / mass_[k / dim_]) * (f_in - a_star_[k]);
  }
  for (int k = 0; k < n; ++k) v_[k] = v_half_[k];
  nodalDamping(0.5 * h, v_in_new);
  t_ += h;
}

void FreeFieldColumn::segmentStress(int e, double *sigma) const {
  const double L  = z_[e + 1] - z_[e];
  auto         lm = lame(mat_[e]);
  lm.lambda *= modulus_factor_[e];
  lm.mu *= modulus_factor_[e];
  const int    z  = dim_ - 1;
  const size_t nm = memory_omega_.size();
  auto memory = [&](int c) {
    double total = 0;
    for (size_t l = 0; l < nm; ++l) total += zeta_[(e * dim_ + c) * nm + l];
    return total;
  };
  for (int k = 0; k < dim_ * dim_; ++k) sigma[k] = 0.0;
  auto grad = [&](const std::vector<double> &x, int c) { return (x[(e + 1) * dim_ + c] - x[e * dim_ + c]) / L; };
  for (int c = 0; c < z; ++c) {
    const double tau = lm.mu * (grad(u_, c) + beta_ * grad(v_half_, c)) - memory(c);
    sigma[c * dim_ + z] = tau;
    sigma[z * dim_ + c] = tau;
  }
  const double ezz = grad(u_, z) + beta_ * grad(v_half_, z);
  // The memory scales lambda and mu alike (one Q), so sigma_xx = lambda/(lambda + 2 mu) sigma_zz
  // holds with it too.
  sigma[z * dim_ + z] = (lm.lambda + 2 * lm.mu) * ezz - memory(z);
  for (int c = 0; c < z; ++c) sigma[c * dim_ + c] = lm.lambda * ezz - lm.lambda / (lm.lambda + 2 * lm.mu) * memory(z);
}

int FreeFieldColumn::findNode(double zq, double tol) const {
  auto it = std::lower_bound(z_.begin(), z_.end(), zq - tol);
  if (it != z_.end() && std::fabs(*it - zq) <= tol) return (int)(it - z_.begin());
  return -1;
}

double FreeFieldColumn::omegaMax() const {
  // Gershgorin on M^{-1} K per chain: row i sums to 2 (k_left + k_right) / m_i.
  double w2 = 0;
  const int n = (int)z_.size();
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < dim_; ++c) {
      double row = 0;
      if (i > 0) row += 2 * k_[(i - 1) * dim_ + c];
      if (i < n - 1) row += 2 * k_[i * dim_ + c];
      w2 = std::max(w2, row / mass_[i]);
    }
  return std::sqrt(w2);
}

double FreeFieldColumn::stableStep() const { return centralDifferenceStableStep(omegaMax(), beta_); }

std::vector<double> FreeFieldColumn::state() const {
  std::vector<double> s{t_, started_ ? 1.0 : 0.0};
  for (const std::vector<double> *x : {&u_, &v_, &a_, &v_half_, &zeta_, &spring_old_}) s.insert(s.end(), x->begin(), x->end());
  return s;
}

bool FreeFieldColumn::setState(const std::vector<double> &s) {
  if (s.size() != 2 + 4 * u_.size() + zeta_.size() + spring_old_.size()) return false;
  t_       = s[0];
  started_ = s[1] != 0.0;
  size_t o = 2;
  for (std::vector<double> *x : {&u_, &v_, &a_, &v_half_, &zeta_, &spring_old_}) {
    std::copy(s.begin() + o, s.begin() + o + x->size(), x->begin());
    o += x->size();
  }
  return true;
}

} // namespace slipwave::physics

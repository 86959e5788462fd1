#include "slipwave/physics/free_field_column.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "slipwave/physics/biot.hpp"
#include "slipwave/physics/stable_time_step.hpp"

namespace slipwave::physics {

namespace {

// Largest eigenvalue of a symmetric n x n matrix (row-major, overwritten) by cyclic Jacobi
// rotations, to round-off (n <= 9 here).
double symmetricLambdaMax(int n, std::vector<double> A) {
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0, diag = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) (i == j ? diag : off) += A[i * n + j] * A[i * n + j];
    if (off <= 1e-32 * diag) break;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        const double aij = A[i * n + j];
        if (aij == 0.0) continue;
        const double theta = (A[j * n + j] - A[i * n + i]) / (2 * aij);
        const double t     = (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), sn = t * c;
        for (int k = 0; k < n; ++k) { // columns i, j
          const double ki = A[k * n + i], kj = A[k * n + j];
          A[k * n + i] = c * ki - sn * kj;
          A[k * n + j] = sn * ki + c * kj;
        }
        for (int k = 0; k < n; ++k) { // rows i, j
          const double ik = A[i * n + k], jk = A[j * n + k];
          A[i * n + k] = c * ik - sn * jk;
          A[j * n + k] = sn * ik + c * jk;
        }
      }
  }
  double top = A[0];
  for (int i = 1; i < n; ++i) top = std::max(top, A[i * n + i]);
  return top;
}

bool sameElastic(const ElasticMaterial &a, const ElasticMaterial &b) { return a.rho == b.rho && a.vp == b.vp && a.vs == b.vs; }

int soilStateSize(int dim, const HystereticSoilModel &model) { return dim == 2 ? hystereticStateSize<2>(model) : hystereticStateSize<3>(model); }

// The Iwan update number `update`, in place, at a point of a height-only motion with
// g[c] = du_c/dz (the last axis vertical): the full strain tensor of the motion in,
// out[c] = sigma_{c z} (c = dim-1: sigma_zz) and out[dim] = sigma_xx.
// scale: the element's strain scale (the model runs at g / scale, its stress comes back times it).
void soilPoint(const HystereticSoilModel &model, int dim, const double *g, double scale, double update, double *state, double *out) {
  if (dim == 2) {
    const double strain[3] = {0.0, g[1] / scale, 0.5 * g[0] / scale}; // xx, yy, xy
    double       sigma[4];
    hystereticUpdate<2>(model, state, strain, sigma, state, update);
    out[0] = scale * sigma[2], out[1] = scale * sigma[1], out[2] = scale * sigma[0];
  } else {
    const double strain[6] = {0.0, 0.0, g[2] / scale, 0.0, 0.5 * g[1] / scale, 0.5 * g[0] / scale}; // xx, yy, zz, xy, yz, xz
    double       sigma[6];
    hystereticUpdate<3>(model, state, strain, sigma, state, update);
    out[0] = scale * sigma[5], out[1] = scale * sigma[4], out[2] = scale * sigma[2], out[3] = scale * sigma[0];
  }
}

} // namespace

std::string FreeFieldColumn::setup(int dim, const std::vector<double> &heights, const std::vector<ElasticMaterial> &materials, double alpha, double beta,
                                   const ColumnElement &given) {
  const ColumnElement element = completeColumnElement(given);
  char buf[240];
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
  const int p = element.degree, nseg = (int)heights.size() - 1;
  if (p < 1 || p > kMaxColumnDegree || (int)element.x.size() != p + 1 || (int)element.w.size() != p + 1 || (int)element.D.size() != (p + 1) * (p + 1))
    return "the column's reference element needs p+1 points and weights and a (p+1)^2 derivative matrix";
  if (nseg % p != 0) {
    std::snprintf(buf, sizeof buf, "a free-field column of degree %d needs a multiple of %d node intervals; the side has %d", p, p, nseg);
    return buf;
  }
  for (int e = 0; e < nseg / p; ++e) {
    const double z0 = heights[e * p], L = heights[(e + 1) * p] - z0;
    for (int a = 0; a <= p; ++a) {
      if (a < p && !sameElastic(materials[e * p + a], materials[e * p])) {
        std::snprintf(buf, sizeof buf, "the element of degree %d from height %g to %g has segments of different materials", p, z0, z0 + L);
        return buf;
      }
      if (std::fabs(heights[e * p + a] - (z0 + (1 + element.x[a]) * L / 2)) > 1e-6 * L) {
        std::snprintf(buf, sizeof buf, "node height %g is not at the GLL point %d of the element of degree %d from height %g to %g", heights[e * p + a], a, p, z0, z0 + L);
        return buf;
      }
    }
  }
  dim_   = dim;
  z_     = heights;
  mat_   = materials;
  alpha_ = alpha;
  beta_  = beta;
  p_     = p;
  element_ = element;
  ref_S2_.assign((p + 1) * (p + 1), 0.0);
  for (int a = 0; a <= p; ++a)
    for (int b = 0; b <= p; ++b) {
      double sum = 0;
      for (int q = 0; q <= p; ++q) sum += element_.w[q] * element_.D[q * (p + 1) + a] * element_.D[q * (p + 1) + b];
      ref_S2_[a * (p + 1) + b] = 2 * sum;
    }
  // W^-1/2 S2 W^-1/2 has the eigenvalues of W^-1 S2.
  std::vector<double> scaled(ref_S2_);
  for (int a = 0; a <= p; ++a)
    for (int b = 0; b <= p; ++b) scaled[a * (p + 1) + b] /= std::sqrt(element_.w[a] * element_.w[b]);
  ref_lambda_ = symmetricLambdaMax(p + 1, scaled);
  const int n = (int)z_.size(), ne = elementCount();
  mass_.assign(n, 0.0);
  k_.assign(ne * dim_, 0.0);
  for (int e = 0; e < ne; ++e) {
    const double L  = elementLength(e);
    const auto  &m  = mat_[e * p_];
    const auto   lm = lame(m);
    for (int a = 0; a <= p_; ++a) mass_[e * p_ + a] += m.rho * L / 2 * element_.w[a];
    for (int c = 0; c < dim_; ++c) k_[e * dim_ + c] = (c == dim_ - 1 ? lm.lambda + 2 * lm.mu : lm.mu) / L;
  }
  modulus_factor_.assign(n - 1, 1.0);
  memory_omega_.clear();
  memory_weight_.clear();
  zeta_.clear();
  spring_old_.clear();
  soil_.clear();
  soil_offset_.clear();
  for (std::vector<double> *x : {&soil_state_, &soil_stress_, &lateral_zeta_, &lateral_old_}) x->clear();
  pore_ = ColumnPorePressure();
  base_dashpot_.assign(dim_, 0.0);
  for (int c = 0; c < dim_; ++c) base_dashpot_[c] = baseImpedance(c);
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
    if (factor[e] != factor[e - e % p_]) return "the segments of a free-field element must share their damping";
    for (size_t l = 0; l < models[e].weight.size(); ++l) memory_weight_[e * L + l] = models[e].weight[l];
    modulus_factor_[e] = factor[e];
  }
  for (int e = 0; e < elementCount(); ++e)
    for (int c = 0; c < dim_; ++c) k_[e * dim_ + c] *= factor[e * p_];
  zeta_.assign(elementCount() * dim_ * (p_ + 1) * L, 0.0);
  spring_old_.assign(elementCount() * dim_ * (p_ + 1), 0.0);
  return "";
}

std::string FreeFieldColumn::setHysteresis(const std::vector<std::shared_ptr<const HystereticSoilModel>> &models) {
  const int ne = elementCount(), n1 = p_ + 1;
  if ((int)models.size() != segmentCount()) return "a free-field column needs one hysteretic model (or none) per segment";
  soil_.assign(ne, nullptr);
  soil_offset_.assign(ne, -1);
  long size = 0;
  for (int e = 0; e < ne; ++e) {
    const std::shared_ptr<const HystereticSoilModel> &m = models[e * p_];
    for (int a = 1; a < p_; ++a)
      if (models[e * p_ + a] != m) return "the segments of a free-field element must share their hysteretic model";
    if (!m) continue;
    // Its small-strain moduli must be the element's (unrelaxed) ones, so that below the
    // elastic limit the segment is the linear one.
    const auto   lm = lame(mat_[e * p_]);
    const double f = modulus_factor_[e * p_], mu = lm.mu * f, bulk = (lm.lambda + 2.0 / 3.0 * lm.mu) * f;
    if (std::fabs(m->shearModulus() - mu) > 1e-12 * mu || std::fabs(m->bulkModulus() - bulk) > 1e-12 * bulk) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "the hysteretic model of the element from height %g has Gmax %.17g and K %.17g, its segment %.17g and %.17g", z_[e * p_], m->shearModulus(),
                    m->bulkModulus(), mu, bulk);
      return buf;
    }
    soil_[e]        = m;
    soil_offset_[e] = size;
    size += (long)n1 * soilStateSize(dim_, *m);
  }
  if (size == 0) {
    soil_.clear();
    soil_offset_.clear();
    return "";
  }
  const size_t L = memory_omega_.size();
  soil_state_.assign(size, 0.0);
  soil_stress_.assign((size_t)ne * n1 * (dim_ + 1), 0.0);
  lateral_zeta_.assign((size_t)ne * n1 * L, 0.0);
  lateral_old_.assign(L > 0 ? (size_t)ne * n1 : 0, 0.0);
  return "";
}

void FreeFieldColumn::setGeostaticScales(double gravity, const std::vector<bool> &geostatic, double reference_stress, double floor) {
  const int ne = elementCount();
  soil_scale_.clear();
  bool any = false;
  for (int e = 0; e < ne; ++e) any = any || (soil_[e] && geostatic[e * p_]);
  if (!any) return;
  soil_scale_.assign(ne, 1.0);
  // The weight above the top of element e, from the top down (an element is one region's: its
  // segments share the material, as lame(mat_[e p]) takes them elsewhere).
  double above = 0;
  for (int e = ne - 1; e >= 0; --e) {
    const double weight = mat_[e * p_].rho * elementLength(e); // per unit area
    if (soil_[e] && geostatic[e * p_]) {
      const auto   lm    = lame(mat_[e * p_]);
      const double sigma = std::max(floor, gravity * (above + 0.5 * weight) * (lm.lambda + 2.0 / 3.0 * lm.mu) / (lm.lambda + 2 * lm.mu));
      soil_scale_[e]     = darendeliStrainScale(sigma, reference_stress);
    }
    above += weight;
  }
}

std::string FreeFieldColumn::setPorePressure(const std::vector<ColumnFluidSegment> &segments, const std::vector<ColumnFluidNode> &nodes, const ColumnFluidRules &rules) {
  const std::string problem = pore_.setup(z_, segments, nodes, rules, element_);
  if (!problem.empty()) return problem;
  base_dashpot_[dim_ - 1] = baseImpedance(dim_ - 1);
  if (input_component_ >= 0) setInput(input_component_, input_p_wave_);
  return "";
}

double FreeFieldColumn::baseImpedance(int c) const {
  const ElasticMaterial &m = mat_[0];
  if (c < dim_ - 1) return m.rho * m.vs;
  if (!pore_.active() || !pore_.segment(0).saturated) return m.rho * m.vp;
  const ColumnFluidSegment &f  = pore_.segment(0);
  const LameParameters      lm = lame(m);
  return m.rho * undrainedPWaveSpeed(lm.lambda + 2.0 * lm.mu / 3.0, lm.mu, f.alpha, f.M, m.rho);
}

void FreeFieldColumn::setInput(int component, bool p_wave) {
  input_component_ = component;
  input_p_wave_    = p_wave;
  input_impedance_ = mat_.empty() ? 0.0 : baseImpedance(p_wave ? dim_ - 1 : 0);
}

double FreeFieldColumn::scaledGradient(const std::vector<double> &x, int e, int c, int q) const {
  double g = 0;
  for (int b = 0; b <= p_; ++b) g += element_.D[q * (p_ + 1) + b] * x[(e * p_ + b) * dim_ + c];
  return 2 * g;
}

void FreeFieldColumn::internalForce(const std::vector<double> &x, std::vector<double> &f, bool skip_soil) const {
  std::fill(f.begin(), f.end(), 0.0);
  const int n1 = p_ + 1;
  for (int e = 0; e < elementCount(); ++e) {
    if (skip_soil && hysteretic() && soil_[e]) continue;
    for (int c = 0; c < dim_; ++c)
      for (int a = 0; a <= p_; ++a) {
        double s = 0;
        for (int b = 0; b <= p_; ++b) s += ref_S2_[a * n1 + b] * x[(e * p_ + b) * dim_ + c];
        f[(e * p_ + a) * dim_ + c] += k_[e * dim_ + c] * s;
      }
  }
}

// f_a = sum_q w_q D_qa sigma_q per component: the integral of the stress against the basis
// gradient (the Jacobian L/2 cancels the 2/L of the gradient), K u for a linear stress.
void FreeFieldColumn::soilForce(std::vector<double> &f) {
  const int n1 = p_ + 1, ns = dim_ + 1;
  double    g[3];
  soil_updates_ += 1;
  for (int e = 0; e < elementCount(); ++e) {
    if (!soil_[e]) continue;
    const double L = elementLength(e);
    const int    size = soilStateSize(dim_, *soil_[e]);
    double      *sig  = &soil_stress_[(size_t)e * n1 * ns];
    for (int q = 0; q <= p_; ++q) {
      for (int c = 0; c < dim_; ++c) g[c] = scaledGradient(u_, e, c, q) / L;
      soilPoint(*soil_[e], dim_, g, soil_scale_.empty() ? 1.0 : soil_scale_[e], soil_updates_, &soil_state_[soil_offset_[e] + (long)q * size], &sig[q * ns]);
    }
    for (int c = 0; c < dim_; ++c)
      for (int a = 0; a <= p_; ++a) {
        double s = 0;
        for (int q = 0; q <= p_; ++q) s += element_.w[q] * element_.D[q * n1 + a] * sig[q * ns + c];
        f[(e * p_ + a) * dim_ + c] += s;
      }
  }
}

// The memory over a step of h ending at u_ (the unrelaxed elastic stress k_U 2 sum_b D_qb u_b
// at each GLL point, linear in time from spring_old_), and its force on the nodes: the stress
// k_U u' - sum_l zeta_l integrated against the basis, f_a = sum_q w_q D_qa sigma_q, whose
// elastic part is K u.
void FreeFieldColumn::memoryForce(double h, std::vector<double> &f) {
  const size_t L = memory_omega_.size();
  if (L == 0) return;
  MemoryUpdate upd[8];
  for (size_t l = 0; l < L; ++l) upd[l] = memoryUpdate(memory_omega_[l], h);
  const int n1 = p_ + 1, ns = dim_ + 1;
  double    total[kMaxColumnDegree + 1];
  for (int e = 0; e < elementCount(); ++e) {
    // A hysteretic element's memory is driven by its Iwan stress (the lateral one too).
    const double *sig = hysteretic() && soil_[e] ? &soil_stress_[(size_t)e * n1 * ns] : nullptr;
    if (sig)
      for (int q = 0; q <= p_; ++q) {
        const size_t j = (size_t)e * n1 + q;
        for (size_t l = 0; l < L; ++l) {
          double &z = lateral_zeta_[j * L + l];
          z         = upd[l].decay * z + memory_weight_[e * p_ * L + l] * (upd[l].end * sig[q * ns + dim_] + upd[l].start * lateral_old_[j]);
        }
        lateral_old_[j] = sig[q * ns + dim_];
      }
    for (int c = 0; c < dim_; ++c) {
      for (int q = 0; q <= p_; ++q) {
        const int    j      = (e * dim_ + c) * n1 + q;
        const double spring = sig ? sig[q * ns + c] : k_[e * dim_ + c] * scaledGradient(u_, e, c, q);
        total[q]            = 0;
        for (size_t l = 0; l < L; ++l) {
          const double y = memory_weight_[e * p_ * L + l];
          double      &z = zeta_[j * L + l];
          z              = upd[l].decay * z + y * (upd[l].end * spring + upd[l].start * spring_old_[j]);
          total[q] += z;
        }
        spring_old_[j] = spring;
      }
      for (int a = 0; a <= p_; ++a) {
        double pull = 0;
        for (int q = 0; q <= p_; ++q) pull += element_.w[q] * element_.D[q * n1 + a] * total[q];
        f[(e * p_ + a) * dim_ + c] -= pull;
      }
    }
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
  for (std::vector<double> *x : {&soil_state_, &soil_stress_, &lateral_zeta_, &lateral_old_}) std::fill(x->begin(), x->end(), 0.0);
  soil_updates_ = 0;
  t_            = t0;
  pore_.start(&u_[dim_ - 1], dim_);
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
  pore_.step(h, &u_[dim_ - 1], dim_);
  internalForce(u_, a_star_, true);
  if (hysteretic()) soilForce(a_star_);
  memoryForce(h, a_star_);
  pore_.addForce(-1.0, &a_star_[dim_ - 1], dim_);
  if (beta_ > 0) {
    internalForce(v_half_, work_);
    for (int k = 0; k < n; ++k) a_star_[k] += beta_ * work_[k];
  }
  // a_star_ holds K u - memory - alpha Q^T p (+ beta K v_half); form M^{-1}(f_in - that).
  for (int k = 0; k < n; ++k) {
    const double f_in = (k == input_component_) ? 2 * input_impedance_ * v_in_new : 0.0;
    a_star_[k] = (1.0 / mass_[k / dim_]) * (f_in - a_star_[k]);
  }
  for (int k = 0; k < n; ++k) v_[k] = v_half_[k];
  nodalDamping(0.5 * h, v_in_new);
  t_ += h;
}

void FreeFieldColumn::stress(int segment, int node, double *sigma) const {
  const int    e = segment / p_, q = node - e * p_;
  const double L = elementLength(e);
  auto         lm = lame(mat_[e * p_]);
  lm.lambda *= modulus_factor_[e * p_];
  lm.mu *= modulus_factor_[e * p_];
  const int    z  = dim_ - 1;
  const size_t nm = memory_omega_.size();
  auto memory = [&](int c) {
    double total = 0;
    for (size_t l = 0; l < nm; ++l) total += zeta_[((e * dim_ + c) * (p_ + 1) + q) * nm + l];
    return total;
  };
  for (int k = 0; k < dim_ * dim_; ++k) sigma[k] = 0.0;
  auto grad = [&](const std::vector<double> &x, int c) { return scaledGradient(x, e, c, q) / L; };
  if (hysteretic() && soil_[e]) {
    // The Iwan stress of the last step, the viscous stress of the linear (unrelaxed) moduli as
    // the main mesh's beta K_U v_{n+1/2}, less the memory of each component.
    const double *sg = &soil_stress_[((size_t)e * (p_ + 1) + q) * (dim_ + 1)];
    for (int c = 0; c < z; ++c) {
      const double tau = sg[c] + beta_ * lm.mu * grad(v_half_, c) - memory(c);
      sigma[c * dim_ + z] = tau;
      sigma[z * dim_ + c] = tau;
    }
    const double vzz = beta_ * grad(v_half_, z);
    double       lateral_memory = 0;
    for (size_t l = 0; l < nm; ++l) lateral_memory += lateral_zeta_[((size_t)e * (p_ + 1) + q) * nm + l];
    sigma[z * dim_ + z] = sg[z] + (lm.lambda + 2 * lm.mu) * vzz - memory(z);
    for (int c = 0; c < z; ++c) sigma[c * dim_ + c] = sg[dim_] + lm.lambda * vzz - lateral_memory;
    return;
  }
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

double FreeFieldColumn::poreStress(int segment, int node, double theta) const {
  if (!pore_.active()) return 0.0;
  // Degree p > 1: the main mesh integrates alpha p div(dv) by the GLL rule, which collocates
  // on the face as well: the nodal value.
  if (p_ > 1) return pore_.alpha(segment) * pore_.pressure(node);
  const int other = node == segment ? segment + 1 : segment;
  return pore_.alpha(segment) * ((1 - theta) * pore_.pressure(node) + theta * pore_.pressure(other));
}

int FreeFieldColumn::findNode(double zq, double tol) const {
  auto it = std::lower_bound(z_.begin(), z_.end(), zq - tol);
  if (it != z_.end() && std::fabs(*it - zq) <= tol) return (int)(it - z_.begin());
  return -1;
}

double FreeFieldColumn::omegaMax(double coupling_factor) const {
  double    w2 = 0;
  const int n  = (int)z_.size();
  if (p_ > 1) {
    // The vertical chain of a saturated element adds coupling_factor alpha^2 M / L to its
    // modulus / L (ColumnPorePressure::undrainedModulus): its element bound scales alike.
    for (int e = 0; e < elementCount(); ++e)
      for (int c = 0; c < dim_; ++c) {
        const double k = k_[e * dim_ + c] + (c == dim_ - 1 ? coupling_factor * pore_.undrainedModulus(e) / elementLength(e) : 0.0);
        w2             = std::max(w2, 2 * k / (mat_[e * p_].rho * elementLength(e)) * ref_lambda_);
      }
    return std::sqrt(w2);
  }
  // Gershgorin on M^{-1} K per chain: row i sums to 2 (k_left + k_right) / m_i; the vertical
  // rows of saturated segments add the undrained stiffening alpha^2 Q^T S^{-1} Q as the main
  // mesh bounds it, coupling_factor times.
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < dim_; ++c) {
      double row = c == dim_ - 1 ? coupling_factor * pore_.undrainedRow(i) : 0.0;
      if (i > 0) row += 2 * k_[(i - 1) * dim_ + c];
      if (i < n - 1) row += 2 * k_[i * dim_ + c];
      w2 = std::max(w2, row / mass_[i]);
    }
  return std::sqrt(w2);
}

double FreeFieldColumn::stableStep(double coupling_factor) const { return centralDifferenceStableStep(omegaMax(coupling_factor), beta_); }

// Each Iwan state's tail age (updates since the tail was set) to or from its kSince slot at
// update `now` (the same map both ways).
void FreeFieldColumn::swapTailAges(std::vector<double> &states, double now) const {
  if (!hysteretic()) return; // an elastic column keeps no Iwan states
  for (int e = 0; e < elementCount(); ++e) {
    if (!soil_[e]) continue;
    const int size = soilStateSize(dim_, *soil_[e]);
    for (int q = 0; q <= p_; ++q) swapTailAge(&states[soil_offset_[e] + (long)q * size], now);
  }
}

std::vector<double> FreeFieldColumn::state() const {
  std::vector<double>       s{t_, started_ ? 1.0 : 0.0}, ages = soil_state_;
  const std::vector<double> &soil = ages;
  // The checkpoint keeps the tails' ages: a restart's count of updates starts again at 0.
  swapTailAges(ages, soil_updates_);
  for (const std::vector<double> *x : {&u_, &v_, &a_, &v_half_, &zeta_, &spring_old_, &soil, &soil_stress_, &lateral_zeta_, &lateral_old_})
    s.insert(s.end(), x->begin(), x->end());
  const std::vector<double> pore = pore_.state();
  s.insert(s.end(), pore.begin(), pore.end());
  return s;
}

bool FreeFieldColumn::setState(const std::vector<double> &s) {
  if (s.size() != 2 + 4 * u_.size() + zeta_.size() + spring_old_.size() + soil_state_.size() + soil_stress_.size() + lateral_zeta_.size() + lateral_old_.size() +
                      pore_.stateSize())
    return false;
  t_       = s[0];
  started_ = s[1] != 0.0;
  size_t o = 2;
  for (std::vector<double> *x : {&u_, &v_, &a_, &v_half_, &zeta_, &spring_old_, &soil_state_, &soil_stress_, &lateral_zeta_, &lateral_old_}) {
    std::copy(s.begin() + o, s.begin() + o + x->size(), x->begin());
    o += x->size();
  }
  pore_.setState(s.data() + o);
  soil_updates_ = 0;
  swapTailAges(soil_state_, soil_updates_);
  return true;
}

} // namespace slipwave::physics

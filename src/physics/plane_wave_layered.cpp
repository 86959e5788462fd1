#include "slipwave/physics/plane_wave_layered.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "slipwave/numerics/dense_solve.hpp"
#include "slipwave/numerics/fft.hpp"

namespace slipwave::physics {

std::string PlaneWaveLayered::setup(const LayeredSite &site, PlaneWaveType wave, double angle_deg) {
  char buf[200];
  if (site.materials.size() != site.thickness.size() + 1) return "a layered site needs one material per layer plus the half-space";
  if (!site.damping.empty() && site.damping.size() != site.materials.size()) return "a damped site needs one damping per material";
  for (const ElasticMaterial &m : site.materials) {
    const std::string problem = elasticMaterialProblem(m);
    if (!problem.empty()) return problem;
  }
  for (double h : site.thickness)
    if (!(h > 0)) {
      std::snprintf(buf, sizeof buf, "layer thickness %g m; allowed: > 0", h);
      return buf;
    }
  if (!(angle_deg >= 0 && angle_deg < 90)) {
    std::snprintf(buf, sizeof buf, "incidence angle %g deg; allowed: 0 <= angle < 90", angle_deg);
    return buf;
  }
  const ElasticMaterial &hs = site.materials.back();
  const double           p  = std::sin(angle_deg * M_PI / 180) / (wave == PlaneWaveType::P ? hs.vp : hs.vs);
  for (const ElasticMaterial &m : site.materials)
    for (double c : {m.vp, m.vs})
      if (p > 0 && std::fabs(p * c - 1) < 1e-9) {
        std::snprintf(buf, sizeof buf, "incidence angle %g deg makes a wave of speed %g m/s graze (p c = 1); choose another angle", angle_deg, c);
        return buf;
      }
  site_ = site;
  wave_ = wave;
  p_    = p;
  top_.assign(1, 0.0);
  for (double h : site.thickness) top_.push_back(top_.back() + h);
  return "";
}

DampedMedium PlaneWaveLayered::medium(size_t j, double w) const {
  if (site_.damping.empty()) {
    const LameParameters lm = lame(site_.materials[j]);
    return {site_.materials[j].rho, lm.lambda, lm.mu};
  }
  return dampedMedium(site_.materials[j], site_.damping[j], w);
}

Complex PlaneWaveLayered::verticalSlowness(size_t j, bool s_wave, double w) const {
  const DampedMedium m = medium(j, w);
  const Complex      c = s_wave ? m.vs() : m.vp();
  const Complex      r = 1.0 / (c * c) - p_ * p_;
  // The root with Im q <= 0, so e^{-i w q z} decays downward for w > 0. Elastic evanescent
  // waves (r < 0 real) get q = -i sqrt(p^2 - 1/c^2); damped ones (Im r < 0) the principal root.
  const Complex q = std::sqrt(r);
  return q.imag() > 0 ? -q : q;
}

PlaneWaveLayered::Wave PlaneWaveLayered::wave(size_t j, bool s_wave, bool down, double w) const {
  const DampedMedium m  = medium(j, w);
  const Complex      sz = down ? verticalSlowness(j, s_wave, w) : -verticalSlowness(j, s_wave, w);
  const double       sx = p_;
  Wave               wv{};
  if (wave_ == PlaneWaveType::SH) {
    wv.d   = {0, 1, 0};
    wv.tau = {0, m.mu * sz, 0};
    return wv;
  }
  const Complex c = s_wave ? m.vs() : m.vp();
  wv.d            = s_wave ? std::array<Complex, 3>{-c * sz, 0, c * sx} : std::array<Complex, 3>{c * sx, 0, c * sz};
  const Complex div = wv.d[0] * sx + wv.d[2] * sz; // d . s
  wv.tau          = {m.mu * (wv.d[0] * sz + wv.d[2] * sx), 0, m.lambda * div + 2.0 * m.mu * wv.d[2] * sz};
  return wv;
}

std::vector<Complex> PlaneWaveLayered::amplitudes(double w) const {
  const size_t N = site_.thickness.size(), nw = wavesPerMedium(), n = nw * N + nw / 2;
  const bool   sh = wave_ == PlaneWaveType::SH;
  // Per medium, the waves in unknown order and the rows of the state they enter:
  // P-SV (u_x, u_z, tau_x, tau_z); SH (u_y, tau_y).
  auto stateRow = [&](const Wave &wv, size_t r) -> Complex {
    if (sh) return r == 0 ? wv.d[1] : wv.tau[1];
    return std::array<Complex, 4>{wv.d[0], wv.d[2], wv.tau[0], wv.tau[2]}[r];
  };
  auto waveOf = [&](size_t medium, size_t k) { // k-th wave of a medium: down waves first
    const bool down = k < nw / 2;
    const bool s    = sh || (k % 2 == 1);
    return wave(medium, s, down, w);
  };
  // Phase of wave k of layer j at depth z: e^{-i w s_z (z - z_ref)}, z_ref its top (down) or bottom (up).
  auto phase = [&](size_t j, size_t k, double z) {
    const bool    down = k < nw / 2;
    const bool    s    = sh || (k % 2 == 1);
    const Complex sz   = down ? verticalSlowness(j, s, w) : -verticalSlowness(j, s, w);
    const double  zref = down ? top_[j] : top_[j + 1];
    return std::exp(Complex(0, -w) * sz * (z - zref));
  };
  std::vector<Complex> A(n * n, 0.0), b(n, 0.0);
  const size_t         ns = nw / 2; // state rows at the free surface: the tractions
  // Free surface: the tractions of the top medium vanish.
  for (size_t r = 0; r < ns; ++r) {
    if (N == 0) {
      for (size_t k = 0; k < nw / 2; ++k) A[r * n + k] = stateRow(waveOf(0, k), ns + r);
      b[r] -= stateRow(wave(0, wave_ != PlaneWaveType::P, false, w), ns + r);
    } else
      for (size_t k = 0; k < nw; ++k) A[r * n + k] = stateRow(waveOf(0, k), ns + r) * phase(0, k, 0.0);
  }
  // Interfaces: the state of layer j at its bottom equals that of medium j+1 at its top.
  for (size_t j = 0; j < N; ++j)
    for (size_t r = 0; r < nw; ++r) {
      const size_t row = ns + j * nw + r;
      for (size_t k = 0; k < nw; ++k) A[row * n + j * nw + k] = stateRow(waveOf(j, k), r) * phase(j, k, top_[j + 1]);
      const bool   halfspace = j + 1 == N;
      const size_t below     = halfspace ? nw / 2 : nw;
      for (size_t k = 0; k < below; ++k)
        A[row * n + (j + 1) * nw + k] = -stateRow(waveOf(j + 1, k), r) * (halfspace ? Complex(1) : phase(j + 1, k, top_[j + 1]));
      if (halfspace) b[row] += stateRow(wave(N, wave_ != PlaneWaveType::P, false, w), r);
    }
  numerics::solveDense((int)b.size(), A.data(), b.data(), b.data());
  return b;
}

PlaneWaveLayered::State PlaneWaveLayered::stateAt(const std::vector<Complex> &amp, double w, double z) const {
  const size_t N = site_.thickness.size(), nw = wavesPerMedium();
  const bool   sh = wave_ == PlaneWaveType::SH;
  size_t       j  = 0;
  while (j < N && z > top_[j + 1]) ++j;
  State st{};
  auto  add = [&](const Wave &wv, Complex a) {
    for (int c = 0; c < 3; ++c) {
      st.u[c] += a * wv.d[c];
      st.traction[c] += a * wv.tau[c];
    }
  };
  const Complex iw(0, -w);
  if (j < N) {
    for (size_t k = 0; k < nw; ++k) {
      const bool    down = k < nw / 2, s = sh || (k % 2 == 1);
      const Complex sz   = down ? verticalSlowness(j, s, w) : -verticalSlowness(j, s, w);
      add(wave(j, s, down, w), amp[j * nw + k] * std::exp(iw * sz * (z - (down ? top_[j] : top_[j + 1]))));
    }
  } else {
    const double zt = top_[N];
    const bool   s_in = wave_ != PlaneWaveType::P;
    add(wave(N, s_in, false, w), std::exp(iw * (-verticalSlowness(N, s_in, w)) * (z - zt)));
    for (size_t k = 0; k < nw / 2; ++k) {
      const bool s = sh || k == 1;
      add(wave(N, s, true, w), amp[N * nw + k] * std::exp(iw * verticalSlowness(N, s, w) * (z - zt)));
    }
  }
  st.u[2] = -st.u[2]; // z down -> up
  return st;
}

PlaneWaveHistories synthesizeHistories(const PlaneWaveLayered &field, const std::vector<double> &depths, double reference_depth, const std::vector<double> &v_in,
                                       double dt, bool with_strain) {
  const size_t m = v_in.size(), n = numerics::fftLength(4 * std::max<size_t>(m, 1)), nc = with_strain ? 5 : 3;
  std::vector<Complex> input(n, 0.0);
  std::copy(v_in.begin(), v_in.end(), input.begin());
  numerics::fft(input, false);
  // The incident wave has unit amplitude at the half-space top; at reference_depth its phase
  // is e^{i w q (zr - zN)} (up-going), so dividing by it puts v_in at the reference depth.
  const double  shift = reference_depth - field.halfspaceDepth();
  const size_t  nd    = depths.size();
  std::vector<std::vector<Complex>> out(nc * nd, std::vector<Complex>(n, 0.0));
  for (size_t j = 0; j <= n / 2; ++j) {
    const double               w   = 2 * M_PI * (double)j / ((double)n * dt);
    const std::vector<Complex> amp = field.amplitudes(w);
    const Complex              q_hs = field.verticalSlowness(field.layerCount(), field.wave() != PlaneWaveType::P, w);
    const Complex              ref  = std::exp(Complex(0, -w) * q_hs * shift);
    for (size_t d = 0; d < nd; ++d) {
      const PlaneWaveLayered::State st = field.stateAt(amp, w, depths[d]);
      // Per unit incident velocity: the velocity is st.u; the traction is -i w st.traction
      // times the displacement v/(i w), so sigma_zz = -traction_z v; eps_xx = -i w p u_x =
      // -p v_x. Their channels hold the rates, i w times those, whose integral is the value.
      const Complex rate(0, w);
      const Complex transfer[5] = {st.u[0], st.u[1], st.u[2], -rate * st.traction[2], -rate * field.horizontalSlowness() * st.u[0]};
      for (size_t c = 0; c < nc; ++c) {
        const Complex y = input[j] * transfer[c] * ref;
        if (j == 0 || 2 * j == n) {
          out[nc * d + c][j] = y.real(); // real input: the transfer is real at w = 0; at Nyquist (complex when damped) its real part is kept
        } else {
          out[nc * d + c][j]     = y;
          out[nc * d + c][n - j] = std::conj(y);
        }
      }
    }
  }
  PlaneWaveHistories h;
  h.samples  = m;
  h.channels = nc;
  h.dt       = dt;
  h.velocity.resize(nc * nd * m);
  h.displacement.resize(nc * nd * m);
  std::vector<Complex> accel(n);
  for (size_t k = 0; k < nc * nd; ++k) {
    // The acceleration by the spectral derivative i w, for the end correction below.
    for (size_t j = 0; j < n; ++j) {
      const double w = 2 * M_PI * (double)(j <= n / 2 ? (long)j : (long)j - (long)n) / ((double)n * dt);
      accel[j]       = 2 * j == n ? 0.0 : Complex(0, w) * out[k][j];
    }
    numerics::fft(out[k], true);
    numerics::fft(accel, true);
    double *v = &h.velocity[k * m], *u = &h.displacement[k * m];
    for (size_t i = 0; i < m; ++i) v[i] = out[k][i].real();
    // Trapezoid with its Euler-Maclaurin end correction dt^2/12 (a_i - a_{i+1}): fourth order,
    // so the displacement is as accurate as the Hermite interpolation that reads it.
    u[0] = 0;
    for (size_t i = 1; i < m; ++i) u[i] = u[i - 1] + 0.5 * dt * (v[i - 1] + v[i]) + dt * dt / 12 * (accel[i - 1].real() - accel[i].real());
  }
  return h;
}

double planeWaveDisplacementAt(const PlaneWaveHistories &h, size_t d, size_t c, double t) {
  if (t <= 0 || h.samples == 0) return 0;
  const double *u = &h.displacement[(d * h.channels + c) * h.samples], *v = &h.velocity[(d * h.channels + c) * h.samples];
  const double  s = t / h.dt;
  if (s >= (double)(h.samples - 1)) return u[h.samples - 1];
  const size_t k = (size_t)s;
  const double x = s - (double)k, x2 = x * x, x3 = x2 * x;
  return (2 * x3 - 3 * x2 + 1) * u[k] + (x3 - 2 * x2 + x) * h.dt * v[k] + (-2 * x3 + 3 * x2) * u[k + 1] + (x3 - x2) * h.dt * v[k + 1];
}

} // namespace slipwave::physics

// Plane waves in a damped layered site (physics/damped_medium, physics/plane_wave_layered with
// MediumDamping), against closed forms:
//  - Rayleigh: c*^2 = mu*/rho* = (mu/rho)(1 + i w beta)/(1 - i alpha/w), so
//    Im c*^2 / Re c*^2 = (alpha/w + w beta)/(1 - alpha beta) = 2 xi(w)/(1 - alpha beta) with the
//    modal ratio xi(w) = alpha/(2w) + beta w/2 (physics/rayleigh_damping): the damping of a
//    single mode of M u'' + (alpha M + beta K) u' + K u = 0 at resonance;
//  - constant Q: mu*/mu and lambda*/lambda equal the fitted body's M(w)/M_U times f_U;
//  - attenuation over n wavelengths: with Im k / Re k = tan(delta/2), tan delta = 1/Q(f) the
//    fitted body's Q, a wave decays over n wavelengths by exactly exp(-2 pi n tan(delta/2))
//    (to 1e-12), and that is exp(-pi n / Q0) to within the fit's Q error (5 % in the band,
//    physics/constant_q.hpp) plus the O(1/Q^2) of tan(delta/2) ~ delta/2 ~ 1/(2Q): 6 %;
//  - one damped layer on a damped half-space: surface / incident =
//    2 / (cos(w q1* H) + i (mu1* q1*)/(mu2* q2*) sin(w q1* H)) with q* = sqrt(rho*/mu*)
//    (Kramer 1996, eq. 7.32 with complex moduli), SH at 35 deg with the q* of Snell's p, and
//    SV at vertical incidence, both damping kinds;
//  - causality: a constant-Q half-space's surface history of a Ricker pulse stays at rest until
//    the front, which travels at the unrelaxed speed sqrt(M_U/rho) (the body's w -> infinity
//    limit), arrives with the pulse's leading edge (1.4/f0 before its centre, where the
//    Ricker is 1.5e-7 of its peak): below 1e-6 of the peak there; and the peak is the
//    narrow-band estimate 2 A exp(-pi f0 zr / (vs Q0)) within 10 %;
//  - the elastic limit: a MediumDamping of zeros gives the elastic amplitudes to round-off.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include "slipwave/physics/damped_medium.hpp"
#include "slipwave/physics/plane_wave_layered.hpp"
#include "slipwave/physics/source_time_function.hpp"
#include "unit_check.hpp"

using namespace slipwave::physics;

namespace {

const ElasticMaterial rock{2400, 1600, 800}, soil{1900, 500, 200};

MediumDamping constantQ(double xi) {
  MediumDamping d;
  d.constant_q       = constantQFit(xi, 0.5, 20, 3);
  d.unrelaxed_factor = constantQUnrelaxedFactor(d.constant_q, 3.16);
  return d;
}

MediumDamping rayleigh(double xi) {
  MediumDamping d;
  d.rayleigh = rayleighFromDampingRatio(xi, 1.0, 10.0);
  return d;
}

void rayleighMedium() {
  const MediumDamping d = rayleigh(0.05);
  double              worst = 0;
  for (double hz : {0.3, 1.0, 3.0, 10.0, 30.0}) {
    const double       w  = 2 * M_PI * hz;
    const DampedMedium m  = dampedMedium(soil, d, w);
    const Complex      c2 = m.mu / m.rho;
    const double       want = 2 * rayleighDampingRatio(d.rayleigh, hz) / (1 - d.rayleigh.alpha * d.rayleigh.beta);
    worst                   = std::max(worst, std::fabs(c2.imag() / c2.real() / want - 1));
  }
  unit::near(worst, 0, 0, 1e-12, "Rayleigh medium: Im c*^2 / Re c*^2 = 2 xi(f) / (1 - alpha beta) at 0.3-30 Hz");
}

void constantQMedium() {
  const MediumDamping d  = constantQ(0.05);
  const LameParameters lm = lame(soil);
  double worst = 0;
  for (double hz : {0.5, 2.0, 7.0, 20.0}) {
    const DampedMedium m    = dampedMedium(soil, d, 2 * M_PI * hz);
    const Complex      want = d.unrelaxed_factor * constantQModulusRatio(d.constant_q, hz);
    worst                   = std::max({worst, std::abs(m.mu / lm.mu - want), std::abs(m.lambda / lm.lambda - want), std::fabs(m.rho.imag())});
  }
  unit::near(worst, 0, 0, 1e-14, "constant-Q medium: lambda*, mu* = f_U M(w)/M_U (lambda, mu), real density");
}

void attenuationOverWavelengths() {
  PlaneWaveLayered    f;
  LayeredSite         site{{}, {soil}, {constantQ(0.05)}};
  unit::check(f.setup(site, PlaneWaveType::SV, 0).empty(), "damped half-space setup");
  const double n = 3, q0 = 10;
  double       worst_exact = 0, worst_approx = 0;
  for (double hz : {1.0, 3.0, 10.0}) {
    const double  w      = 2 * M_PI * hz;
    const Complex q      = f.verticalSlowness(0, true, w);
    const double  lambda = 2 * M_PI / (w * q.real());
    const double  decay  = std::abs(std::exp(Complex(0, -w) * q * (n * lambda))); // a down-going wave over n wavelengths
    const double  Q      = constantQQuality(site.damping[0].constant_q, hz);
    worst_exact          = std::max(worst_exact, std::fabs(decay / std::exp(-2 * M_PI * n * std::tan(0.5 * std::atan(1 / Q))) - 1));
    worst_approx         = std::max(worst_approx, std::fabs(std::log(decay) / (-M_PI * n / q0) - 1));
  }
  unit::near(worst_exact, 0, 0, 1e-12, "constant Q 5 %: decay over 3 wavelengths = exp(-2 pi n tan(atan(1/Q(f))/2)) at 1, 3, 10 Hz");
  unit::near(worst_approx, 0, 0, 0.06, "constant Q 5 %: ln(decay) over 3 wavelengths = -pi n / Q0 within the fit's Q error (6 %)");
}

void oneLayerTransfer(PlaneWaveType wave, double angle, const MediumDamping &soil_damping, const MediumDamping &rock_damping, const char *what) {
  const double     H = 30;
  PlaneWaveLayered f;
  unit::check(f.setup({{H}, {soil, rock}, {soil_damping, rock_damping}}, wave, angle).empty(), "damped one-layer setup");
  const double p = f.horizontalSlowness();
  double       worst = 0;
  for (double hz = 0.25; hz < 12; hz += 0.25) {
    const double       w = 2 * M_PI * hz;
    const DampedMedium s = dampedMedium(soil, soil_damping, w), r = dampedMedium(rock, rock_damping, w);
    const Complex      q1 = std::sqrt(s.rho / s.mu - p * p), q2 = std::sqrt(r.rho / r.mu - p * p);
    const Complex      want = 2.0 / (std::cos(w * q1 * H) + Complex(0, 1) * (s.mu * q1) / (r.mu * q2) * std::sin(w * q1 * H));
    const Complex      got  = f.stateAt(f.amplitudes(w), w, 0.0).u[wave == PlaneWaveType::SH ? 1 : 0];
    worst                   = std::max(worst, std::abs(got - want) / std::abs(want));
  }
  unit::near(worst, 0, 0, 1e-10, what);
}

void causality() {
  PlaneWaveLayered    f;
  const MediumDamping d = constantQ(0.05);
  unit::check(f.setup({{}, {soil}, {d}}, PlaneWaveType::SV, 0).empty(), "damped half-space setup");
  const RickerWavelet ricker{0.1, 4.0, 0.4};
  const double        dt = 1e-3, zr = 200;
  std::vector<double> v_in(3000);
  for (size_t k = 0; k < v_in.size(); ++k) v_in[k] = velocity(ricker, k * dt);
  const PlaneWaveHistories h       = synthesizeHistories(f, {0.0}, zr, v_in, dt);
  const double             c_u     = soil.vs * std::sqrt(d.unrelaxed_factor);
  const double             t_front = zr / c_u + ricker.delay - 1.4 / ricker.frequency;
  double                   before = 0, peak = 0;
  for (size_t k = 0; k < h.samples; ++k) {
    const double v = std::fabs(h.velocity[k]);
    peak           = std::max(peak, v);
    if (k * dt < t_front) before = std::max(before, v);
  }
  char what[200];
  std::snprintf(what, sizeof what, "constant Q 5 %%: surface at rest before the unrelaxed front (zr / c_U = %.4f s) meets the pulse's edge (peak %.3g)", zr / c_u, peak);
  unit::near(before / peak, 0, 0, 1e-6, what);
  // Narrow-band estimate of the peak: twice the incident one, decayed over zr at f0 by
  // exp(-pi f0 zr / (vs Q0)); the Ricker is broadband (its low frequencies decay less, its
  // high ones more), so 10 %.
  unit::near(peak, 2 * ricker.amplitude * std::exp(-M_PI * ricker.frequency * zr / (soil.vs * 10)), 0.1, 0, "constant Q 5 %: surface peak = 2 A exp(-pi f0 zr / (vs Q0))");
}

void elasticLimit() {
  PlaneWaveLayered e, z;
  const LayeredSite site{{8, 12}, {soil, {2100, 900, 400}, rock}, {}};
  LayeredSite       zero = site;
  zero.damping.assign(3, MediumDamping{});
  unit::check(e.setup(site, PlaneWaveType::SV, 25).empty() && z.setup(zero, PlaneWaveType::SV, 25).empty(), "elastic-limit setups");
  double worst = 0;
  for (double hz : {0.7, 4.0, 13.0}) {
    const std::vector<Complex> a = e.amplitudes(2 * M_PI * hz), b = z.amplitudes(2 * M_PI * hz);
    for (size_t k = 0; k < a.size(); ++k) worst = std::max(worst, std::abs(a[k] - b[k]));
  }
  unit::near(worst, 0, 0, 1e-13, "zero damping gives the elastic amplitudes");
  LayeredSite bad = site;
  bad.damping.assign(2, MediumDamping{});
  unit::check(!e.setup(bad, PlaneWaveType::SV, 25).empty(), "a damping list of the wrong length is refused");
}

} // namespace

int main() {
  rayleighMedium();
  constantQMedium();
  attenuationOverWavelengths();
  oneLayerTransfer(PlaneWaveType::SH, 35, constantQ(0.05), constantQ(0.01), "constant Q (5 % soil, 1 % rock), SH 35 deg: one-layer transfer (Kramer 7.32, complex moduli)");
  oneLayerTransfer(PlaneWaveType::SV, 0, constantQ(0.05), MediumDamping{}, "constant Q (5 % soil, elastic rock), SV vertical: one-layer transfer");
  oneLayerTransfer(PlaneWaveType::SH, 35, rayleigh(0.05), rayleigh(0.05), "Rayleigh 5 %, SH 35 deg: one-layer transfer with rho* = rho (1 - i alpha/w)");
  oneLayerTransfer(PlaneWaveType::SV, 0, rayleigh(0.05), rayleigh(0.05), "Rayleigh 5 %, SV vertical: one-layer transfer");
  causality();
  elasticLimit();
  return unit::failures();
}

// Plane waves in a layered half-space (physics/plane_wave_layered) and the FFT behind their
// histories (numerics/fft), against closed forms:
//  - FFT: a direct DFT sum;
//  - free-surface reflection coefficients of a homogeneous half-space (Aki & Richards,
//    Quantitative Seismology, 2nd ed., eqs. 5.27 and 5.30);
//  - zero traction at the surface and continuity across interfaces of a 3-layer site;
//  - vertical energy flux: a free-surface stack sends back all that comes in;
//  - one layer on a half-space: surface / incident = 2 / (cos(w q1 H) + i (mu1 q1)/(mu2 q2)
//    sin(w q1 H)) for SH at any angle and SV at vertical incidence (Kramer 1996, eq. 7.32 with
//    the impedance ratio of the vertical slownesses);
//  - synthesised histories of a vertically incident Ricker SV wave: incident plus reflected
//    pulse, 2 v(t - z_r/vs) at the surface; the displacement (fourth-order integral, Hermite in
//    between) to 1e-7 of its peak at dt = 1 ms, f0 = 4 Hz (3e-9 measured; the plain trapezoid
//    gave 6e-5).
//  - the strain channels (with_strain) of an inclined P wave on a layered site: sigma_zz = 0
//    at the free surface; inside each medium, the volumetric strain they give
//    (physics::undrainedPlaneWavePressure with alpha M = 1) equals eps_xx + d u_z/dz by
//    centred differences of the displacement histories 5 cm apart, to 1e-5 of its peak (the
//    differences' own error, (w dz / c)^2 / 6, is 1e-7 at 10 Hz).
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include "slipwave/numerics/fft.hpp"
#include "slipwave/physics/biot.hpp"
#include "slipwave/physics/plane_wave_layered.hpp"
#include "slipwave/physics/source_time_function.hpp"
#include "unit_check.hpp"

using namespace slipwave::physics;
using namespace slipwave::numerics;

namespace {

const ElasticMaterial rock{2400, 1600, 800}, soil{1900, 500, 200}, clay{1800, 400, 150};

void fftAgainstDft() {
  const size_t         n = 16;
  std::vector<Complex> x(n), X;
  for (size_t k = 0; k < n; ++k) x[k] = Complex(std::sin(1.3 * k) + 0.2 * k, std::cos(0.7 * k * k));
  X = x;
  fft(X, false);
  double err = 0;
  for (size_t j = 0; j < n; ++j) {
    Complex s = 0;
    for (size_t k = 0; k < n; ++k) s += x[k] * std::exp(Complex(0, -2 * M_PI * j * k / n));
    err = std::max(err, std::abs(s - X[j]));
  }
  fft(X, true);
  double back = 0;
  for (size_t k = 0; k < n; ++k) back = std::max(back, std::abs(X[k] - x[k]));
  unit::near(err, 0, 0, 1e-12, "fft: 16 points match the direct DFT sum");
  unit::near(back, 0, 0, 1e-14, "fft: the inverse restores the input");
  unit::check(fftLength(1) == 1 && fftLength(5) == 8 && fftLength(16) == 16, "fftLength: next power of two");
}

// Aki & Richards (5.27) for an incident P (angle i) and (5.30) for an incident SV (angle j):
// with a = vp, b = vs, p the ray parameter, D = (1/b^2 - 2p^2)^2 + 4p^2 (cos i/a)(cos j/b),
//   PP = (-(1/b^2-2p^2)^2 + 4p^2 (cos i/a)(cos j/b)) / D,  PS = 4 (a/b) p (cos i/a)(1/b^2-2p^2) / D,
//   SS = -PP,  SP = 4 (b/a) p (cos j/b)(1/b^2-2p^2) / D.
// Signs depend on the polarisation conventions, so the magnitudes are compared.
void halfspaceReflection(PlaneWaveType wave, double angle) {
  const ElasticMaterial m = rock;
  PlaneWaveLayered      f;
  unit::check(f.setup({{}, {m}, {}}, wave, angle).empty(), "half-space setup");
  const double p = f.horizontalSlowness(), a = m.vp, b = m.vs;
  const double ci = std::sqrt(1 - p * p * a * a), cj = std::sqrt(1 - p * p * b * b);
  const double g = 1 / (b * b) - 2 * p * p, D = g * g + 4 * p * p * (ci / a) * (cj / b);
  const double PP = (-g * g + 4 * p * p * (ci / a) * (cj / b)) / D, PS = 4 * (a / b) * p * (ci / a) * g / D, SP = 4 * (b / a) * p * (cj / b) * g / D;
  const std::vector<Complex> amp = f.amplitudes(2 * M_PI * 3);
  const bool                 P   = wave == PlaneWaveType::P;
  char                       what[120];
  std::snprintf(what, sizeof what, "half-space, incident %s at %g deg: |reflected P| (Aki & Richards %s)", P ? "P" : "SV", angle, P ? "PP" : "SP");
  unit::near(std::abs(amp[0]), std::fabs(P ? PP : SP), 1e-12, 1e-14, what);
  std::snprintf(what, sizeof what, "half-space, incident %s at %g deg: |reflected S| (Aki & Richards %s)", P ? "P" : "SV", angle, P ? "PS" : "SS");
  unit::near(std::abs(amp[1]), std::fabs(P ? PS : PP), 1e-12, 1e-14, what);
}

LayeredSite threeLayers() { return {{8, 12, 20}, {clay, soil, {2100, 900, 400}, rock}, {}}; }

void boundaryConditions(PlaneWaveType wave, double angle) {
  PlaneWaveLayered f;
  const LayeredSite site = threeLayers();
  unit::check(f.setup(site, wave, angle).empty(), "layered setup");
  const double               w   = 2 * M_PI * 7.3;
  const std::vector<Complex> amp = f.amplitudes(w);
  const auto                 top = f.stateAt(amp, w, 0.0);
  double                     scale = 0, surf = 0, jump = 0;
  for (int c = 0; c < 3; ++c) scale = std::max(scale, std::abs(top.u[c]));
  for (int c = 0; c < 3; ++c) surf = std::max(surf, std::abs(top.traction[c]) * w / (lame(site.materials[0]).mu * w * scale / site.materials[0].vs));
  double z = 0;
  for (double h : site.thickness) {
    z += h;
    const auto above = f.stateAt(amp, w, z * (1 - 1e-13)), below = f.stateAt(amp, w, z * (1 + 1e-13));
    for (int c = 0; c < 3; ++c) {
      jump = std::max(jump, std::abs(above.u[c] - below.u[c]) / scale);
      jump = std::max(jump, std::abs(above.traction[c] - below.traction[c]) / (lame(rock).mu * scale / rock.vs));
    }
  }
  const char *name = wave == PlaneWaveType::P ? "P" : wave == PlaneWaveType::SV ? "SV" : "SH";
  char        what[120];
  std::snprintf(what, sizeof what, "3 layers, %s at %g deg, 7.3 Hz: surface traction / (mu w |u| / vs) ~ 0", name, angle);
  unit::near(surf, 0, 0, 1e-10, what);
  std::snprintf(what, sizeof what, "3 layers, %s at %g deg: displacement and traction continuous at the interfaces", name, angle);
  unit::near(jump, 0, 0, 1e-9, what);
}

// Vertical energy flux per unit horizontal area of a wave of amplitude A: rho c^2 Re(q) |A|^2
// (energy density times c cos(angle)); evanescent waves (q imaginary) carry none.
void energyFlux(PlaneWaveType wave, double angle) {
  PlaneWaveLayered f;
  unit::check(f.setup(threeLayers(), wave, angle).empty(), "layered setup");
  const size_t  N  = f.layerCount();
  const double  qP = f.verticalSlowness(N, false, 0.0).real(), qS = f.verticalSlowness(N, true, 0.0).real();
  const double  fP = rock.rho * rock.vp * rock.vp * qP, fS = rock.rho * rock.vs * rock.vs * qS;
  const size_t  nw = wave == PlaneWaveType::SH ? 2 : 4;
  double        worst = 0;
  for (double hz : {0.5, 2.0, 7.3, 19.0}) {
    const std::vector<Complex> amp = f.amplitudes(2 * M_PI * hz);
    const double in = wave == PlaneWaveType::P ? fP : fS;
    const double out = wave == PlaneWaveType::SH ? fS * std::norm(amp[N * nw]) : fP * std::norm(amp[N * nw]) + fS * std::norm(amp[N * nw + 1]);
    worst = std::max(worst, std::fabs(out / in - 1));
  }
  const char *name = wave == PlaneWaveType::P ? "P" : wave == PlaneWaveType::SV ? "SV" : "SH";
  char        what[120];
  std::snprintf(what, sizeof what, "3 layers, %s at %g deg: reflected energy flux = incident at 0.5-19 Hz", name, angle);
  unit::near(worst, 0, 0, 1e-10, what);
}

void oneLayerTransfer(PlaneWaveType wave, double angle) {
  const double     H = 30;
  PlaneWaveLayered f;
  unit::check(f.setup({{H}, {soil, rock}, {}}, wave, angle).empty(), "one-layer setup");
  const Complex q1 = f.verticalSlowness(0, true, 0.0), q2 = f.verticalSlowness(1, true, 0.0);
  const double  ratio = (lame(soil).mu * q1.real()) / (lame(rock).mu * q2.real());
  double        worst = 0;
  for (double hz = 0.25; hz < 12; hz += 0.25) {
    const double  w    = 2 * M_PI * hz;
    const Complex want = 2.0 / (std::cos(w * q1.real() * H) + Complex(0, ratio * std::sin(w * q1.real() * H)));
    const Complex got  = f.stateAt(f.amplitudes(w), w, 0.0).u[wave == PlaneWaveType::SH ? 1 : 0];
    worst              = std::max(worst, std::abs(got - want) / std::abs(want));
  }
  char what[140];
  std::snprintf(what, sizeof what, "30 m soil on rock, %s at %g deg: surface / incident = 2/(cos kH + i a sin kH), 0.25-12 Hz", wave == PlaneWaveType::SH ? "SH" : "SV", angle);
  unit::near(worst, 0, 0, 1e-11, what);
}

void verticalRickerHistories() {
  PlaneWaveLayered f;
  unit::check(f.setup({{}, {soil}, {}}, PlaneWaveType::SV, 0).empty(), "half-space setup");
  const RickerWavelet ricker{0.1, 4.0, 0.4};
  const double        dt = 1e-3, zr = 100;
  std::vector<double> v_in(2000);
  for (size_t k = 0; k < v_in.size(); ++k) v_in[k] = velocity(ricker, k * dt);
  const std::vector<double> depths{0.0, 40.0};
  const PlaneWaveHistories  h = synthesizeHistories(f, depths, zr, v_in, dt);
  double                    err_v = 0, err_u = 0, err_up = 0;
  for (size_t k = 0; k < h.samples; ++k) {
    const double t = k * dt;
    for (size_t d = 0; d < 2; ++d) {
      const double z  = depths[d];
      const double tu = t - (zr - z) / soil.vs, td = t - (zr + z) / soil.vs; // up-going, then its reflection
      err_v           = std::max(err_v, std::fabs(h.velocity[(d * 3) * h.samples + k] - velocity(ricker, tu) - velocity(ricker, td)) / 0.2);
      err_u = std::max(err_u, std::fabs(planeWaveDisplacementAt(h, d, 0, t + 0.3 * dt) - displacement(ricker, tu + 0.3 * dt) - displacement(ricker, td + 0.3 * dt)));
      err_up = std::max(err_up, std::fabs(h.velocity[(d * 3 + 2) * h.samples + k]));
    }
  }
  const double u_peak = 2 * displacement(ricker, ricker.delay + 1 / (M_PI * std::sqrt(2.0) * ricker.frequency));
  unit::near(err_v, 0, 0, 1e-6, "vertical SV Ricker: velocity = v(t - (zr-z)/vs) + v(t - (zr+z)/vs) at z = 0, 40 m (/ peak)");
  unit::near(err_u / u_peak, 0, 0, 1e-7, "vertical SV Ricker: displacement between samples (Hermite) matches the closed form (/ peak)");
  unit::near(err_up, 0, 0, 1e-12, "vertical SV Ricker: no vertical motion");
}

void strainChannels() {
  PlaneWaveLayered f;
  unit::check(f.setup({{20.0}, {soil, rock}, {}}, PlaneWaveType::P, 30).empty(), "layered setup");
  const RickerWavelet ricker{0.1, 8.0, 0.2};
  const double        dt = 5e-4, zr = 60, dz = 0.05;
  std::vector<double> v_in(1600);
  for (size_t k = 0; k < v_in.size(); ++k) v_in[k] = velocity(ricker, k * dt);
  // Depth triplets about 10 m (soil) and 40 m (rock), and the surface.
  const std::vector<double> depths{10 - dz, 10, 10 + dz, 40 - dz, 40, 40 + dz, 0.0};
  const PlaneWaveHistories  h = synthesizeHistories(f, depths, zr, v_in, dt, true);
  unit::check(h.channels == 5, "with_strain: five channels");
  double surface = 0, stress_peak = 0, err = 0, peak = 0;
  for (size_t k = 0; k < h.samples; ++k) {
    const double t = (k + 0.4) * dt;
    surface        = std::max(surface, std::fabs(planeWaveDisplacementAt(h, 6, 3, t)));
    for (size_t m = 0; m < 2; ++m) {
      const ElasticMaterial &mat = m == 0 ? soil : rock;
      const LameParameters   lm  = lame(mat);
      const size_t           d   = 3 * m + 1;
      const double           szz = planeWaveDisplacementAt(h, d, 3, t), exx = planeWaveDisplacementAt(h, d, 4, t);
      // The up component's derivative along depth z (down): d u_z/dz = -d u_up/d depth.
      const double ezz = -(planeWaveDisplacementAt(h, d + 1, 2, t) - planeWaveDisplacementAt(h, d - 1, 2, t)) / (2 * dz);
      const double ev  = -undrainedPlaneWavePressure(szz, exx, lm.lambda, lm.mu, 1, 1);
      err              = std::max(err, std::fabs(ev - (exx + ezz)));
      peak             = std::max(peak, std::fabs(exx + ezz));
      stress_peak      = std::max(stress_peak, std::fabs(szz));
    }
  }
  unit::near(surface / stress_peak, 0, 0, 1e-9, "strain channels: sigma_zz = 0 at the free surface (/ peak at depth)");
  unit::near(err / peak, 0, 0, 1e-5, "strain channels: eps_v from sigma_zz and eps_xx = eps_xx + du_z/dz by differences, soil and rock");
}

} // namespace

int main() {
  fftAgainstDft();
  halfspaceReflection(PlaneWaveType::P, 30);
  halfspaceReflection(PlaneWaveType::SV, 20);
  halfspaceReflection(PlaneWaveType::P, 70);
  for (PlaneWaveType w : {PlaneWaveType::P, PlaneWaveType::SV, PlaneWaveType::SH}) {
    boundaryConditions(w, 25);
    energyFlux(w, w == PlaneWaveType::P ? 30 : 20);
  }
  energyFlux(PlaneWaveType::SV, 40); // beyond the critical angle of the half-space's P (30 deg): evanescent P
  oneLayerTransfer(PlaneWaveType::SH, 35);
  oneLayerTransfer(PlaneWaveType::SV, 0);
  verticalRickerHistories();
  strainChannels();
  return unit::failures();
}

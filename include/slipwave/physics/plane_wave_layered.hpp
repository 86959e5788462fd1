// Exact plane P, SV or SH waves in a horizontally layered elastic or damped half-space with a
// free surface, in the frequency domain (time dependence e^{i w t}), for the Domain Reduction
// Method's free field. A damped medium (Rayleigh or constant Q) enters through its complex
// density and moduli at each frequency (physics/damped_medium.hpp), as the discrete model
// damps it.
//
// Geometry: depth z >= 0 downward from the free surface; layers 0 .. N-1 with thicknesses
// h_j over the half-space (material N), which starts at depth z_N = sum h_j. A plane wave of
// horizontal slowness p (Snell's law: the same in every layer) comes up through the
// half-space at angle i from the vertical, p = sin i / c_halfspace. Every field carries the
// factor e^{-i w p x} along the horizontal propagation direction x, factored out here.
//
// Method: in each medium the field is the sum of down- and up-going P and S waves (SH: S only)
// with vertical slowness q = sqrt(1/c^2 - p^2), or q = -i sqrt(p^2 - 1/c^2) where the wave
// is evanescent; with damping c is complex and q the root with Im q <= 0 (e^{-i w q z}
// decays downward), continuous with both elastic cases. p stays real: sin i over the
// half-space's given (real) speed, so the field at x is the history at t - p x as in the
// elastic case; a damped wave then decays vertically only. Down-going amplitudes are referenced at the layer's top, up-going ones at its
// bottom, so no exponential ever exceeds 1 and thick or evanescent layers stay well conditioned
// (the global-matrix form of the Thomson-Haskell propagator, Knopoff 1964). The free surface
// (zero traction) and the continuity of displacement and traction at every interface give a
// (4N+2) x (4N+2) linear system (SH: 2N+1) per frequency, solved by Gaussian elimination.
//
// Polarisations (x horizontal along propagation, z down): P d = vp (p, s_z) (along the
// slowness), SV d = vs (-s_z, p), SH d = transverse; unit vectors for propagating waves
// (damped: complex vp, vs, with d.d = 1 unconjugated; at vertical incidence still (0, 1) and
// (1, 0)).
// The incident up-going wave (s_z = -q) thus moves +x for SV, upward and +x for P.
// Displacements are returned as (radial x, transverse, up), up = -z.
#pragma once
#include <array>
#include <complex>
#include <string>
#include <vector>

#include "slipwave/physics/damped_medium.hpp"
#include "slipwave/physics/elastic_material.hpp"

namespace slipwave::physics {

enum class PlaneWaveType { P, SV, SH };

struct LayeredSite {
  std::vector<double>          thickness;  // h_j [m] of the layers from the surface down
  std::vector<ElasticMaterial> materials;  // thickness.size() + 1: the layers, then the half-space
  std::vector<MediumDamping>   damping;    // empty (elastic) or one per material
};

using Complex = std::complex<double>;

class PlaneWaveLayered {
public:
  // "" when valid, else one sentence: materials valid, thicknesses > 0, damping empty or one
  // per material, 0 <= angle < 90 deg, and p not at (within 1e-9 relative) a grazing
  // slowness 1/c of any layer's P or S wave.
  std::string setup(const LayeredSite &site, PlaneWaveType wave, double incidence_angle_deg);

  // Amplitudes of every wave at circular frequency w >= 0 for a unit incident amplitude at
  // the top of the half-space: per layer j, [4j .. 4j+3] = P down, S down, P up, S up (SH:
  // [2j, 2j+1] = down, up), then the half-space's reflected P down, S down (SH: S down).
  std::vector<Complex> amplitudes(double w) const;
  // Total displacement (radial, transverse, up) at depth z and traction on the horizontal
  // plane divided by -i w (tau_xz, tau_yz, tau_zz, z down) from amplitudes(w).
  struct State {
    std::array<Complex, 3> u, traction;
  };
  State stateAt(const std::vector<Complex> &amplitudes, double w, double z) const;

  double horizontalSlowness() const { return p_; }
  double halfspaceDepth() const { return top_.back(); }
  size_t layerCount() const { return site_.thickness.size(); }
  PlaneWaveType wave() const { return wave_; }
  // Vertical slowness of the P (or S) wave in medium j (N: the half-space) at frequency w.
  Complex verticalSlowness(size_t j, bool s_wave, double w) const;

private:
  struct Wave {
    std::array<Complex, 3> d, tau; // displacement (x, y, z down) and traction / (-i w) per unit amplitude
  };
  DampedMedium medium(size_t j, double w) const;
  Wave wave(size_t medium, bool s_wave, bool down, double w) const;
  size_t wavesPerMedium() const { return wave_ == PlaneWaveType::SH ? 2 : 4; }

  LayeredSite         site_;
  PlaneWaveType       wave_ = PlaneWaveType::SV;
  double              p_    = 0;
  std::vector<double> top_; // depth of the top of each medium (top_[N]: the half-space)
};

// Free-field histories at a set of depths for an incident wave whose up-going particle
// velocity (along the incident polarisation) at depth reference_depth >= halfspaceDepth() and
// x = 0 is v_in: v_in[k] = v(k dt), k = 0 .. m-1, zero before. They are synthesised by FFT
// over a period of at least 4m samples (zero padded, so the reverberations of m samples have
// decayed before they wrap around). Returned per depth d and channel c, sample k: index
// (d*channels + c)*m + k, a rate and its time integral (zero at t = 0; the trapezoid rule with
// its end correction from the spectral derivative, fourth order). Channels 0-2: velocity and
// displacement (radial, transverse, up). With with_strain (a saturated site's undrained pore
// pressure, physics::undrainedPorePressure) two more, both continuous across the horizontal
// interfaces: 3, the total normal stress on a horizontal plane sigma_zz [Pa, tension
// positive]; 4, the normal strain along the direction of travel eps_xx = -p v_x. Their
// integral channel holds the value, the other its rate. The field at horizontal position x is
// the history at t - p x.
struct PlaneWaveHistories {
  size_t              samples = 0, channels = 3;
  double              dt      = 0;
  std::vector<double> velocity, displacement;
};
PlaneWaveHistories synthesizeHistories(const PlaneWaveLayered &field, const std::vector<double> &depths, double reference_depth, const std::vector<double> &v_in,
                                       double dt, bool with_strain = false);

// The integral channel c (displacement for c < 3, sigma_zz, eps_xx) at depth index d and time
// t (the histories' own clock): cubic Hermite between samples with the rate as its slope
// (error O(dt^4)); zero for t <= 0, the last sample held after the end.
double planeWaveDisplacementAt(const PlaneWaveHistories &h, size_t d, size_t c, double t);

} // namespace slipwave::physics

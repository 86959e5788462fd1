#include "slipwave/physics/soil_backbone.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace slipwave::physics {
namespace {

// Darendeli (2001): coefficients of his model fitted over all soils.
constexpr double kPhi[13] = {0, 0.0352, 0.0010, 0.3246, 0.3483, 0.9190, 0.8005, 0.0129, -0.1069, -0.2889, 0.2919, 0.6329, -0.0057};
constexpr double kAtmosphere = 101325; // [Pa]

void require(bool ok, const std::string &what) {
  if (!ok) throw std::invalid_argument(what);
}

// G/Gmax of the curve without its cap.
double uncappedRatio(const SoilBackbone &b, double gamma) {
  switch (b.kind) {
  case BackboneKind::Mkz: return 1.0 / (1.0 + b.beta * std::pow(gamma / b.reference_strain, b.curvature));
  case BackboneKind::Gqh: {
    const double x = gamma / b.reference_strain;
    if (x == 0) return 1.0;
    const double xp = b.theta[3] * std::pow(x, b.theta[4]);
    const double theta = std::min(1.0, b.theta[0] + b.theta[1] * xp / (std::pow(b.theta[2], b.theta[4]) + xp));
    // tau/tau_max = [1 + x - sqrt((1+x)^2 - 4 theta x)] / (2 theta), rationalised so that it holds
    // at theta = 0 (the hyperbola x/(1+x)) without cancellation; theta <= 1 keeps the root real.
    const double root = std::sqrt((1 + x) * (1 + x) - 4 * theta * x);
    return 2.0 / (1 + x + root); // (tau/tau_max) / x
  }
  case BackboneKind::Table: {
    const std::vector<double> &s = b.table_strain, &r = b.table_ratio;
    if (gamma <= s.front()) return r.front();
    if (gamma >= s.back()) return r.back() * s.back() / gamma; // the last row's stress
    const size_t k = std::upper_bound(s.begin(), s.end(), gamma) - s.begin(); // s[k-1] < gamma < s[k]
    // Linear in (ln gamma, ln G/Gmax): a power law between rows. tau is then concave wherever
    // the table's log-log slope falls from row to row, as on every MKZ-shaped curve; linear in
    // ln gamma alone puts a convex kink in tau at each row where G/Gmax levels off.
    const double w = std::log(gamma / s[k - 1]) / std::log(s[k] / s[k - 1]);
    return r[k - 1] * std::pow(r[k] / r[k - 1], w);
  }
  }
  return 1.0;
}

// Gauss-Legendre nodes and weights on [-1, 1] by Newton on P_n (n = 10).
struct GaussLegendre {
  static constexpr int n = 10;
  double               x[n], w[n];
  GaussLegendre() {
    for (int i = 0; i < n; ++i) {
      double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 1;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1);
        const double dz = p1 / dp;
        z -= dz;
        if (std::fabs(dz) < 1e-16) break;
      }
      x[i] = z;
      w[i] = 2 / ((1 - z * z) * dp * dp);
    }
  }
};

} // namespace

SoilBackbone mkzBackbone(double reference_strain, double curvature, double beta, double cap_strain) {
  require(reference_strain > 0 && std::isfinite(reference_strain), "MKZ backbone: reference strain must be > 0");
  require(curvature > 0 && std::isfinite(curvature), "MKZ backbone: curvature s must be > 0");
  require(beta > 0 && std::isfinite(beta), "MKZ backbone: beta must be > 0");
  require(cap_strain >= 0 && std::isfinite(cap_strain), "backbone: the strength cap tau_max/Gmax must be >= 0 (0: none)");
  SoilBackbone b;
  b.kind = BackboneKind::Mkz;
  b.reference_strain = reference_strain;
  b.curvature = curvature;
  b.beta = beta;
  b.cap_strain = cap_strain;
  return b;
}

SoilBackbone gqhBackbone(double shear_modulus, double strength, const double theta[5]) {
  require(shear_modulus > 0 && strength > 0 && std::isfinite(strength / shear_modulus), "GQ/H backbone: Gmax and tau_max must be > 0");
  require(theta[2] > 0 && theta[3] >= 0 && theta[4] > 0, "GQ/H backbone: theta3 > 0, theta4 >= 0 and theta5 > 0 required");
  for (int k = 0; k < 5; ++k) require(std::isfinite(theta[k]), "GQ/H backbone: theta must be finite");
  SoilBackbone b;
  b.kind = BackboneKind::Gqh;
  b.reference_strain = strength / shear_modulus;
  for (int k = 0; k < 5; ++k) b.theta[k] = theta[k];
  return b;
}

SoilBackbone tableBackbone(std::vector<double> strain, std::vector<double> ratio, double cap_strain) {
  require(strain.size() == ratio.size() && strain.size() >= 2, "table backbone: needs at least 2 rows of (strain, G/Gmax)");
  for (size_t k = 0; k < strain.size(); ++k) {
    require(strain[k] > 0 && std::isfinite(strain[k]), "table backbone: strains must be > 0 (a ratio, not percent)");
    require(k == 0 || strain[k] > strain[k - 1], "table backbone: strains must increase strictly");
    require(ratio[k] > 0 && ratio[k] <= 1, "table backbone: G/Gmax must be in (0, 1]");
  }
  require(cap_strain >= 0 && std::isfinite(cap_strain), "backbone: the strength cap tau_max/Gmax must be >= 0 (0: none)");
  SoilBackbone b;
  b.kind = BackboneKind::Table;
  b.table_strain = std::move(strain);
  b.table_ratio = std::move(ratio);
  b.cap_strain = cap_strain;
  return b;
}

double modulusReduction(const SoilBackbone &b, double gamma) {
  const double r = uncappedRatio(b, gamma);
  // tau <= tau_max: G/Gmax <= (tau_max/Gmax) / gamma.
  return b.cap_strain > 0 && r * gamma > b.cap_strain ? b.cap_strain / gamma : r;
}

double masingDampingRatio(const SoilBackbone &b, double gamma_a) {
  static const GaussLegendre gl;
  if (gamma_a <= 0) return 0.0;
  // Panel ends: log-spaced over 12 decades below gamma_a, plus every kink of the curve.
  const double        lo = gamma_a * 1e-12;
  std::vector<double> ends;
  const int           panels = 12 * 24;
  for (int k = 0; k <= panels; ++k) ends.push_back(lo * std::pow(gamma_a / lo, (double)k / panels));
  if (b.kind == BackboneKind::Table)
    for (double s : b.table_strain)
      if (s > lo && s < gamma_a) ends.push_back(s);
  if (b.cap_strain > 0 && uncappedRatio(b, gamma_a) * gamma_a > b.cap_strain) {
    // The cap's kink: the uncapped stress rises through tau_max once (bisection in ln gamma).
    double a = lo, c = gamma_a;
    for (int it = 0; it < 200 && c / a > 1 + 1e-15; ++it) {
      const double m = std::sqrt(a * c);
      (uncappedRatio(b, m) * m > b.cap_strain ? c : a) = m;
    }
    ends.push_back(a);
  }
  std::sort(ends.begin(), ends.end());
  double integral = 0.5 * lo * lo * modulusReduction(b, lo); // F ~ Gmax gamma below lo
  for (size_t k = 0; k + 1 < ends.size(); ++k) {
    const double a = ends[k], h = 0.5 * (ends[k + 1] - ends[k]), mid = a + h;
    if (h <= 0) continue;
    double s = 0;
    for (int i = 0; i < GaussLegendre::n; ++i) {
      const double g = mid + h * gl.x[i];
      s += gl.w[i] * g * modulusReduction(b, g);
    }
    integral += h * s;
  }
  const double tau_a = gamma_a * modulusReduction(b, gamma_a);
  return 2 / M_PI * (2 * integral / (gamma_a * tau_a) - 1);
}

double darendeliReferenceStrain(const DarendeliSoil &s) {
  const double percent = (kPhi[1] + kPhi[2] * s.plasticity_index * std::pow(s.ocr, kPhi[3])) * std::pow(s.mean_effective_stress / kAtmosphere, kPhi[4]);
  return percent / 100;
}

double darendeliStrainScale(double mean_effective_stress, double reference_stress) { return std::pow(mean_effective_stress / reference_stress, kPhi[4]); }

double darendeliCurvature() { return kPhi[5]; }

double darendeliModulusReduction(const DarendeliSoil &s, double gamma) {
  return 1.0 / (1.0 + std::pow(gamma / darendeliReferenceStrain(s), darendeliCurvature()));
}

double darendeliMinimumDamping(const DarendeliSoil &s) {
  const double percent = (kPhi[6] + kPhi[7] * s.plasticity_index * std::pow(s.ocr, kPhi[8])) * std::pow(s.mean_effective_stress / kAtmosphere, kPhi[9]) *
                         (1 + kPhi[10] * std::log(s.frequency));
  return percent / 100;
}

double darendeliMasingDamping(double reference_strain, double curvature, double gamma) {
  if (gamma <= 0) return 0.0;
  // His a = 1 closed form, in percent: (100/pi) [4 (g - gr ln((g + gr)/gr)) / (g^2/(g + gr)) - 2].
  const double g = gamma, gr = reference_strain;
  const double d1 = 100 / M_PI * (4 * (g - gr * std::log1p(g / gr)) / (g * g / (g + gr)) - 2);
  const double a = curvature;
  const double c1 = -1.1143 * a * a + 1.8618 * a + 0.2523;
  const double c2 = 0.0805 * a * a - 0.0710 * a - 0.0095;
  const double c3 = -0.0005 * a * a + 0.0002 * a + 0.0003;
  return (c1 * d1 + c2 * d1 * d1 + c3 * d1 * d1 * d1) / 100;
}

double darendeliDamping(const DarendeliSoil &s, double gamma) {
  const double b = kPhi[11] + kPhi[12] * std::log(s.cycles);
  const double masing = darendeliMasingDamping(darendeliReferenceStrain(s), darendeliCurvature(), gamma);
  return b * std::pow(darendeliModulusReduction(s, gamma), 0.1) * masing + darendeliMinimumDamping(s);
}

SoilBackbone darendeliBackbone(const DarendeliSoil &s, double cap_strain) {
  require(s.plasticity_index >= 0 && s.ocr >= 1 && s.mean_effective_stress > 0 && s.frequency > 0 && s.cycles >= 1,
          "Darendeli backbone: PI >= 0, OCR >= 1, sigma'_0 > 0, frequency > 0 and cycles >= 1 required");
  return mkzBackbone(darendeliReferenceStrain(s), darendeliCurvature(), 1.0, cap_strain);
}

} // namespace slipwave::physics

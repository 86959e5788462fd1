// Cost of one hysteretic-soil update per quadrature point (physics/hysteretic_soil.hpp), 2D
// plane strain and 3D, for several numbers of surfaces N, states in cache (256 points).
// Two loadings: a strong cyclic shear (equivalent strain amplitude ~1e-3 on a Darendeli
// backbone with gamma_r = 3.5e-4: most elements yield at every reversal) and a weak one
// (4e-7, below the elastic limit 1e-6: every element elastic, the cheapest path). Two calls:
// the update (state and stress at one strain), and the bulk force's step per point
// (hystereticSettleEvaluate: the state brought to the last strain, the stress evaluated at
// the new one).
// The time is the best of many short windows (256 updates each): on a shared machine a short
// window is the likeliest to run undisturbed, so the best is the machine's own speed.
//   build/bench/bench_hysteretic_soil [--csv FILE]
#include "slipwave/physics/hysteretic_soil.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

using namespace slipwave::physics;

namespace {

template <int Dim>
double nsPerUpdate(int surfaces, double amplitude, bool step, double *sink, double *yield_fraction) {
  using Layout = HystereticLayout<Dim>;
  constexpr int      points = 256, windows = 4000;
  HystereticSurfaces options;
  options.count = surfaces;
  const HystereticSoilModel model(5e7, 1e8, darendeliBackbone(DarendeliSoil{}), options);
  const int                 size = hystereticStateSize<Dim>(model);
  std::vector<double>       state((size_t)points * size, 0.0), strain((size_t)points * Layout::kStrain), last(strain), stress((size_t)points * Layout::kStress);
  double                    best = 1e300;
  std::size_t               dissipating = 0;
  for (int w = 0; w < windows; ++w) {
    // A strain path that turns: every component a sinusoid of its own phase (shear larger).
    last = strain;
    for (int p = 0; p < points; ++p) {
      const double a = 0.05 * w + 0.37 * p;
      for (int c = 0; c < Layout::kStrain; ++c) {
        const bool shear = c >= (Dim == 2 ? 2 : 3);
        strain[(size_t)p * Layout::kStrain + c] = amplitude * (shear ? 0.5 : 0.2) * std::sin(a + 1.1 * c);
      }
    }
    const auto t0 = std::chrono::steady_clock::now();
    for (int p = 0; p < points; ++p) {
      double       *s = &state[(size_t)p * size], *sigma = &stress[(size_t)p * Layout::kStress];
      const double *e = &strain[(size_t)p * Layout::kStrain];
      const double  d = step ? hystereticSettleEvaluate<Dim>(model, s, s + Layout::kPlastic, &last[(size_t)p * Layout::kStrain], w + 1, e, sigma)
                           : hystereticUpdate<Dim>(model, s, e, sigma, s, w + 1);
      *sink += d;
      dissipating += d > 0;
    }
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  *yield_fraction = (double)dissipating / ((double)points * windows);
  return 1e9 * best / points;
}

} // namespace

int main(int argc, char **argv) {
  const char *csv = nullptr;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--csv") == 0) csv = argv[i + 1];
  FILE  *out = csv ? std::fopen(csv, "a") : nullptr;
  double sink = 0.0;
  for (int surfaces : {16, 24, 32, 48}) {
    for (int dim : {2, 3}) {
      for (double amplitude : {1e-3, 4e-7})
        for (bool step : {false, true}) {
          double       yielding = 0;
          const double ns = dim == 2 ? nsPerUpdate<2>(surfaces, amplitude, step, &sink, &yielding) : nsPerUpdate<3>(surfaces, amplitude, step, &sink, &yielding);
          const char  *load = amplitude > 1e-5 ? "strong" : "weak", *call = step ? "step" : "update";
          std::printf("hysteretic_soil %dD N=%-3d %-6s %-6s %7.1f ns  %5.2f ns/surface  (%3.0f%% dissipate)\n", dim, surfaces, load, call, ns, ns / surfaces,
                      100 * yielding);
          if (out) std::fprintf(out, "hysteretic_soil,%dd_n%d_%s%s,ns_per_update,%.2f,ns\n", dim, surfaces, load, step ? "_step" : "", ns);
        }
    }
  }
  if (out) std::fclose(out);
  return sink == 12345.678 ? 1 : 0; // keeps the results alive against dead-code elimination
}

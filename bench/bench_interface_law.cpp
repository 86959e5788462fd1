// Cost of one interface-law update per pair, 2D and 3D, with the pair states in cache
// (4096 pairs) and out of cache (4M pairs, far beyond the last-level cache). Increments are
// a cyclic shear with a normal wobble so that pairs go through stick, yield and reversal.
//   build/bench/bench_interface_law [--csv FILE]
#include "slipwave/physics/mohr_coulomb_interface.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

using namespace slipwave::physics;

namespace {

template <int Dim>
double nsPerUpdate(std::size_t pairs, int sweeps, double *sink, double *slip_fraction) {
  InterfaceParams p;
  p.E = 1e8;
  p.G = 5e7;
  p.phi = 30 * M_PI / 180;
  p.psi = 0.0; // dilatancy would harden the pairs (compression grows with slip) until none slips
  p.c = 2e3;
  p.e_ini = 1e-3;
  const InterfaceLaw law(p);
  std::vector<InterfaceState<Dim>> state(pairs, interfaceInitialState<Dim>(law, -1e5));
  // Per-pair increments as the simulation would gather them: one array of Dim values.
  std::vector<double> dw(pairs * Dim);
  const double w_y = (1e5 * law.tan_phi + p.c) / p.G;
  double elapsed = 0.0;
  std::size_t slipping = 0;
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    const double phase = 0.7 * sweep;
    for (std::size_t i = 0; i < pairs; ++i) {
      const double a = phase + 1e-3 * static_cast<double>(i % 997);
      for (int k = 0; k < Dim - 1; ++k) dw[i * Dim + k] = 1.5 * w_y * std::cos(a + 1.3 * k);
      dw[i * Dim + Dim - 1] = 0.05 * w_y * std::sin(3 * a);
    }
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < pairs; ++i) interfaceUpdate<Dim>(law, state[i], &dw[i * Dim], dw[i * Dim + Dim - 1]);
    elapsed += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    for (std::size_t i = 0; i < pairs; ++i) slipping += state[i].status == InterfaceStatus::Slip;
  }
  for (const auto &s : state) *sink += s.sigma_N;
  *slip_fraction = static_cast<double>(slipping) / (static_cast<double>(pairs) * sweeps);
  return 1e9 * elapsed / (static_cast<double>(pairs) * sweeps);
}

} // namespace

int main(int argc, char **argv) {
  const char *csv = nullptr;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--csv") == 0) csv = argv[i + 1];
  FILE *out = csv ? std::fopen(csv, "a") : nullptr;
  double sink = 0.0;
  struct Case {
    const char *name;
    int dim;
    std::size_t pairs;
    int sweeps;
  } cases[] = {{"2d_in_cache", 2, 4096, 4000}, {"3d_in_cache", 3, 4096, 4000},
               {"2d_out_of_cache", 2, 4u << 20, 10}, {"3d_out_of_cache", 3, 4u << 20, 10}};
  for (const Case &c : cases) {
    double slip = 0.0;
    const double ns = c.dim == 2 ? nsPerUpdate<2>(c.pairs, c.sweeps, &sink, &slip) : nsPerUpdate<3>(c.pairs, c.sweeps, &sink, &slip);
    std::printf("interface_law %-16s %7.2f ns/update/pair  %6.1f M updates/s  (%zu pairs, %.0f%% slipping)\n", c.name, ns,
                1e3 / ns, c.pairs, 100 * slip);
    if (out) {
      std::fprintf(out, "interface_law,%s,ns_per_update,%.3f,ns\n", c.name, ns);
      std::fprintf(out, "interface_law,%s,updates_per_second,%.4g,1/s\n", c.name, 1e9 / ns);
    }
  }
  if (out) std::fclose(out);
  return sink == 12345.678 ? 1 : 0; // keeps the states alive against dead-code elimination
}

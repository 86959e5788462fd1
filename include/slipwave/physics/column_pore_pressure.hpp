// The excess pore pressure of a free-field column's saturated segments (physics/
// free_field_column.hpp): the main mesh's explicit u-p split (porous/pore_pressure.hpp,
// docs/saturated-soil.md) restricted to a height-only motion, u = u_z(z) e_z and p = p(z),
// with no flow across the sides. Plain C++ (no PETSc), replicated on every rank with its column.
//
// Per unit area, at degree 1 (segment e between nodes e and e+1, length L_e, Biot coefficient
// alpha_e, modulus M_e, mobility kappa_e; dry segments add nothing):
//   storage   S_i  = sum over adjacent saturated segments L_e / (2 M_e)         (lumped)
//   coupling  (alpha Q u)_i = sum over adjacent saturated segments alpha_e (u_{e+1} - u_e) / 2
//   Darcy     H    = sum over saturated segments kappa_e / L_e [[1, -1], [-1, 1]]
//   skeleton  (alpha Q^T p)_e -= alpha_e (p_e + p_{e+1}) / 2, (alpha Q^T p)_{e+1} += the same.
// These are the main mesh's Q1/P1 matrices (full Gauss quadrature) applied to such a motion,
// per unit area of a node's cells: the horizontal shape functions integrate to the cells'
// width and their horizontal derivatives cancel, so every row of the main mesh's S, alpha Q u
// and H p at a node is its width share times the column's row (a side node's share is half an
// interior one's, and the noflow side loses nothing: the free field has no horizontal flow).
// The update is then the main mesh's on the same numbers (to round-off: some sums run in
// another order), with the same sub-step count:
//   p*      = p_n after m sub-steps S (p^{k+1} - p^k) = -(h/m) H p^k,
//             m = diffusionSubsteps(h, the main mesh's diffusion limit, its sub-cycling)
//             (the main mesh's limit, not the column's own: its Gershgorin rows also hold
//             the horizontal entries of H, so it is smaller, and another count would split
//             the step otherwise, an O(h) difference rather than round-off),
//   p_{n+1} = p* - S^{-1} alpha Q (u_{n+1} - u_n) + h q/S      on free nodes (0 elsewhere),
//   then the cavitation floor (physics/cavitation.hpp) where the main mesh has one: the total
//   pressure p_h + p held at or above the limit, the pore volume the water does not follow a
//   cavity per node.
// Free nodes, the hydrostatic pressure p_h and the inflow q are the main mesh's at the side's
// nodes (input/free_field.cpp), so the column's top and base have the main mesh's fluid
// conditions (a drained surface, the water table, a noflow or flux base).
#pragma once
#include <string>
#include <vector>

namespace slipwave::physics {

struct ColumnFluidSegment {
  bool   saturated = false;
  double alpha = 0, M = 0, kappa = 0; // Biot coefficient [-], modulus [Pa], mobility [m^2/(Pa s)]
};
struct ColumnFluidNode {
  bool   drained     = false; // excess pressure held at 0 (a drained boundary, the water table)
  double hydrostatic = 0;     // p_h [Pa], for the cavitation floor
  double inflow_rate = 0;     // q / S: the pressure rate of a prescribed inflow [Pa/s] (the same
                              // for any width share of the node, which divides out)
};
struct ColumnFluidRules {
  double dt_diffusion        = 1e300; // the main mesh's explicit diffusion limit [s]
  bool   subcycle            = true;  // -pore_pressure_subcycle
  bool   cavitation          = false;
  double cavitation_pressure = 0;     // [Pa gauge], with cavitation
};

class ColumnPorePressure {
public:
  // heights: the column's node heights (ascending), one segment per interval; nodes: one per
  // height. Returns "" or a sentence naming the problem.
  std::string setup(const std::vector<double> &heights, const std::vector<ColumnFluidSegment> &segments, const std::vector<ColumnFluidNode> &nodes,
                    const ColumnFluidRules &rules);
  // Some segment is saturated (otherwise nothing here does anything).
  bool active() const { return !storage_.empty(); }

  // Rest with zero excess pressure and no cavities at the vertical displacement u (node i's at
  // u[i * stride]): the reference of the first strain increment.
  void start(const double *u, int stride);
  // One step of length h to the vertical displacement u_{n+1}.
  void step(double h, const double *u, int stride);
  // f[i * stride] += scale (alpha Q^T p)_i: the pore pressure's force on the skeleton.
  void addForce(double scale, double *f, int stride) const;

  double pressure(int node) const { return p_[node]; }
  double cavity(int node) const { return cavity_[node]; }
  double storage(int node) const { return storage_[node]; }
  bool   free(int node) const { return inv_storage_[node] > 0; }
  double alpha(int segment) const { return segments_[segment].saturated ? segments_[segment].alpha : 0.0; }
  const ColumnFluidSegment &segment(int e) const { return segments_[e]; }
  // Sub-steps of the diffusion in a step of size h (the main mesh's count).
  int substeps(double h) const;
  // The column's own explicit diffusion limit (Gershgorin on S^{-1} H over free nodes), which
  // the main mesh's, taken over its wider rows, never exceeds.
  double diffusionLimit() const;
  // The undrained stiffening of the vertical row of node i for the stable step, as the main
  // mesh bounds it (PorePressureAddUndrainedRows): sum over segments e and their nodes a of
  // |(alpha Q_e)_a,i| w_a, w_a = sum_k |(alpha Q)_ak| / S_a over free nodes.
  double undrainedRow(int node) const;

  // p, alpha Q u and the cavities (3 per node).
  std::vector<double> state() const;
  size_t              stateSize() const { return 3 * storage_.size(); }
  void                setState(const double *s);

private:
  void couplingTimes(const double *u, int stride, std::vector<double> &q) const; // q = alpha Q u
  void diffusionTimes(const std::vector<double> &p, std::vector<double> &hp) const; // hp = H p

  std::vector<double>             length_;
  std::vector<ColumnFluidSegment> segments_;
  std::vector<double>             storage_, inv_storage_, hydrostatic_, inflow_rate_; // per node; inv 0 where not free
  ColumnFluidRules                rules_;
  std::vector<double>             p_, qu_, cavity_, qu_new_, p_star_, hp_;
};

} // namespace slipwave::physics

// The excess pore pressure of a free-field column's saturated segments (physics/
// free_field_column.hpp): the main mesh's explicit u-p split (porous/pore_pressure.hpp,
// docs/saturated-soil.md) restricted to a height-only motion, u = u_z(z) e_z and p = p(z),
// with no flow across the sides. Plain C++ (no PETSc), replicated on every rank with its column.
//
// Per unit area, element E of length L (J = L/2) with its GLL points (physics/column_element
// .hpp: weights w, derivative matrix D; degree 1: w = 1, D rows (-1/2, 1/2)), Biot coefficient
// alpha, modulus M and mobility kappa (dry elements add nothing), the pressure collocated at
// the GLL nodes as the main mesh's (fem/spectral_biot.hpp; at degree 1 the Q1/P1 matrices):
//   storage   S_a        += w_a J / M                                  (diagonal, lumped at p = 1)
//   coupling  (alpha Q u)_a += alpha w_a sum_b D_ab u_b                (J cancels)
//   Darcy     H_ab       += kappa / J sum_q w_q D_qa D_qb
//   skeleton  (alpha Q^T p)_b += alpha sum_a w_a D_ab p_a.
// At degree 1: S_i = sum L/(2M), (alpha Q u)_i = alpha (u_{e+1} - u_e)/2, H = kappa/L [[1,-1],[-1,1]].
// These are the main mesh's matrices applied to such a motion, per unit area of a node's
// cells: the horizontal shape functions integrate to the cells' width and their horizontal
// derivatives cancel, so every row of the main mesh's S, alpha Q u and H p at a node is its
// width share times the column's row (a side node's share is half an interior one's, and the
// noflow side loses nothing: the free field has no horizontal flow).
// The update is then the main mesh's on the same numbers (to round-off: some sums run in
// another order), with the same sub-step count:
//   p*      = p_n after m sub-steps S (p^{k+1} - p^k) = -(h/m) H p^k,
//             m = diffusionSubstepsOfDegree(p, h, the main mesh's diffusion limit, its
//             sub-cycling) (physics/split_diffusion_step.hpp; the main mesh's limit, not the
//             column's own: its Gershgorin rows also hold the horizontal entries of H, so it is
//             smaller, and another count would split the step otherwise, an O(h) difference
//             rather than round-off),
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

#include "slipwave/physics/column_element.hpp"

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
  // heights: the column's node heights (ascending), one segment per interval, p segments per
  // element of degree p (its nodes at the element's GLL points, as FreeFieldColumn::setup
  // checks); segments of an element share their fluid; nodes: one per height. Returns "" or a
  // sentence naming the problem.
  std::string setup(const std::vector<double> &heights, const std::vector<ColumnFluidSegment> &segments, const std::vector<ColumnFluidNode> &nodes,
                    const ColumnFluidRules &rules, const ColumnElement &element = ColumnElement());
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
  // Degree 1: the undrained stiffening of the vertical row of node i for the stable step, as
  // the main mesh bounds it (PorePressureAddUndrainedRows): sum over segments e and their
  // nodes a of |(alpha Q_e)_a,i| w_a, w_a = sum_k |(alpha Q)_ak| / S_a over free nodes.
  double undrainedRow(int node) const;
  // Degree p > 1: the modulus alpha^2 M by which element E's undrained stiffening
  // alpha^2 Q^T S^-1 Q is the element's stiffness matrix (0 when dry): with the pressure at the
  // GLL nodes, Q^T S^-1 Q = M/J D^T W D, the 1D element's stiffness per unit modulus (an upper
  // bound where drained nodes release it).
  double undrainedModulus(int element) const;

  // p, alpha Q u and the cavities (3 per node).
  std::vector<double> state() const;
  size_t              stateSize() const { return 3 * storage_.size(); }
  void                setState(const double *s);

private:
  void couplingTimes(const double *u, int stride, std::vector<double> &q) const; // q = alpha Q u
  void diffusionTimes(const std::vector<double> &p, std::vector<double> &hp) const; // hp = H p

  int elementCount() const { return (int)jacobian_.size(); }
  const ColumnFluidSegment &elementFluid(int E) const { return segments_[(size_t)E * element_.degree]; }

  ColumnElement                   element_;
  std::vector<double>             jacobian_, stiffness_ref_; // per element L/2; sum_q w_q D_qa D_qb
  std::vector<ColumnFluidSegment> segments_;
  std::vector<double>             storage_, inv_storage_, hydrostatic_, inflow_rate_; // per node; inv 0 where not free
  ColumnFluidRules                rules_;
  std::vector<double>             p_, qu_, cavity_, qu_new_, p_star_, hp_;
};

} // namespace slipwave::physics

// The free-field soil column of a lateral boundary (FLAC-style free-field boundary): a 1D
// column per unit area, with nodes at the heights of the lateral boundary's nodes, that
// carries the vertically propagating incident wave as if the model extended to infinity
// sideways. Plain C++ (no PETSc), replicated on every rank.
//
// Discretisation, chosen so that a main-mesh column with rollers and this column give the
// same motion to round-off (described at degree 1; at degree p see "Degree p" below):
//  - segment e between heights z_e and z_{e+1} (length L_e) has the material of the
//    main-mesh region next to it; lumped mass m_i = sum over adjacent segments rho L/2;
//  - every component is an independent chain: horizontal components (0 .. dim-2) are shear
//    motions with modulus mu (SV), the vertical one (dim-1, the last axis) has lambda + 2 mu
//    (P); spring k_e = modulus / L_e. (A Q1/P1 main mesh gives exactly these nodal forces for
//    a motion that depends only on height: the field is in the FE space and full Gauss
//    quadrature integrates its energy exactly.)
//  - base (node 0): Lysmer dashpot rho vs (horizontal) / rho vp (vertical) of the lowest
//    segment, plus the incident-wave traction 2 rho c v_in(t) on the input component (the
//    same equivalent force the main mesh's absorbing base receives); top free;
//  - Rayleigh damping alpha M + beta K, treated as the main TS treats it: the nodal part
//    (alpha, dashpot) centred, the stiffness part with the lagged half-step velocity;
//  - time stepping: the velocity-Verlet central difference of the TS type "cd", with the
//    same step h:
//      v_{n+1/2} = v_n + h/2 a_n;  u_{n+1} = u_n + h v_{n+1/2}
//      a* = (f_in(t_{n+1}) - K u_{n+1} - beta K v_{n+1/2}) / m
//      (1 + h/2 D) v_{n+1} = v_{n+1/2} + h/2 a*;  a_{n+1} = a* - D v_{n+1},  D = c/m + alpha.
//
// Degree p (spectral elements, the main mesh's -element_degree): the side's nodes are the GLL
// nodes of its elements, and every p consecutive segments from the base are one 1D element of
// degree p, the 1D restriction of the main mesh's element (a height-only motion of a tensor
// GLL element gives exactly these nodal forces: the horizontal GLL weights sum to the face):
// GLL lumped mass m_a = rho L/2 w_a, stiffness K_ab = (M/L) 2 sum_q w_q D_qa D_qb (D the GLL
// derivative matrix, w the weights on [-1, 1]: ColumnElement). The stress is per element and
// varies along it: stress(segment, node) evaluates it at a node of the segment's element, as
// the main mesh's GLL face rule does; constant-Q memory lives at the element's GLL points. At
// p = 1 all of this is the chain above, operation for operation.
//
// Free-field stress of a vertically propagating wave (vertical axis z = last axis, u = u(z)):
// the only strains are eps_xz = u_x'/2 (and eps_yz in 3D) for SV and eps_zz = u_z' for P, so
//   tau_xz = mu u_x',  tau_yz = mu u_y',  sigma_zz = (lambda + 2 mu) u_z',
//   sigma_xx = sigma_yy = lambda u_z' = lambda/(lambda + 2 mu) sigma_zz (lateral strain is zero),
// and the other components vanish. The column returns it per segment (constant there, as in
// the main mesh's cells), plus the stiffness-proportional viscous stress beta D:eps(v_{n+1/2}),
// because the main mesh applies beta K v_{n+1/2} as an internal force as well.
//
// Hysteretic segments (setHysteresis): the element's stress at each of its GLL points (both
// ends at p = 1, where the strain is constant) is the Iwan model of its region
// (physics/hysteretic_soil.hpp) fed the full strain of the height-only motion, eps_xz = u_x'/2
// (eps_yz = u_y'/2 in 3D) and eps_zz = u_z', the function the main mesh's cells evaluate at
// their points; its sigma_xz, sigma_yz, sigma_zz give the nodal forces f_a = sum_q w_q D_qa
// sigma_q (the elastic chains' K u for a linear stress), and its sigma_xx (the deviator
// couples it to sigma_zz once a surface yields) is the lateral stress the side receives. The
// horizontal normal stresses are equal (sigma_xx = sigma_yy in 3D: every deviatoric strain of
// the motion, hence every plastic strain, has e_xx = e_yy and e_xy = 0), so one is kept. The
// state advances in step() (the column is copied as the trial by its caller, which keeps the
// committed one: the main mesh's trial/commit rule). The stable step stays the elastic one:
// the Iwan tangent modulus is at most Gmax. With constant-Q the memory is driven by the Iwan
// stress at each point (as the main mesh drives its memory by the force of the soil's stress),
// one more set of memory variables for the lateral stress.
//
// Saturated segments (setPorePressure, any degree): the segments' materials are the drained
// skeleton's, and the vertical chain carries the excess pore pressure of the main mesh's u-p
// split restricted to the column (physics/column_pore_pressure.hpp): each step computes
// p_{n+1} from u_{n+1} and adds the force alpha Q^T p_{n+1} to the vertical chain, so the
// column's P wave is the main mesh's, draining or undrained, to round-off. The base's vertical
// dashpot and P input take the undrained impedance of a saturated base segment, as the main
// mesh's absorbing base does. stress() stays the effective (skeleton's) stress; the total
// horizontal stress on a side is it less alpha p (poreStress), which varies along a segment.
// An SV wave leaves the vertical chain, and so p, exactly at rest.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "slipwave/physics/column_element.hpp"
#include "slipwave/physics/column_pore_pressure.hpp"
#include "slipwave/physics/constant_q.hpp"
#include "slipwave/physics/elastic_material.hpp"
#include "slipwave/physics/hysteretic_soil.hpp"

namespace slipwave::physics {

class FreeFieldColumn {
public:
  // heights: strictly ascending node heights (node 0 is the base); materials: one per segment
  // (heights.size() - 1). Degree p > 1: the segments count p per element, the segments of an
  // element share their material and its nodes lie at the element's GLL points (to 1e-6 of
  // its length). Returns "" or a sentence naming the problem.
  std::string setup(int dim, const std::vector<double> &heights, const std::vector<ElasticMaterial> &materials, double alpha, double beta,
                    const ColumnElement &element = ColumnElement());
  // The incident wave: particle-velocity component (0 .. dim-1) and its speed (vs for an S
  // wave, vp for a P wave). Without a call the base only absorbs.
  void setInput(int component, bool p_wave);
  // Constant-Q damping per segment, as the main mesh's cells have it (medium/attenuation.hpp):
  // models[e] is the segment's fitted body (no mechanisms: elastic), factor[e] its unrelaxed
  // modulus factor M_U/(rho c^2). Every spring becomes k_U Δu - sum_l zeta_l with
  // d zeta_l/dt = w_l (Y_l k_U Δu - zeta_l), updated exactly (memoryUpdate) once per step.
  // All damped segments share the relaxation frequencies. Call after setup.
  std::string setAttenuation(const std::vector<ConstantQModel> &models, const std::vector<double> &factor);
  // Hysteretic soil per segment: models[e] is the segment's Iwan model on its element moduli
  // (the unrelaxed ones where damped; null: elastic), the same model the main mesh's cells of
  // its region use. The segments of an element share it. Call after setAttenuation, if any.
  std::string setHysteresis(const std::vector<std::shared_ptr<const HystereticSoilModel>> &models);
  bool        hysteretic() const { return !soil_offset_.empty(); }
  // Darendeli segments whose sigma'_0 comes from the geostatic state (geostatic[segment];
  // their model is the curve at reference_stress): each such element's strain scale
  // (darendeliStrainScale) of sigma'_0 = sigma_v K / M at its mid-height, sigma_v = gravity x
  // the weight of the column above, K / M its bulk over P modulus (the laterally confined
  // column: sigma_h = lambda / M sigma_v, the main mesh's geostatic stage beside the side),
  // at least floor. Its points run the model at the strain divided by the scale and return
  // the stress times it, as the main mesh's (medium/hysteresis.hpp). Call after setHysteresis.
  void setGeostaticScales(double gravity, const std::vector<bool> &geostatic, double reference_stress, double floor);
  // The pore pressure of saturated segments (physics/column_pore_pressure.hpp): per segment
  // its Biot numbers (the segment's material must be the drained skeleton), per node the main
  // mesh's fluid conditions at the side. Call after setup and before start.
  std::string setPorePressure(const std::vector<ColumnFluidSegment> &segments, const std::vector<ColumnFluidNode> &nodes, const ColumnFluidRules &rules);
  bool        saturated() const { return pore_.active(); }
  const ColumnPorePressure &pore() const { return pore_; }

  // State at rest at time t0; a_0 from the input velocity v_in(t0).
  void start(double t0, double v_in0);
  // One step of length h; v_in_new = v_in(t + h).
  void step(double h, double v_in_new);

  bool   started() const { return started_; }
  double time() const { return t_; }
  int    dim() const { return dim_; }
  int    nodeCount() const { return (int)z_.size(); }
  int    segmentCount() const { return (int)z_.size() - 1; }
  double height(int node) const { return z_[node]; }
  double displacement(int node, int c) const { return u_[node * dim_ + c]; }
  double velocity(int node, int c) const { return v_[node * dim_ + c]; }
  double acceleration(int node, int c) const { return a_[node * dim_ + c]; }
  const ElasticMaterial &material(int segment) const { return mat_[segment]; }
  // Stress (dim x dim, row-major) of the element holding segment e at node `node` of that
  // element (degree 1: constant over the segment): elastic at u_{n+1}, plus beta times the
  // viscous stress of v_{n+1/2}, less the memory.
  void stress(int segment, int node, double *sigma) const;
  // alpha p of segment e on the face shape function of its node `node` (0 in dry segments):
  // alpha [(1 - theta) p_node + theta p_other], theta = integral of N_a zeta / integral of N_a over
  // the face (zeta: 0 at the node's height, 1 at the segment's other one), i.e. the face
  // integral of alpha p N_a over the lumped weight. The main mesh's cells integrate their
  // alpha p div(dv) exactly, which on a side's node is this face integral of the pressure
  // (linear along the face), not its nodal value: so the total stress a side receives is
  // stress() less this on the diagonal. Degree p > 1: alpha p_node (theta unused), as the main
  // mesh's GLL rule collocates the pressure on the face too.
  double poreStress(int segment, int node, double theta) const;
  // Node whose height is within tol of z, or -1.
  int findNode(double z, double tol) const;
  // A bound on the column's highest angular frequency and its stable step (with the
  // stiffness-proportional damping), for comparison with the main model's. Degree 1:
  // Gershgorin. Degree p: the largest element's omega^2 = 2 k_e/(rho L_e) lambda_max(W^-1 S2)
  // (K = sum K_e <= max_e omega_e^2 M; the reference eigenvalue by Jacobi rotations).
  // Saturated segments add the undrained stiffening coupling_factor times, as the main mesh
  // does (porous::PorePressureCouplingFactor: 1 at degree 1, the split step's c at p > 1).
  double omegaMax(double coupling_factor = 1) const;
  double stableStep(double coupling_factor = 1) const;

  // Full state for checkpoints: t, u, v, a, v_half, memory variables and last spring forces,
  // then (hysteretic columns only) the Iwan states, their last stresses and the lateral memory,
  // then (saturated columns only) the pore pressure's state.
  std::vector<double> state() const;
  bool                setState(const std::vector<double> &s);

private:
  // K x over the elements (skip_soil: the elastic ones only).
  void internalForce(const std::vector<double> &x, std::vector<double> &f, bool skip_soil = false) const;
  // Advances the Iwan states of the hysteretic elements to u_, keeps their stresses and adds
  // the force of those stresses.
  void soilForce(std::vector<double> &f);
  void swapTailAges(std::vector<double> &states, double now) const;
  void nodalDamping(double s, double v_in);                                        // from a_star_ and v_
  // rho c of the base segment for component c: vs horizontal, vp vertical (the undrained vp
  // of a saturated segment).
  double baseImpedance(int c) const;

  int                          dim_ = 2;
  std::vector<double>          z_, mass_;
  std::vector<ElasticMaterial> mat_;
  int                          p_ = 1;             // element degree: p_ segments per element
  ColumnElement                element_;           // reference GLL points, weights and derivative matrix
  std::vector<double>          ref_S2_;            // 2 sum_q w_q D_qa D_qb, (p+1)^2
  double                       ref_lambda_ = 2;    // lambda_max(W^-1 S2)
  std::vector<double>          k_; // per element and component: modulus / L
  double                       alpha_ = 0, beta_ = 0;
  int                          input_component_ = -1;
  bool                         input_p_wave_    = false;
  double                       input_impedance_ = 0; // rho c of the base segment for the input
  std::vector<double>          base_dashpot_;        // per component
  std::vector<double>          u_, v_, a_, v_half_, a_star_, work_;
  std::vector<double>          modulus_factor_;     // per segment: M_U / (rho c^2), 1 if elastic
  std::vector<double>          memory_omega_;       // w_l shared by the damped segments
  std::vector<double>          memory_weight_;      // Y_l per segment ([e * L + l]; 0 if elastic)
  // Per element, component and GLL point q (j = (e * dim + c) * (p+1) + q): the memory
  // variables zeta_[j * L + l] and the last unrelaxed elastic stress spring_old_[j].
  std::vector<double>          zeta_, spring_old_;
  // Hysteretic elements: per element its model (null: elastic) and the offset of its points'
  // states in soil_state_ (-1: elastic); per element and GLL point (j = e * (p+1) + q) the Iwan
  // stress of the last step, soil_stress_[j * (dim+1) + c]: sigma_{c z} for c < dim, then
  // sigma_xx; with constant-Q the memory of sigma_xx, lateral_zeta_[j * L + l], and its last
  // drive lateral_old_[j].
  std::vector<std::shared_ptr<const HystereticSoilModel>> soil_;
  std::vector<long>            soil_offset_;
  std::vector<double>          soil_scale_; // per element: its strain scale (setGeostaticScales), empty: 1
  std::vector<double>          soil_state_, soil_stress_, lateral_zeta_, lateral_old_;
  double                       soil_updates_ = 0; // Iwan updates so far (the kernel's count)
  int    elementCount() const { return segmentCount() / p_; }
  double elementLength(int e) const { return z_[(e + 1) * p_] - z_[e * p_]; }
  // 2 sum_b D_qb x_b at point q of element e, component c: the derivative times the length.
  double scaledGradient(const std::vector<double> &x, int e, int c, int q) const;
  void                         memoryForce(double h, std::vector<double> &f); // updates zeta_, adds its force
  ColumnPorePressure           pore_; // inactive on a dry column
  double                       t_ = 0;
  bool                         started_ = false;
};

} // namespace slipwave::physics

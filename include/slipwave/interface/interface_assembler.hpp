// One soil-structure interface of the mesh, updated explicitly every step with no global
// tangent: gather the displacements of this rank's node pairs (a VecScatter from the global
// displacement), advance each pair with the Mohr-Coulomb law on the jump increment of the
// step, and add the forces +A tau on the soil node and -A tau on the structure node to the
// global force vector (the reverse scatter adds them, wherever the nodes are owned).
// AddForces computes a trial state from the committed one (asking again gives the same
// forces); Commit makes the last trial the committed state once the step is accepted.
#pragma once
#include <petscmat.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "slipwave/interface/interface_options.hpp"
#include "slipwave/meshing/interface_split.hpp"
#include "slipwave/physics/friction_lag.hpp"
#include "slipwave/physics/mohr_coulomb_interface.hpp"

namespace slipwave::interface {

struct InterfaceTotals {
  double stored      = 0; // elastic energy held by the penalty springs [J]
  double dissipated  = 0; // plastic work plus energy lost at openings [J]
  double max_drift   = 0; // largest yield-surface drift returned so far [Pa]
  PetscInt n_stick = 0, n_slip = 0, n_open = 0;
  PetscInt switches  = 0; // times a pair opened or closed (impacts), summed over the pairs and the run
};

class InterfaceAssembler {
public:
  // `mass`: the global lumped mass per dof (its layout gives the pairs' dof indices; its
  // values size the contact dashpots). `contact_damping`: fraction of each pair's critical
  // normal damping, 0 for none (physics/contact_damping.hpp). `lag`: the friction's lag
  // behind the normal traction (physics/friction_lag.hpp; none: slip_length 0).
  PetscErrorCode Setup(MPI_Comm comm, PetscInt dim, const meshing::InterfaceSpec &spec, const meshing::InterfacePairs &pairs, const physics::InterfaceParams &params,
                       double sigma_N0, double contact_damping, const physics::FrictionLag &lag, Vec mass);
  // f += interface forces at displacement u and time t: every pair advanced from its committed
  // state into the trial state. t is the friction lag's clock; NaN where no time passes (a
  // static solve, the geostatic stage: the lag is then at rest, sigma* = sigma_N + p).
  PetscErrorCode AddForces(Vec u, Vec f, PetscReal t);
  // The trial state of the last AddForces becomes the committed state (no-op without one).
  void Commit();
  // Saturated soil side: from now on AddForces reads the pore pressure at the pairs' soil
  // nodes from p (a global vector with one value per node, node i of it being node i of the
  // displacement: porous/pore_pressure.hpp) and applies the law in effective stress.
  PetscErrorCode SetPorePressure(Vec p);
  // The committed state's pore pressure at the pairs (what the next step's law starts from)
  // from p_committed (laid out as SetPorePressure's p): a restart restores it, and gaps that
  // drained after the commit change it. No-op on dry soil.
  PetscErrorCode ReadCommittedPorePressure(Vec p_committed);
  // f += contact damping forces of the pairs closed in the last AddForces' trial, from the
  // velocity v (the half-step velocity that the step's other damping terms use). No-op
  // without contact damping.
  PetscErrorCode AddDampingForces(Vec v, Vec f);
  // Adds the Gershgorin row sums of the penalty springs, 2 * sum_j |k_ij| with
  // k = A (E n n + G (I - n n)), to a global vector laid out like u.
  PetscErrorCode AddStiffnessRowAbsSums(Vec rowabs);
  // Adds the stick springs A [k -k; -k k], k = E n n + G (I - n n), of every pair of this rank
  // to K (global rows; the matrix must accept new nonzeros: the pair couples two nodes that
  // share no cell). Not assembled here.
  PetscErrorCode AddStickStiffness(Mat K) const;
  // Pairs (over all ranks) that no longer answer as a linear stick spring: slipping, open, or
  // on the tension plateau (see physics::interfaceOnLinearStickBranch).
  PetscErrorCode CountOffLinearStick(PetscInt *count) const;
  // The same for the contact dashpots, 2 * sum_j |c n_i n_j| (all pairs, as if closed).
  PetscErrorCode AddDampingRowAbsSums(Vec rowabs);
  double contactDamping() const { return contact_damping_; }
  // Smallest and largest dashpot coefficient c over all pairs [N s/m] (for the report).
  PetscErrorCode DashpotRange(double *c_min, double *c_max) const;
  PetscErrorCode Totals(InterfaceTotals *totals) const;
  // Global soil-node dof indices (x component) of this rank's pairs that are open in the
  // committed state (a saturated soil side drains into the gap: porous/pore_pressure.hpp).
  void openSoilDofs(std::vector<PetscInt> *dofs) const;
  // Measures jumps from the current displacement as zero again (after the geostatic stage the
  // displacements restart from zero); tractions and state are kept.
  void ResetJumpReference() { jump_prev_.assign(jump_prev_.size(), 0.0); }
  // Checkpoints: each owned pair's state and jump reference as stateWidth() doubles.
  int    stateWidth() const { return dim_ == 2 ? 11 : 14; }
  // The time of the committed state (a restart sets it: the friction lag's clock).
  void   setCommittedTime(double t) { committed_time_ = t; }
  void   saveState(std::vector<double> *out) const;
  void   loadState(const double *in);
  double maxDrift() const { return max_drift_; }
  void   setMaxDrift(double drift) { max_drift_ = drift; }
  // Open/closed switches counted on this rank (Totals sums them); a restart gives the run's
  // total to one rank.
  void setSwitches(PetscInt n) { switches_ = n; }
  // Pairs (over all ranks) whose soil and structure nodes are owned by different ranks.
  PetscErrorCode CountCutPairs(Vec u_template, PetscInt *cut) const;
  // Per-pair fields of this rank's pairs for output, each value with its pair id.
  void pairFields(std::vector<double> *values, int *per_pair) const;
  // Their names, in order (saturated soil side: also the pore pressure and sigma_N + p).
  std::vector<std::string> pairFieldNames() const;
  // The displacement of each of this rank's pairs' soil node (dim per pair, in pairs().id
  // order) in the global vector u, for output: the interface grid moves with the soil side.
  PetscErrorCode SoilSideDisplacement(Vec u, std::vector<double> *values) const;
  PetscErrorCode Destroy();

  const meshing::InterfaceSpec  &spec() const { return spec_; }
  const meshing::InterfacePairs &pairs() const { return pairs_; }
  const physics::InterfaceParams &params() const { return params_; }

private:
  // Gathers x at this rank's pairs (dim values per node, soil node then structure node), lets
  // kernel fill the pair forces, and adds them to f wherever the nodes are owned.
  PetscErrorCode applyToPairs(Vec x, Vec f, const std::function<void(const PetscScalar *, PetscScalar *)> &kernel);
  // Adds 2 sum_j |k(p, n, i, j)| to both nodes' rows of every pair (a +k/-k coupling of the
  // pair's nodes; n is the pair's normal).
  PetscErrorCode addPairRowAbsSums(Vec rowabs, const std::function<double(size_t, const double *, PetscInt, PetscInt)> &k);
  MPI_Comm                 comm_ = MPI_COMM_NULL;
  PetscInt                 dim_  = 0;
  meshing::InterfaceSpec      spec_;
  meshing::InterfacePairs     pairs_;
  physics::InterfaceParams params_{};
  std::vector<physics::InterfaceState<2>> states2_;
  std::vector<physics::InterfaceState<3>> states3_;
  std::vector<double> tangent_;   // (dim-1) unit tangents per pair, dim components each
  std::vector<double> jump_prev_; // [u] at the committed state, dim per pair
  // The last AddForces: states, jumps and drift it reached, not yet committed.
  std::vector<physics::InterfaceState<2>> trial_states2_;
  std::vector<physics::InterfaceState<3>> trial_states3_;
  std::vector<double> trial_jump_;
  std::vector<double> pair_pore_, trial_pair_pore_; // saturated soil side: p at each pair, committed and trial
  double              trial_max_drift_ = 0;
  physics::FrictionLag lag_{};
  double              committed_time_ = NAN, trial_time_ = NAN; // of the committed and the trial state [s]
  bool                has_trial_       = false;
  double              contact_damping_ = 0;
  std::vector<double> dashpot_;   // normal dashpot c per pair [N s/m]
  double              max_drift_ = 0;
  // Pairs that opened or closed at a commit: the switching the linear stable-step bound does
  // not cover (problem/stable_step.hpp).
  PetscInt            switches_ = 0;
  VecScatter          scatter_ = nullptr;
  Vec                 pair_u_ = nullptr, pair_f_ = nullptr;
  VecScatter          pore_scatter_ = nullptr; // the soil nodes' pore pressure (saturated soil side), or null
  Vec                 pore_source_ = nullptr, pair_p_ = nullptr;
};

} // namespace slipwave::interface

// The bulk force of hysteretic regions (-material_<r>_model hysteretic): the soil's stress is
// the parallel Iwan model of physics/hysteretic_soil.hpp at every quadrature point of the
// region's elements (degree 1: the Gauss points of its cells), while the bulk operator keeps
// applying the linear small-strain stiffness K (Gmax) everywhere. The difference is a correction force
//   f_relax = sum_q B_q^T (C:eps_q - sigma_q) w_q |det J_q|,     f_internal = K u - f_relax,
// with C the region's element moduli, eps_q = B_q u the strain and sigma_q the Iwan stress at
// the point. K is integrated by the same Gauss rule (fem/element_kernels.hpp), so K u -
// f_relax is exactly the force of the Iwan stress, and a cell of another region costs nothing.
// f_relax is zero (to round-off) while every surface is elastic, and it enters the
// acceleration like the constant-Q memory forces (problem/nodal_acceleration.hpp).
//
// State: per point the kernel's state (hystereticStateSize doubles), kept once, and the strain
// of the last force. The force at (t, u) evaluates the Iwan stresses from the committed states
// without writing them, so the RHS asked twice at one time gives the same force, and keeps the
// strains; HysteresisCommit, once the step is accepted, marks those strains as the states' next
// (pending), and the next force first brings each point's state to its strain in place, in the
// same pass over the point's elements (physics::hystereticSettleEvaluate): each state is read
// once per step and written only where an element yields, not copied into a trial state.
// Readers of the committed state in between (ledger, output, stations, checkpoint) bring a
// copy of a point's state to its strain, the same update, so they see the same bits. The
// kernel's count of updates is the number of these settles (Hysteresis::settles). Off during
// the geostatic stage (the soil starts virgin with the dynamic stage, whose displacement
// starts from zero).
//
// An element none of whose points has had a nonzero strain, with its nodes at rest (u exactly
// 0), is skipped: its states are virgin at a zero strain, where an update changes nothing and
// the relaxation stress is zero. Ahead of a wave that is most of a mesh (docs/performance.md).
//
// Degree p > 1: the points are the elements' GLL nodes with the GLL weights, the quadrature
// of the spectral K (collocated), so K u - f_relax is again exactly the Iwan stress's force.
//
// -material_<r>_stress_points mean evaluates the correction once per cell, from the cell's mean
// strain B_m u (B_m the volume average of the Gauss points' B) with its volume V: the linear
// part stays fully integrated in K, so no hourglass mode appears (only the correction is
// under-integrated), and the tangent stays between K - V B_m^T C B_m = sum_q (B_q - B_m)^T C
// (B_q - B_m) w_q |det J_q| >= 0 and K. Exact for a uniform strain; 4x (8x) fewer updates.
//
// The stable step stays that of the linear soil: the Iwan model's
// tangent shear modulus is sum of the elastic elements' G_i <= Gmax, its bulk modulus K.
#pragma once
#include <petscdm.h>

#include <memory>
#include <utility>
#include <string>
#include <vector>

#include "slipwave/fem/bulk_operator.hpp"
#include "slipwave/medium/materials.hpp"

namespace slipwave::medium {

struct HystereticRegion {
  PetscInt                                            region = -1;
  std::shared_ptr<const physics::HystereticSoilModel> model;
  double                                              lambda = 0, mu = 0; // element moduli: C of the linear operator
  std::vector<PetscInt>                               elements;           // this rank's elements of the region (degree 1: cells)
  std::vector<PetscInt>                               dofs;               // per element: its nodes' local dof offsets
  int                                                 points = 0;         // per element: the Gauss rule's, 1 (mean), or its GLL nodes
  // Per element and point: the weight w |det J|, and at degree 1 dN_a/dx_j (nodes x dim), at
  // degree p > 1 dxi_k/dx_j (dim x dim; the basis gradients come from the GLL derivative
  // matrix along the lines through the node).
  std::vector<double>                                 volume, gradient, jinv;
  // The kernel states, point-major, in two arrays: the headers (read every step, so kept
  // together and streamed) and the plastic strains (read only where an element can yield).
  std::vector<double>                                 header, plastic;
  std::vector<double>                                 strain;             // per point: the strain of the last force
  // Per point, once HysteresisAddRegionForce has asked for the region: the relaxation stress
  // C:eps - sigma of the last force (kStress values), so that the call scatters it again.
  std::vector<double>                                 relaxation;
  // Per element: whether any of its points has had a nonzero strain (else its states are
  // virgin at a zero strain, and a pass over the points skips it while its nodes rest).
  std::vector<unsigned char>                          stirred;
  // Per element, a Darendeli region whose sigma'_0 comes from the geostatic stage: the strain
  // scale s of its sigma'_0 (physics::darendeliStrainScale against the model's 1 atm), empty
  // otherwise. Its points run the model at eps / s, so their stress is s sigma(eps / s) and
  // their state (kept in the checkpoint with s) is the model's at the scaled strains.
  std::vector<double>                                 scale;
};

// sigma'_0 below this is taken at it [Pa]: a free surface's first elements, or tension.
constexpr double kGeostaticStressFloor = 1e3;

struct Hysteresis {
  PetscInt                      dim = 0, nodes = 0, degree = 1; // nodes per element
  std::vector<double>           derivative;      // degree p > 1: the GLL derivative matrix, (p+1)^2
  std::vector<PetscInt>         cell_element;    // per local cell: its element (output)
  std::vector<std::pair<PetscInt, PetscInt>> element_place; // per element: (index in regions, index in its elements), or -1s
  std::vector<HystereticRegion> regions;
  bool                          has_trial = false; // a force since the last commit
  bool                          pending   = false; // committed: the states wait for the strains of the last force
  double                        settles   = 0;     // the states brought to their pending strains so far: the kernel's update count
};

// The Iwan model of a region on its element moduli (fe.lame: the unrelaxed ones in a damped
// region), the one its cells use (and the free-field columns beside them); null if the region
// is not hysteretic.
PetscErrorCode HystereticElementModel(const RegionMaterialInfo &m, std::shared_ptr<const physics::HystereticSoilModel> *model);
// *out is null when no region is hysteretic.
PetscErrorCode HysteresisCreate(const fem::BulkOperator &bulk, const std::vector<RegionMaterialInfo> &materials, Hysteresis **out);
PetscErrorCode HysteresisDestroy(Hysteresis **h);
// f_local += f_relax from the ghosted displacement u_local (this rank's cells; the caller
// assembles), the strains kept for HysteresisCommit.
void HysteresisForce(Hysteresis *h, const PetscScalar *u_local, PetscScalar *f_local);
// f_local += scale f_relax of region `region` alone (a no-op for a region that is not
// hysteretic), from the committed states (evaluated, not updated): at the u of the last
// HysteresisForce, its contribution of that region. For the constant-Q drive of a damped
// hysteretic region that does not cover the mesh (medium/attenuation.hpp), every step: the
// first call evaluates the stresses and marks the region, whose relaxation stresses each
// later HysteresisForce then keeps (kStress doubles per point), so that a call after a force
// (before the commit) scatters them: the same bits, without a second evaluation.
void HysteresisAddRegionForce(Hysteresis *h, PetscInt region, const PetscScalar *u_local, double scale, PetscScalar *f_local);
// After the geostatic stage (u_local: its ghosted displacement; the states still virgin):
// each element of a region with -material_<r>_mean_effective_stress geostatic gets the strain
// scale of its sigma'_0 = -(sigma_xx + sigma_yy + sigma_zz)/3, the volume average over its
// points (at least kGeostaticStressFloor). *report: a line per such region with the range.
PetscErrorCode HysteresisSetGeostaticStress(Hysteresis *h, MPI_Comm comm, const PetscScalar *u_local, const std::vector<RegionMaterialInfo> &materials,
                                            std::vector<std::string> *report);
// The strains of the last HysteresisForce become the committed state (no-op without one).
void HysteresisCommit(Hysteresis *h);
// The strains of the last HysteresisForce are dropped: a later commit keeps the state (a
// force evaluated only to time it, app/run_report.cpp).
void HysteresisDiscardTrial(Hysteresis *h);
// Committed state for checkpoints: this rank's points' states, region by region. The size is fixed by the mesh and the models (a checkpoint of another
// scene is refused before, by the displacement's size).
std::vector<double> HysteresisState(const Hysteresis *h);
PetscInt            HysteresisStateSize(const Hysteresis *h);
void                HysteresisSetState(Hysteresis *h, const std::vector<double> &state);
// Sum over this rank's points of (1/2 eps:C:eps - Iwan stored energy) w |det J| at the
// committed state and the ghosted displacement u_local: what the linear strain energy
// 1/2 u.K u holds beyond the soil's stored energy (energy ledger). It reads every state, so it
// brings them to their pending strains in place first (the next force then has none to bring).
double HysteresisRelaxationEnergy(Hysteresis *h, const PetscScalar *u_local);
// Output, per local cell of a hysteretic region (other cells untouched), at the committed
// state and the ghosted displacement u_local: relaxation (6 per cell: xx, yy, zz, xy, yz, xz)
// the mean over the cell's points of C:eps - sigma, what the linear cell stress holds beyond
// the soil's; max_strain the largest equivalent shear strain any of its points reached;
// modulus_ratio the model's secant G/Gmax at that strain.
void HysteresisCellFields(const Hysteresis *h, const PetscScalar *u_local, double *relaxation, double *max_strain, double *modulus_ratio);
// The relaxation of HysteresisCellFields for local cell `cell` alone (6 values; untouched if
// the cell is not hysteretic), at the cost of its element's points (a station, every step).
void HysteresisCellRelaxation(const Hysteresis *h, const PetscScalar *u_local, PetscInt cell, double *relaxation);
// Run report lines: per hysteretic region its backbone, parameters, surfaces and their fit.
std::vector<std::string> HysteresisReport(const std::vector<RegionMaterialInfo> &materials);

} // namespace slipwave::medium

// The run's main answers, accumulated every step (not from the sampled output) and stated at
// the end of every run with an interface: a table on stdout and run_info.json["answers"]
// (keys as scripts/scene_metrics.py names them, each {"value": x, "unit": "..."}).
// - The interface (-answer_interface, default "base" or the first): with s(t) the mean over
//   its pairs of the tangential jump's x component (structure minus soil), net_slip = s at
//   the end, accumulated_slip = the largest slip path of a pair, largest_slip_excursion = the
//   largest one-way slide of s (numerics/slide_excursion.hpp, gate 5 % of the range),
//   mean_slip_range = max - min of s, peak_uplift = the largest opening of a pair.
// - Rocking: peak_rocking_angle = max |theta| of the rigid body (-answer_rigid_body, default
//   the first rigid region; 2D theta_z, 3D the rotation vector's length), else max
//   |u_v(right) - u_v(left)| / their x distance of the two stations -answer_rocking_stations
//   (default block_base_left,block_base_right). tilt_after_shaking = the same angle, signed
//   (2D: counter-clockwise positive; 3D: the length), its mean over the last 2 s
//   (numerics/tail_window.hpp): the permanent tilt, which a yielding soil accumulates cycle
//   by cycle, once the rocking has settled; rocking_at_end = the angle's half range over the
//   same 2 s, the swing left about it (a note says when it exceeds the tilt: the run ended
//   while the structure still rocked, and its last angle would be a point of the swing).
// - The structure station (-answer_structure_station, default block_top): its 5 %-damped
//   floor spectrum <name>_psa_<T>s at -answer_periods (numerics/response_spectrum.hpp) and
//   peak_structure_acceleration; settlement_gravity = -u_v at the end of the geostatic stage,
//   settlement_after_shaking = -u_v at the end, measured from the state under gravity
//   (downward positive).
// - The free-field station (-answer_free_field_station, default free_field): free_field_pga
//   = max |a_x| and its spectrum.
// - Both stations' peaks also low-passed (numerics/low_pass.hpp) at the frequency the mesh
//   resolves, p vs_min / (8 h) (app::LowPassCornerFrequency; scene_metrics.py's resolved
//   frequency): <station>_peak_acceleration_lowpassed, the peak that converges where the
//   unfiltered one does not (a landing, a yielding soil's corners). Their a_x is kept every
//   step for it (8 bytes a step and station).
// u_v is the vertical displacement (u_y in 2D, u_z in 3D). Accelerations are a_x, unfiltered
// unless said. A station named by option must exist; a default one
// that the run lacks drops its answers (said in the table). Every rank does the same
// arithmetic on values summed over the ranks: the answers do not depend on the partition
// beyond round-off. After a restart the answers are not stated (the state before it is not
// in the checkpoint).
#pragma once
#include <petscsys.h>

#include <memory>
#include <string>
#include <vector>

#include "slipwave/io/stations.hpp"
#include "slipwave/numerics/response_spectrum.hpp"
#include "slipwave/numerics/slide_excursion.hpp"
#include "slipwave/problem/elastodynamics.hpp"

namespace slipwave::app {

// Per interface, each step: its pairs' status counts (for the progress line).
struct InterfaceCounts {
  double stick = 0, slip = 0, open = 0;
};

class RunAnswers {
public:
  PetscErrorCode Setup(const problem::Elastodynamics &model, const io::Stations &stations);
  bool           active() const { return active_; }
  // The geostatic displacement (global): the settlement under gravity.
  PetscErrorCode SetGeostatic(const problem::Elastodynamics &model, io::Stations &stations, Vec u_geo);
  // Every step (collective); motion: problem::RigidBodiesMotion's values (empty without bodies).
  PetscErrorCode Update(const problem::Elastodynamics &model, io::Stations &stations, double t, Vec u, Vec a, const std::vector<double> &motion);
  // The status counts of every interface at the last Update.
  const std::vector<InterfaceCounts> &counts() const { return counts_; }
  // Collective: the table (rank 0 prints) and the JSON object for run_info.json; after a
  // restart (restarted) a line that says why there is none, and json stays empty.
  PetscErrorCode Finish(const problem::Elastodynamics &model, bool restarted, const std::string &output_dir, std::string *json);

private:
  bool                     active_ = false;
  size_t                   interface_ = 0;
  int                      structure_ = -1, free_field_ = -1, rock_left_ = -1, rock_right_ = -1, body_ = -1;
  std::string              structure_name_, free_field_name_, body_name_;
  double                   rock_span_ = 0;
  std::vector<double>      periods_;
  std::unique_ptr<numerics::ResponseSpectrum> structure_spectrum_, free_field_spectrum_;
  numerics::TurningPoints  turning_;
  std::vector<io::Stations::Probe> probes_;
  std::vector<InterfaceCounts>     counts_;
  // Every step: the times, and beside them the records of the low-passed peaks and the tilt's
  // final window.
  std::vector<double> times_, structure_ax_, free_field_ax_, tilts_;
  double              corner_hz_ = 0;
  double net_slip_ = 0, local_uplift_ = 0, rocking_ = 0, tilt_ = 0, structure_peak_ = 0, free_field_peak_ = 0, structure_vertical_ = 0, geostatic_vertical_ = 0;
  bool   geostatic_ = false;
  std::vector<std::string> notes_;
};

} // namespace slipwave::app

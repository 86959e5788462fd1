// Checkpoint and restart: the full state of a run at the end of a step, so that a continued
// run is identical to an uninterrupted one. The file (PETSc binary, written to a temporary
// name and renamed, so a crash never leaves half a checkpoint) holds: time, step and step
// size; u, v, a; the constant loads and initial stresses left by a geostatic stage; the
// committed history: every interface pair's state, the free-field columns, the constant-Q
// memory variables; the energy ledger; the station records and the output times so far. No
// cache of the last right-hand side (its force parts): the next step recomputes them.
// A restart runs on the same number of ranks (pairs and stations are stored per rank).
#pragma once
#include <petscts.h>

#include <string>
#include <vector>

#include "slipwave/io/stations.hpp"
#include "slipwave/problem/elastodynamics.hpp"
#include "slipwave/problem/energy_ledger.hpp"

namespace slipwave::app {

struct CheckpointState {
  problem::Elastodynamics *model       = nullptr;
  TS                     ts          = nullptr;
  problem::EnergyLedger   *ledger      = nullptr;
  io::Stations          *stations    = nullptr;
  std::vector<PetscReal> *frame_times = nullptr; // times of the output frames written so far
  PetscReal             *next_output = nullptr;
};

PetscErrorCode CheckpointWrite(const std::string &path, const CheckpointState &state);
// The folder holding the checkpoint file path ("." for a bare file name): the series a
// restart continues (energy.csv, the frame files) are there.
std::string CheckpointFolder(const std::string &path);
// Collective, before the heavy work: the file is there, whole and undamaged (its seal), or one
// line says what is wrong with it.
PetscErrorCode CheckpointVerify(MPI_Comm comm, const std::string &path);
// Restores everything into an already set-up run (TS solution vectors given), after
// CheckpointVerify; a checkpoint of another scene is refused, naming the options that differ.
PetscErrorCode CheckpointRead(const std::string &path, const CheckpointState &state);

} // namespace slipwave::app

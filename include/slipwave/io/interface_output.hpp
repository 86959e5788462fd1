// An interface as its own XDMF grid, interface_<name>.xmf/h5: lines in 2D, faces in 3D, one
// node per pair (numbered by pair id, so the grid does not depend on the partition), with
// per step: opening w_N, slip (tangential jump vector), sigma_N, sigma_T (vector), plastic
// opening, accumulated slip, status (0 stick, 1 slip, 2 open), dissipation [J/m^2], and the
// soil side's displacement, total (displacement) and less the base's (displacement_relative,
// as the volume output), so that the grid warps with the volume's soil.
#pragma once
#include <petscvec.h>

#include <string>
#include <vector>

#include "slipwave/interface/interface_assembler.hpp"
#include "slipwave/io/field_writer.hpp"

namespace slipwave::io {

class InterfaceOutput {
public:
  // previous: output steps (step, time) already in the file to keep (a restart), or null.
  PetscErrorCode Open(MPI_Comm comm, PetscInt dim, const interface::InterfaceAssembler &iface, const std::string &dir,
                      const std::vector<std::pair<PetscInt, PetscReal>> *previous = nullptr);
  // u: the global displacement; base: the base's displacement (io/base_displacement.hpp).
  PetscErrorCode Write(const interface::InterfaceAssembler &iface, PetscInt step, PetscReal t, Vec u, const PetscScalar *base);
  PetscErrorCode Close();

private:
  PetscErrorCode fill(const interface::InterfaceAssembler &iface, Vec u, const PetscScalar *base);
  FieldWriter      writer_;
  PetscInt         dim_ = 0;
  Vec              geometry_ = nullptr, u_soil_ = nullptr, u_relative_ = nullptr;
  IS               topology_ = nullptr;
  std::vector<Vec> fields_;
  std::vector<int> widths_;
  std::vector<std::string> names_; // of fields_, from InterfaceAssembler::pairFieldNames
};

} // namespace slipwave::io

#include "slipwave/meshing/box_element_frame.hpp"

#include "slipwave/mesh/spectral_layout.hpp"

#include <algorithm>
#include <cmath>

namespace slipwave::meshing {

PetscInt ElementFrame::code() const {
  PetscInt c = 0;
  for (PetscInt a = 0; a < dim; ++a) c |= (2 * axis[a] + (sign[a] < 0)) << (3 * a);
  return c;
}

void ElementFrame::decode(PetscInt c) {
  for (PetscInt a = 0; a < dim; ++a) axis[a] = ((c >> (3 * a)) & 7) / 2, sign[a] = ((c >> (3 * a)) & 1) ? -1 : 1;
}

PetscInt ElementFrame::position(PetscInt p, const PetscInt *q) const {
  PetscInt pos = 0, stride = 1;
  for (PetscInt a = 0; a < dim; stride *= p, ++a) pos += stride * (sign[a] > 0 ? q[axis[a]] : p - 1 - q[axis[a]]);
  return pos;
}

// Frame axis a runs from the frame's corner 0 to its corner 2^a.
PetscErrorCode BoxCellFrame(DM dm, const mesh::VertexCoordinates &coords, PetscInt c, ElementFrame *f) {
  PetscInt  lex[8];
  PetscReal x0[3], x1[3];
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &f->dim));
  PetscCall(mesh::SpectralCellFrame(dm, coords, c, lex));
  PetscCall(coords.Get(lex[0], x0));
  for (PetscInt a = 0; a < f->dim; ++a) {
    PetscCall(coords.Get(lex[1 << a], x1));
    PetscInt along = 0;
    for (PetscInt d = 1; d < f->dim; ++d)
      if (std::fabs(x1[d] - x0[d]) > std::fabs(x1[along] - x0[along])) along = d;
    f->axis[a] = along;
    f->sign[a] = x1[along] > x0[along] ? 1 : -1;
  }
  PetscFunctionReturn(0);
}

PetscReal BoxGllCoordinate(const BoxSpec &box, PetscInt d, PetscInt p, const double *gll, PetscInt i) {
  const PetscInt  e = std::min(i / p, box.faces[d] - 1);
  const PetscReal h = (box.upper[d] - box.lower[d]) / box.faces[d];
  return box.lower[d] + h * ((PetscReal)e + 0.5 * (1 + gll[i - e * p]));
}

} // namespace slipwave::meshing

// The Domain Reduction Method on a saturated site: the u-p operator's share of the layer
// forces (docs/drm.md, "Saturated sites"). With the total field (u, p) inside Omega and the
// scattered one outside, the effective forces are the layer elements' full coupled operator
// applied to the free field (u0, p0) restricted to their e nodes (rows of their b nodes, with
// a minus sign) or to their b nodes (rows of their e nodes), as Bielak et al. (2003) do for K.
// input/drm.cpp gives the skeleton's K part; here, per saturated layer element with its alpha
// Q and kappa H (the matrices PorePressureTrial uses):
//   momentum:  P_b += +(alpha Q^T)_be p0_e,   P_e += -(alpha Q^T)_eb p0_b       (force alpha Q^T p)
//   pressure:  a volume source per step, S (p_{n+1} - p*) = ... + W_{n+1/2},
//              W_{n+1/2} = -(G(t_{n+1}) - G(t_n)) + h r(t_n), with
//              G_b = +(alpha Q)_be u0_e, G_e = -(alpha Q)_eb u0_b        (the storage update's alpha Q du)
//              r_b = -(H p0_e)_b,       r_e = +(H p0_b)_e               (its Darcy term h H p_n)
// p0 is the undrained free field's, so the Darcy terms are exact only as kappa -> 0: what a
// permeable site's flow would add to the free field is the drainage mismatch docs/drm.md measures.
#pragma once
#include <petscdm.h>

#include "slipwave/fem/bulk_operator.hpp"
#include "slipwave/input/drm.hpp"
#include "slipwave/porous/pore_pressure.hpp"

namespace slipwave::porous {

// The layer's saturated elements (degree 1: a bulk element is a cell) and the state vectors,
// zero: the free field is at rest before t = 0.
PetscErrorCode PorePressureDrmCreate(PorePressure *pore, const input::Drm *drm, const fem::BulkOperator &bulk);
// The trial's G and r at the free field's time t (input::DrmFreeFieldUpdate first) and the
// volume source W of the step from the committed time to t (drm_source), which
// PorePressureTrial adds and the energy ledger books.
PetscErrorCode PorePressureDrmSource(PorePressure *pore, const input::Drm *drm);
// f += the coupling's layer forces at the free field's time (global, displacement layout).
PetscErrorCode PorePressureDrmForce(PorePressure *pore, const input::Drm *drm, DM dm, Vec f);

} // namespace slipwave::porous

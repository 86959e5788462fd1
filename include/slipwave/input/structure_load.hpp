// Forced vibration of a structure: a resultant force and moment on one region, times a
// factor history (harmonic for impedance at one frequency, a Ricker for a broad band):
//   -structure_load_region <r>          the loaded region (a structure or its foundation)
//   -structure_load_force fx,fy[,fz]    resultant force [N; N/m in 2D]
//   -structure_load_moment M | mx,my,mz resultant moment about the region's node centroid
//                                       [N m/m in 2D (about z); N m in 3D]
//   -structure_load_stf ...             factor history (TimeFunction, HistoryRole::Load;
//                                       none: constant)
// Spread over the region's nodes (each node once, whatever the partition) as the nodal
// forces of a rigid-body motion: the force evenly, f_i = F/N, and the moment linearly in the
// position r_i from the centroid, f_i = theta x r_i with theta = I^-1 M and
// I = sum_i (|r_i|^2 1 - r_i r_i^T) (2D: f_i = M (-r_y, r_x) / sum_i |r_i|^2). The nodal
// forces sum to F exactly and their moment about the centroid is M exactly.
#pragma once
#include <petscdmplex.h>

#include <string>
#include <vector>

#include "slipwave/fem/bulk_operator.hpp"
#include "slipwave/input/boundary_conditions.hpp"

namespace slipwave::input {

PetscErrorCode StructureLoadCreate(DM dm, const fem::BulkOperator &bulk, const std::vector<std::string> &regions, BoundaryConditions *bc);

} // namespace slipwave::input

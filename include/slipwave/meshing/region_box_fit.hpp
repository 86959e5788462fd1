// A box region (-region_<r>_box) takes the cells of the box mesh whose centroid lies inside its
// box, so the region the run computes is a union of whole cells: each face of the box moves to
// a grid line. Where a face lies between grid lines the geometry changes without a word (the
// default scene's 6 m block on -mesh_box_faces 60,30 is 4.07 m wide), so the caller refuses a
// box whose faces inside the mesh miss a grid line by more than kRegionBoxFitTolerance of a
// cell. Faces on or beyond the mesh's sides cut no cell and always fit.
#pragma once
#include <vector>

#include "slipwave/meshing/mesh_options.hpp"

namespace slipwave::meshing {

inline constexpr double kRegionBoxFitTolerance = 0.01; // of the cell size along the axis

struct RegionBoxFit {
  std::vector<double> meshed;      // xmin,xmax,ymin,ymax[,zmin,zmax] of the cells it takes
  bool                empty = false; // no centroid inside (reported by the labelling)
  bool                fits  = true;  // every face inside the mesh within the tolerance of the meshed one
};

// `region_box` holds 2 dim bounds; the mesh is `box` (faces, lower, upper).
RegionBoxFit RegionBoxOnMesh(int dim, const BoxSpec &box, const std::vector<double> &region_box);

} // namespace slipwave::meshing

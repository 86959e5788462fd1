// Region boxes on a box mesh (region_box_fit.hpp). Expected boxes by hand from the rule "a
// cell joins the region when its centroid lower + (k + 1/2) h lies inside the box":
//  1. The default scene's mesh, x in [-61, 61]: 122 cells (h = 1 m) take the 6 m block
//     [-3, 3] exactly (faces on the lines -61 + 58 and -61 + 64); 61 cells (h = 2 m) too
//     (-61 + 2*29, -61 + 2*32).
//  2. 60 cells (h = 122/60 m): centroids -61 + (k + 1/2) 122/60 inside [-3, 3] for k = 29, 30
//     only (k = 28: -3.05; k = 31: 3.05), so the block is [-61 + 29 h, -61 + 31 h] =
//     [-2.0333, 2.0333]: refused.
//  3. Faces on or beyond the mesh's sides fit whatever the cell size: [-100, 100] on [-61, 61]
//     gives the whole mesh.
//  4. Tolerance: a face 0.5 % of a cell off a grid line fits, 2 % off does not.
//  5. A box holding no centroid is reported empty (the labelling names it), not refused here.
//  6. 3D: the z axis is checked like the others (z in [-12, 10], 11 cells of 2 m: 4 fits, 5 does not).
#include "slipwave/meshing/region_box_fit.hpp"

#include "unit_check.hpp"

using slipwave::meshing::BoxSpec;
using slipwave::meshing::RegionBoxOnMesh;

static BoxSpec box2d(int nx, int ny) {
  BoxSpec b;
  b.faces[0] = nx, b.faces[1] = ny;
  b.lower[0] = -61, b.lower[1] = -20, b.upper[0] = 61, b.upper[1] = 40;
  return b;
}

int main() {
  const std::vector<double> block = {-3, 3, 30, 40};
  auto fine = RegionBoxOnMesh(2, box2d(122, 60), block);
  unit::check(fine.fits && !fine.empty, "the 6 m block fits 122 x 60 cells");
  unit::near(fine.meshed[0], -3, 0, 1e-12, "122 x 60: meshed xmin");
  unit::near(fine.meshed[1], 3, 0, 1e-12, "122 x 60: meshed xmax");
  auto coarse = RegionBoxOnMesh(2, box2d(61, 30), block);
  unit::check(coarse.fits, "the 6 m block fits 61 x 30 cells (h = 2 m)");
  unit::near(coarse.meshed[2], 30, 0, 1e-12, "61 x 30: meshed ymin");
  unit::near(coarse.meshed[3], 40, 0, 1e-12, "61 x 30: meshed ymax (the mesh's top)");
  auto odd = RegionBoxOnMesh(2, box2d(60, 30), block);
  const double h = 122.0 / 60;
  unit::check(!odd.fits && !odd.empty, "the 6 m block does not fit 60 x 30 cells");
  unit::near(odd.meshed[0], -61 + 29 * h, 0, 1e-12, "60 x 30: meshed xmin = -61 + 29 h");
  unit::near(odd.meshed[1], -61 + 31 * h, 0, 1e-12, "60 x 30: meshed xmax = -61 + 31 h");
  auto wide = RegionBoxOnMesh(2, box2d(60, 30), {-100, 100, 30, 40});
  unit::check(wide.fits, "faces beyond the mesh's sides fit");
  unit::near(wide.meshed[0], -61, 0, 1e-12, "beyond the sides: meshed xmin = the mesh's");
  unit::near(wide.meshed[1], 61, 0, 1e-12, "beyond the sides: meshed xmax = the mesh's");
  unit::check(RegionBoxOnMesh(2, box2d(122, 60), {-3.005, 3, 30, 40}).fits, "a face 0.5 % of a cell off a line fits");
  unit::check(!RegionBoxOnMesh(2, box2d(122, 60), {-3.02, 3, 30, 40}).fits, "a face 2 % of a cell off a line does not");
  auto outside = RegionBoxOnMesh(2, box2d(122, 60), {-3, 3, 50, 60});
  unit::check(outside.empty && outside.fits, "a box above the mesh is empty, not refused here");
  BoxSpec b3;
  b3.faces[0] = 12, b3.faces[1] = 12, b3.faces[2] = 11;
  b3.lower[0] = b3.lower[1] = b3.lower[2] = -12, b3.upper[0] = b3.upper[1] = 12, b3.upper[2] = 10;
  unit::check(RegionBoxOnMesh(3, b3, {-2, 2, -2, 2, 4, 10}).fits, "3D: the foundation block fits 12 x 12 x 11");
  unit::check(!RegionBoxOnMesh(3, b3, {-2, 2, -2, 2, 5, 10}).fits, "3D: zmin = 5 (between the lines 4 and 6) does not fit");
  return unit::failures();
}

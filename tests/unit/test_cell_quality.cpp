// Cell shape measures against hand-computed values: regular cells have aspect 1 and corner
// Jacobian ratio 1; an r:1 rectangle or r:1:1 box has aspect r; a trapezoid's corner
// Jacobians are the cross products of its edges; a bow-tie folds (ratio -1); collapsed
// cells are degenerate; reversing the node order changes nothing.
#include "slipwave/mesh/cell_quality.hpp"

#include "unit_check.hpp"

#include <cmath>
#include <vector>

using namespace slipwave::numerics;
using namespace slipwave::mesh;

namespace {

CellShapeQuality q(CellShape s, const std::vector<double> &x) { return cellShapeQuality(s, x.data()); }

bool is(CellShape s, const std::vector<double> &x, CellDefect want) { return cellDefect(q(s, x), 50, 0.1) == want; }

} // namespace

int main() {
  const std::vector<double> square = {0, 0, 2, 0, 2, 2, 0, 2};
  unit::near(q(CellShape::Quad4, square).aspect, 1, 1e-14, 0, "square: aspect 1");
  unit::near(q(CellShape::Quad4, square).jacobian_ratio, 1, 1e-14, 0, "square: Jacobian ratio 1");
  unit::check(is(CellShape::Quad4, square, CellDefect::None), "square: no defect");
  const std::vector<double> clockwise = {0, 0, 0, 2, 2, 2, 2, 0};
  unit::near(q(CellShape::Quad4, clockwise).jacobian_ratio, 1, 1e-14, 0, "square, clockwise nodes: Jacobian ratio 1");
  // 10 x 1 rectangle: longest edge 10, area 10 -> aspect 10^2 / 10 = 10.
  const std::vector<double> rectangle = {0, 0, 10, 0, 10, 1, 0, 1};
  unit::near(q(CellShape::Quad4, rectangle).aspect, 10, 1e-14, 0, "10:1 rectangle: aspect 10");
  // 100 x 1: aspect 100 > 50: distorted, not inverted.
  unit::check(is(CellShape::Quad4, {0, 0, 100, 0, 100, 1, 0, 1}, CellDefect::Distorted), "100:1 rectangle: distorted");
  // Trapezoid (0,0) (4,0) (3,1) (1,1): corner Jacobians (edge cross products) 4, 4, 2, 2 -> ratio 0.5.
  unit::near(q(CellShape::Quad4, {0, 0, 4, 0, 3, 1, 1, 1}).jacobian_ratio, 0.5, 1e-14, 0, "trapezoid: corner Jacobian ratio 2/4");
  // Nearly a triangle: top edge 0.02 long, corner Jacobians 4, 4, 0.02*1... ratio (2*0.01)/4 = 0.005 < 0.1.
  unit::check(is(CellShape::Quad4, {0, 0, 4, 0, 2.01, 1, 1.99, 1}, CellDefect::Distorted), "near-triangle quadrilateral: distorted");
  // Bow-tie: nodes 2 and 3 swapped; the corner Jacobians are +1, -1, ... -> ratio -1.
  const std::vector<double> bowtie = {0, 0, 1, 0, 0, 1, 1, 1};
  unit::near(q(CellShape::Quad4, bowtie).jacobian_ratio, -1, 1e-14, 0, "bow-tie: corner Jacobian ratio -1");
  unit::check(is(CellShape::Quad4, bowtie, CellDefect::Inverted), "bow-tie: inverted");
  // A non-convex (arrow) quadrilateral: node 2 pulled inside, its corner Jacobian negative.
  unit::check(is(CellShape::Quad4, {0, 0, 2, 0, 0.5, 0.5, 0, 2}, CellDefect::Inverted), "arrow (non-convex): inverted");
  unit::check(is(CellShape::Quad4, {0, 0, 1, 0, 1, 0, 0, 0}, CellDefect::Degenerate), "quadrilateral of zero area: degenerate");

  // Equilateral triangle: aspect 1; right isosceles: h^2 (sqrt 3 / 4) / A = 2 (sqrt 3 / 4) / (1/2) = sqrt 3.
  unit::near(q(CellShape::Tri3, {0, 0, 1, 0, 0.5, std::sqrt(3.0) / 2}).aspect, 1, 1e-14, 0, "equilateral triangle: aspect 1");
  unit::near(q(CellShape::Tri3, {0, 0, 1, 0, 0, 1}).aspect, std::sqrt(3.0), 1e-14, 0, "right isosceles triangle: aspect sqrt(3)");
  unit::near(q(CellShape::Tri3, {0, 0, 0, 1, 1, 0}).jacobian_ratio, 1, 1e-14, 0, "clockwise triangle: ratio 1 (either orientation is allowed)");
  unit::check(is(CellShape::Tri3, {0, 0, 1, 0, 2, 0}, CellDefect::Degenerate), "collinear triangle: degenerate");
  // Sliver: base 1, height 0.001 -> aspect sqrt(3)/4 / 0.0005 = 866.
  unit::near(q(CellShape::Tri3, {0, 0, 1, 0, 0.5, 0.001}).aspect, std::sqrt(3.0) / 4 / 0.0005, 1e-9, 0, "sliver triangle: aspect 866");

  // Regular tetrahedron (alternate cube corners): aspect 1.
  unit::near(q(CellShape::Tet4, {0, 0, 0, 1, 1, 0, 1, 0, 1, 0, 1, 1}).aspect, 1, 1e-14, 0, "regular tetrahedron: aspect 1");
  unit::check(is(CellShape::Tet4, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, CellDefect::Degenerate), "flat tetrahedron: degenerate");

  const std::vector<double> cube = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  unit::near(q(CellShape::Hex8, cube).aspect, 1, 1e-14, 0, "cube: aspect 1");
  unit::near(q(CellShape::Hex8, cube).jacobian_ratio, 1, 1e-14, 0, "cube: Jacobian ratio 1");
  // 4 x 1 x 1 box: longest edge 4, volume 4 -> (4^3 / 4)^(1/2) = 4.
  unit::near(q(CellShape::Hex8, {0, 0, 0, 4, 0, 0, 4, 1, 0, 0, 1, 0, 0, 0, 1, 4, 0, 1, 4, 1, 1, 0, 1, 1}).aspect, 4, 1e-14, 0, "4:1:1 box: aspect 4");
  // Top face upside down (nodes 4-7 mirrored through the bottom): the map folds.
  std::vector<double> folded = cube;
  folded[3 * 6 + 2] = -1;
  unit::check(is(CellShape::Hex8, folded, CellDefect::Inverted), "hexahedron with a node pushed through the opposite face: inverted");
  return unit::failures();
}

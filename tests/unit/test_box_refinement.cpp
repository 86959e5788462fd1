// BoxRefinementLevels: how many times a box is refined when built distributed. Expected
// levels follow from the rule in box_refinement.hpp by hand: the largest k with 2^k dividing
// every face count, every region bound inside the box on a coarse grid line, and enough coarse
// cells (1000 per rank for auto, 1 per rank for distributed).
#include "slipwave/mesh/box_refinement.hpp"

#include "unit_check.hpp"

#include <string>
#include <vector>

using namespace slipwave::mesh;

namespace {

BoxSpec box3(PetscInt n, PetscReal length) {
  BoxSpec b;
  for (int d = 0; d < 3; ++d) b.faces[d] = n, b.lower[d] = 0, b.upper[d] = length;
  return b;
}

void expect(PetscInt got, PetscInt want, const std::string &what) { unit::check(got == want, what + ": " + std::to_string(got) + " levels, want " + std::to_string(want)); }

} // namespace

int main() {
  const std::vector<std::vector<PetscReal>> none;
  // 128^3 on 16 ranks: 32^3 = 32768 >= 16000 coarse cells, 16^3 = 4096 < 16000: 2 levels.
  expect(BoxRefinementLevels(3, box3(128, 128), none, 16, kMeshBuildAuto), 2, "128^3, 16 ranks, auto");
  // 64^3 on 2 ranks: 16^3 = 4096 >= 2000, 8^3 = 512 < 2000: 2 levels.
  expect(BoxRefinementLevels(3, box3(64, 64), none, 2, kMeshBuildAuto), 2, "64^3, 2 ranks, auto");
  // distributed asks only one coarse cell per rank: 64 = 2^6, 1 cell at k = 6 < 2 ranks: 5.
  expect(BoxRefinementLevels(3, box3(64, 64), none, 2, kMeshBuildDistributed), 5, "64^3, 2 ranks, distributed");
  expect(BoxRefinementLevels(3, box3(64, 64), none, 2, kMeshBuildSerial), 0, "serial never refines");
  // A small box stays serial under auto: 40 x 20 has 800 cells < 1000.
  BoxSpec small;
  small.faces[0] = 40, small.faces[1] = 20, small.upper[0] = 100, small.upper[1] = 50;
  expect(BoxRefinementLevels(2, small, none, 1, kMeshBuildAuto), 0, "40 x 20, auto");
  // An odd face count allows no refinement.
  BoxSpec odd   = box3(64, 64);
  odd.faces[2] = 63;
  expect(BoxRefinementLevels(3, odd, none, 1, kMeshBuildDistributed), 0, "63 cells on z");
  // Region bounds: on the 1 m grid of 64^3 over 64 m, a bound at 24 m lies on the grid of
  // 8 m (k = 3) but not of 16 m (k = 4); bounds at 0 and 64 m (the sides) and beyond cut no cell.
  const std::vector<std::vector<PetscReal>> at24 = {{0, 64, -5, 70, 24, 64}};
  expect(BoxRefinementLevels(3, box3(64, 64), at24, 1, kMeshBuildDistributed), 3, "bound at 24 m");
  // A bound at 24.5 m lies between fine grid lines: no coarse grid holds it.
  const std::vector<std::vector<PetscReal>> at245 = {{0, 64, 0, 64, 24.5, 64}};
  expect(BoxRefinementLevels(3, box3(64, 64), at245, 1, kMeshBuildDistributed), 0, "bound at 24.5 m");
  // A region without a box (the fill region) bounds nothing.
  const std::vector<std::vector<PetscReal>> fill = {{}, {0, 64, 0, 64, 32, 64}};
  expect(BoxRefinementLevels(3, box3(64, 64), fill, 1, kMeshBuildDistributed), 5, "fill region and a bound at 32 m");
  return unit::failures();
}

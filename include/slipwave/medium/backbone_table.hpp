// A user's modulus-reduction table for a hysteretic region (-material_<r>_backbone table,
// -material_<r>_backbone_file): a CSV file of G/Gmax against the engineering shear strain, read
// whole and checked before the mesh work, so that a bad file stops the run in one line naming
// it and the line.
//
// Format (docs/hysteretic-soil.md, "Table backbone"):
//   # source: Vucetic & Dobry (1991), Fig. 5, PI = 15      <- required: where the curve is from
//   strain_percent,G/Gmax                                 <- required header: strain's unit
//   0.0001,1.0
//   0.001,0.98
//   ...
// Lines starting with '#' are comments; the first "# source:" line is the table's source. The
// header's first column names the strain's unit, `strain` (a ratio) or `strain_percent` (as
// most published curves are drawn), the second `G/Gmax` (or `modulus_ratio`): a table whose
// strains are in percent but read as ratios would be 100 times too stiff, so the unit is never
// guessed. The rows' values go to physics::tableBackbone, which checks their order and range.
#pragma once
#include <string>
#include <vector>

namespace slipwave::medium {

struct BackboneTable {
  std::vector<double> strain; // engineering shear strain, a ratio (converted from percent)
  std::vector<double> ratio;  // G/Gmax
  std::string         source; // the text after "# source:"
};

// Reads `path` into *table. Returns "" or a sentence naming the file, the line and what is
// wrong (without the option's name: the caller adds it).
std::string ReadBackboneTable(const std::string &path, BackboneTable *table);

} // namespace slipwave::medium

// Suggestions for a misspelled option (nearest_name.hpp). Distances by hand: one deleted,
// inserted or substituted character, or two neighbours swapped, cost 1 ("-ts_monitr" ->
// "-ts_monitor": 1 insertion; "-ts_mointor": 1 swap, where plain Levenshtein counts 2).
#include "slipwave/core/nearest_name.hpp"

#include "unit_check.hpp"

using namespace slipwave::core;

int main() {
  unit::check(EditDistance("-ts_monitr", "-ts_monitor") == 1, "one insertion: distance 1");
  unit::check(EditDistance("-ts_mointor", "-ts_monitor") == 1, "one swap of neighbours: distance 1");
  unit::check(EditDistance("-material_soil_rhoo", "-material_soil_rho") == 1, "one deletion: distance 1");
  unit::check(EditDistance("abc", "xyz") == 3, "three substitutions: distance 3");
  unit::check(EditDistance("", "abc") == 3 && EditDistance("abc", "abc") == 0, "empty and equal strings");
  const std::vector<std::string> known = {"-ts_max_time", "-ts_monitor", "-ts_dt", "-output_dir", "-bc_bottom_type", "-bc_top_type"};
  unit::check(NearestName("-ts_monitr", known) == "-ts_monitor", "-ts_monitr: -ts_monitor");
  unit::check(NearestName("-bc_botom_type", known) == "-bc_bottom_type", "-bc_botom_type: -bc_bottom_type");
  unit::check(NearestName("-output_dri", known) == "-output_dir", "-output_dri (a swap): -output_dir");
  unit::check(NearestName("-zzz", known).empty(), "-zzz: nothing near (no suggestion)");
  unit::check(NearestName("-ts_d", {"-ts_dt", "-ts_max_time"}) == "-ts_dt", "short name, 1 edit: suggested");
  unit::check(NearestName("-ab", {"-xy"}).empty(), "a 3-character name with 2 edits: not suggested (at most a third of the length)");
  unit::check(NearestName("-ts_monitor", known).empty(), "a known name itself is not suggested");
  return unit::failures();
}

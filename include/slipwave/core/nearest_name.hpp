// The known name nearest to a misspelled one ("-ts_monitr": "-ts_monitor"), by the optimal
// string alignment distance (Damerau-Levenshtein without repeated edits of one substring:
// insertions, deletions, substitutions and swaps of two neighbours cost 1 each).
#pragma once
#include <string>
#include <vector>

namespace slipwave::core {

size_t EditDistance(const std::string &a, const std::string &b);

// The candidate at the smallest distance if it is close enough to be a typo (at most 2 edits,
// and at most a third of the name's length), else "". Ties: the first candidate.
std::string NearestName(const std::string &name, const std::vector<std::string> &candidates);

} // namespace slipwave::core

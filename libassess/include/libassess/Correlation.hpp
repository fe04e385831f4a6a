#pragma once
// How a protection index goes with a stand's dendrometry (the paper's Fig. 12 and Sect. 3.3): Pearson's
// correlation, and the ranks that order the stands (Fig. 11: rank 1 is the least effective forest).
#include <vector>

namespace sylva::assess {

// Pearson's product-moment correlation of paired samples; NaN when it is undefined (fewer than two
// pairs, or a sample without spread). Throws std::invalid_argument if the sizes differ.
double pearson(const std::vector<double>& x, const std::vector<double>& y);

// Rank of each value in ascending order, 1 for the smallest. Equal values share the lowest of their
// ranks (1, 2, 2, 4), so that a tie never orders two stands the data cannot tell apart.
std::vector<int> ascendingRanks(const std::vector<double>& values);

}  // namespace sylva::assess

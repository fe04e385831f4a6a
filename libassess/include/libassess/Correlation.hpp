#pragma once
// How a protection index goes with a stand's dendrometry (the paper's Fig. 12 and Sect. 3.3): Pearson's
// correlation, and the ranks that order the stands (Fig. 11: rank 1 is the least effective forest).
#include <cstddef>
#include <vector>

namespace sylva::assess {

// Pearson's product-moment correlation of paired samples; NaN when it is undefined (fewer than two
// pairs, or a sample without spread). Throws std::invalid_argument if the sizes differ.
double pearson(const std::vector<double>& x, const std::vector<double>& y);

// Two-sided p-value of Pearson's r over n pairs against no correlation: t = r sqrt((n-2)/(1-r^2)) with
// n - 2 degrees of freedom (Student's t test of a correlation, e.g. Sokal & Rohlf, Biometry, Sect. 15.5).
// NaN when r is NaN or n < 3. The paper calls a trend significant at p < 0.05 (Sect. 3.3).
double pearsonPValue(double r, std::size_t n);

// Rank of each value in ascending order, 1 for the smallest. Equal values share the lowest of their
// ranks (1, 2, 2, 4), so that a tie never orders two stands the data cannot tell apart.
std::vector<int> ascendingRanks(const std::vector<double>& values);

}  // namespace sylva::assess

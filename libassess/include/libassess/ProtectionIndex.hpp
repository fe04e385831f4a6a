#pragma once
// The protection index of a forest (paper Sect. 2.3.3).
#include <vector>

namespace sylva::assess {

// PF50 = 1 - Dist50(with forest) / Dist50(without forest), Dist50 the median run-out (Eq. 26).
double protectionIndex(double dist50WithForest, double dist50WithoutForest);
// The same from the two samples of run-out distances.
double protectionIndex(const std::vector<double>& runoutWithForest, const std::vector<double>& runoutWithoutForest);

}  // namespace sylva::assess

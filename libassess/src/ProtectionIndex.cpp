#include "libassess/ProtectionIndex.hpp"

#include <stdexcept>

#include "libdem/CampaignSummary.hpp"

namespace sylva::assess {

double protectionIndex(double dist50WithForest, double dist50WithoutForest) {
    if (!(dist50WithoutForest > 0)) throw std::invalid_argument("Dist50 without forest must be positive");
    return 1.0 - dist50WithForest / dist50WithoutForest;  // Eq. 26
}

double protectionIndex(const std::vector<double>& runoutWithForest, const std::vector<double>& runoutWithoutForest) {
    return protectionIndex(dem::quantile(runoutWithForest, 0.5), dem::quantile(runoutWithoutForest, 0.5));
}

}  // namespace sylva::assess

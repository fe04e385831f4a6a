#include "libdem/StepHold.hpp"

#include <algorithm>

namespace sylva::dem {

double StepHold::next(double bound) {
    if (bound <= current_) {
        current_ = bound;
        waited_ = 0;
        return current_;
    }
    lowestWhileWaiting_ = waited_ == 0 ? bound : std::min(lowestWhileWaiting_, bound);
    if (++waited_ >= kRiseAfter) {
        current_ = lowestWhileWaiting_;
        waited_ = 0;
    }
    return current_;
}

}  // namespace sylva::dem

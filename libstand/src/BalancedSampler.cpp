#include "BalancedSampler.hpp"

#include <gsl/gsl_randist.h>

#include <numeric>
#include <stdexcept>

namespace sylva::stand {

BalancedSampler::BalancedSampler(std::size_t poolSize, gsl_rng* rng) : order_(poolSize), position_(poolSize), rng_(rng) {
    if (poolSize == 0) throw std::logic_error("BalancedSampler: empty pool");
    std::iota(order_.begin(), order_.end(), std::size_t{0});
}

std::size_t BalancedSampler::next() {
    if (position_ == order_.size()) {
        gsl_ran_shuffle(rng_, order_.data(), order_.size(), sizeof(std::size_t));
        position_ = 0;
    }
    return order_[position_++];
}

}  // namespace sylva::stand

#pragma once
// Resampling from a finite pool "by whole copies": every index of the pool is drawn once in each
// run of n consecutive draws, in a fresh random order per run (sampling without replacement from
// the pool repeated as often as needed). Drawing k*n items reproduces the pool's distribution
// exactly; only the last, partial run is a random subset. This keeps a virtual forest's diameter
// mean and sd at the inventory's instead of carrying the noise of drawing with replacement.
#include <gsl/gsl_rng.h>

#include <cstddef>
#include <vector>

namespace sylva::stand {

class BalancedSampler {
public:
    // rng must outlive the sampler; poolSize must be positive.
    BalancedSampler(std::size_t poolSize, gsl_rng* rng);
    std::size_t next();

private:
    std::vector<std::size_t> order_;
    std::size_t position_;
    gsl_rng* rng_;
};

}  // namespace sylva::stand

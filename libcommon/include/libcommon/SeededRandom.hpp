#pragma once
// The one random stream of sylvarock: GSL's Mersenne twister (mt19937), seeded with 32 bits so a seed
// means the same on every platform. Every draw that a result depends on (forest generation, the soil
// bed, a run's release, the lumped model's rebounds, bootstrap resampling, CSR envelopes) comes from
// one of these, seeded from the user's seed alone, so results do not depend on threads or ranks.
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include <cstdint>

namespace sylva {

class SeededRandom {
public:
    explicit SeededRandom(std::uint64_t seed) : r_(gsl_rng_alloc(gsl_rng_mt19937)) {
        gsl_rng_set(r_, static_cast<unsigned long>(seed));
    }
    ~SeededRandom() { gsl_rng_free(r_); }
    SeededRandom(const SeededRandom&) = delete;
    SeededRandom& operator=(const SeededRandom&) = delete;
    double uniform() { return gsl_rng_uniform(r_); }  // [0, 1)
    double uniform(double a, double b) { return a + (b - a) * gsl_rng_uniform(r_); }
    double gaussian(double sd) { return gsl_ran_gaussian_ziggurat(r_, sd); }
    gsl_rng* gsl() { return r_; }  // for GSL's other distributions and samplers

private:
    gsl_rng* r_;
};

}  // namespace sylva

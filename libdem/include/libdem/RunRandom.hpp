#pragma once
// A run's own random stream (GSL's Mersenne twister), seeded from the run's seed alone so that a run
// draws the same numbers whichever thread runs it.
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include <cstdint>

namespace sylva::dem {

class RunRandom {
public:
    explicit RunRandom(std::uint64_t seed) : r_(gsl_rng_alloc(gsl_rng_mt19937)) {
        gsl_rng_set(r_, static_cast<unsigned long>(seed));
    }
    ~RunRandom() { gsl_rng_free(r_); }
    RunRandom(const RunRandom&) = delete;
    RunRandom& operator=(const RunRandom&) = delete;
    double uniform(double a, double b) { return a + (b - a) * gsl_rng_uniform(r_); }
    double gaussian(double sd) { return gsl_ran_gaussian_ziggurat(r_, sd); }

private:
    gsl_rng* r_;
};

}  // namespace sylva::dem

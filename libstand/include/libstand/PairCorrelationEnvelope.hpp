#pragma once
// Is a stand's g(r) that of complete spatial randomness (CSR)? The pointwise envelope of g(r) over
// patterns simulated under CSR with each plot's own number of stems in its own window, estimated and
// pooled exactly as the data are: spatstat's envelope(X, pcf, nsim = 39, fix.n = TRUE) (Baddeley,
// Rubak & Turner 2015, Sect. 10.7). Where the data's g leaves [low, high] at a given r, CSR is
// rejected at that r at the level 2 / (simulations + 1) (5 % for 39): a pointwise test, not a global
// one, so a few excursions over a long r range are expected even under CSR.
#include <cstdint>
#include <vector>

#include "libstand/PairCorrelation.hpp"

namespace sylva::stand {

struct PairCorrelationEnvelope {
    std::vector<double> r;
    std::vector<double> transLow, transHigh;  // pointwise min and max of the simulated estimates
    std::vector<double> isoLow, isoHigh;
    int simulations = 0;
    double level() const { return 2.0 / (simulations + 1); }  // pointwise significance
};

// Throws InputError if `simulations` < 1 or a plot is given no stems to simulate; the seed fixes the
// patterns (GSL mt19937), so the same call gives the same envelope.
PairCorrelationEnvelope csrEnvelope(const std::vector<PlotPoints>& plots, double rmax, std::size_t nr, int simulations,
                                    std::uint32_t seed, const PairCorrelationOptions& options = {});

}  // namespace sylva::stand

#include "libstand/PairCorrelationEnvelope.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "libcommon/InputError.hpp"
#include "libcommon/SeededRandom.hpp"

namespace sylva::stand {

namespace {

// n points uniform in the window (binomial process: CSR given n), by rejection from its bounding box.
std::vector<Eigen::Vector2d> uniformPoints(const Window& window, std::size_t n, SeededRandom& rng) {
    const Eigen::Vector2d lo = window.lower(), span = window.upper() - window.lower();
    std::vector<Eigen::Vector2d> points;
    points.reserve(n);
    while (points.size() < n) {
        const Eigen::Vector2d p(lo.x() + span.x() * rng.uniform(), lo.y() + span.y() * rng.uniform());
        if (window.contains(p)) points.push_back(p);
    }
    return points;
}

void widen(std::vector<double>& low, std::vector<double>& high, const std::vector<double>& g) {
    for (std::size_t i = 0; i < g.size(); ++i) {
        if (std::isnan(g[i])) continue;
        low[i] = std::min(low[i], g[i]);
        high[i] = std::max(high[i], g[i]);
    }
}

}  // namespace

PairCorrelationEnvelope csrEnvelope(const std::vector<PlotPoints>& plots, double rmax, std::size_t nr, int simulations,
                                    std::uint32_t seed, const PairCorrelationOptions& options) {
    if (simulations < 1) throw InputError("CSR envelope: need at least 1 simulation, got " + std::to_string(simulations));
    SeededRandom rng(seed);
    PairCorrelationEnvelope e;
    e.simulations = simulations;
    const double inf = std::numeric_limits<double>::infinity();
    e.transLow.assign(nr, inf);
    e.isoLow.assign(nr, inf);
    e.transHigh.assign(nr, -inf);
    e.isoHigh.assign(nr, -inf);
    std::vector<PlotPoints> simulated = plots;
    for (int s = 0; s < simulations; ++s) {
        for (std::size_t p = 0; p < plots.size(); ++p) simulated[p].points = uniformPoints(plots[p].window, plots[p].points.size(), rng);
        const PairCorrelation g = pooledPairCorrelation(simulated, rmax, nr, options);
        e.r = g.r;
        widen(e.transLow, e.transHigh, g.trans);
        widen(e.isoLow, e.isoHigh, g.iso);
    }
    return e;
}

}  // namespace sylva::stand

#include "libdem/LumpedCalibration.hpp"

#include <gsl/gsl_statistics_double.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "libdem/Campaign.hpp"
#include "libcommon/SeededRandom.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::dem {
namespace {

double quantileOfSorted(const std::vector<double>& sorted, double q) {
    return gsl_stats_quantile_from_sorted_data(sorted.data(), 1, sorted.size(), q);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return quantileOfSorted(v, 0.5);
}

double spread(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return quantileOfSorted(v, 0.9) - quantileOfSorted(v, 0.1);
}

Estimate bootstrap(const std::vector<double>& sample, const std::function<double(std::vector<double>)>& statistic,
                   std::uint64_t seed) {
    if (sample.empty()) throw std::invalid_argument("bootstrap of an empty sample");
    constexpr int kReplicates = 1000;
    SeededRandom rng(seed);
    std::vector<double> values(kReplicates), resample(sample.size());
    for (double& v : values) {
        for (double& x : resample) x = sample[std::min(sample.size() - 1, static_cast<std::size_t>(rng.uniform(0, sample.size())))];
        v = statistic(resample);
    }
    std::sort(values.begin(), values.end());
    return {statistic(sample), quantileOfSorted(values, 0.025), quantileOfSorted(values, 0.975)};
}

}  // namespace

Estimate bootstrapMedian(const std::vector<double>& sample, std::uint64_t seed) { return bootstrap(sample, median, seed); }
Estimate bootstrapSpread(const std::vector<double>& sample, std::uint64_t seed) { return bootstrap(sample, spread, seed); }

LumpedCalibration calibrateLumped(const Scene& scene, const std::vector<double>& demRunouts,
                                  const LumpedCalibrationOptions& options) {
    LumpedCalibration fit;
    fit.demDist50 = bootstrapMedian(demRunouts, options.seed);
    fit.demSpread = bootstrapSpread(demRunouts, options.seed);
    auto runouts = [&](double roughness) {
        LumpedParams p = scene.config().lumped;
        p.rg70 = p.rg20 = p.rg10 = roughness;
        CampaignOptions c;
        c.model = Model::Lumped;
        c.runs = options.runs;
        c.seed = options.seed;
        c.threads = options.threads;
        ++fit.trials;
        std::vector<double> out;
        for (const RunResult& r : runCampaign(scene.withLumped(p), c)) out.push_back(r.runoutAlongSlope);
        return out;
    };
    // More roughness, shorter run-out: bisect on the logarithm of the roughness. Every trial uses the
    // same seeds, so the curve is smooth enough to bisect.
    auto solve = [&](double target, double tolerance) {
        double lo = options.roughnessLow, hi = options.roughnessHigh;
        const double atLo = median(runouts(lo)), atHi = median(runouts(hi));
        if (!(atLo >= target && target >= atHi))
            throw InputError("calibrating the lumped model: a Dist50 of " + std::to_string(target) +
                             " m is outside what roughness " + std::to_string(lo) + " to " + std::to_string(hi) +
                             " m gives (" + std::to_string(atLo) + " to " + std::to_string(atHi) +
                             " m); check lumped.soil_type and the scene");
        for (int k = 0; k < 40 && hi / lo > 1.0005; ++k) {
            const double mid = std::sqrt(lo * hi);
            const double d = median(runouts(mid));
            if (std::abs(d - target) < tolerance) return mid;
            (d > target ? lo : hi) = mid;
        }
        return std::sqrt(lo * hi);
    };
    fit.roughness = solve(fit.demDist50.value, options.tolerance);
    const std::vector<double> best = runouts(fit.roughness);
    fit.lumpedDist50 = bootstrapMedian(best, options.seed);
    fit.lumpedSpread = bootstrapSpread(best, options.seed);
    // The DEM's Dist50 is known to its interval, and the fit to its tolerance: so is the roughness (a
    // longer run-out, less roughness), over the interval widened by the tolerance. Its ends are found
    // to a quarter of that width: to the fit's tolerance, the ends of a DEM interval narrower than
    // it both stopped at the first roughness within it of the centre, a single value.
    const double shortest = fit.demDist50.low - options.tolerance, longest = fit.demDist50.high + options.tolerance;
    const double endTolerance = 0.25 * (longest - shortest);
    fit.roughnessHigh = std::max(fit.roughness, solve(shortest, endTolerance));
    fit.roughnessLow = std::min(fit.roughness, solve(longest, endTolerance));
    return fit;
}

}  // namespace sylva::dem

#pragma once
// Calibrating the lumped model on the DEM without forest, as the paper did (Sect. 2.3.2, Table 1):
// the soil type stays the paper's, the roughness (one obstacle height for rg70, rg20 and rg10, as
// Table 1 gives one) is fitted so that the lumped Dist50 matches the DEM's.
#include <cstdint>
#include <vector>

#include "libdem/Scene.hpp"

namespace sylva::dem {

struct Estimate {
    double value = 0, low = 0, high = 0;  // a statistic of the sample and its 95 % percentile bootstrap interval
};
// The median of a run-out sample, and the spread p90 - p10 (GSL's quantile definition), with their
// bootstrap intervals (GSL mt19937 seeded with `seed`, 1 000 resamples).
Estimate bootstrapMedian(const std::vector<double>& sample, std::uint64_t seed);
Estimate bootstrapSpread(const std::vector<double>& sample, std::uint64_t seed);

struct LumpedCalibrationOptions {
    int runs = 3000;             // lumped runs per trial roughness (the paper: 3 000)
    std::uint64_t seed = 1;
    int threads = 0;
    double roughnessLow = 0.005, roughnessHigh = 0.5;  // m: the bracket searched
    double tolerance = 0.5;      // m of Dist50 at which the search stops
};

struct LumpedCalibration {
    double roughness = 0;        // m: the fitted rg70 = rg20 = rg10
    Estimate demDist50, lumpedDist50;  // m
    Estimate demSpread, lumpedSpread;  // p90 - p10 of the run-out, m
    double roughnessLow = 0, roughnessHigh = 0;  // the roughness meeting the ends of the DEM's Dist50 interval widened by the tolerance
    int trials = 0;
};

// `demRunouts`: the DEM's run-outs without forest on `scene` (finite values). The scene's other
// [lumped] keys are kept. Throws InputError when no roughness in the bracket meets the target.
LumpedCalibration calibrateLumped(const Scene& scene, const std::vector<double>& demRunouts,
                                  const LumpedCalibrationOptions& options);

}  // namespace sylva::dem

#pragma once
// The pair correlation function g(r) of a stationary point pattern, estimated as spatstat's
//   pcf(X, r = seq(0, rmax, length.out = nr), correction = c("translate", "Ripley"), divisor = "r"):
//   g(r) = |W| / (2 pi r n (n-1)) * sum_{i != j} w_ij K_h(r - d_ij),
// with the Epanechnikov kernel of half-width h = stoyan / sqrt(lambda) (Stoyan & Stoyan 1994) and the
// translation (w = |W| / |W ∩ (W + x_j - x_i)|) or Ripley isotropic edge correction.
// g = 1 for a Poisson pattern; g > 1 at distances where pairs are more frequent (aggregation).
#include <Eigen/Core>
#include <vector>

#include "libstand/Inventory.hpp"
#include "libstand/KernelSmoothing.hpp"
#include "libstand/Window.hpp"

namespace sylva::stand {

struct PairCorrelationOptions {
    double stoyan = 0.15;                        // bandwidth coefficient c in h = c / sqrt(lambda)
    KernelSum kernelSum = KernelSum::AsRDensity;  // as spatstat (through R's density), or exact
};

struct PairCorrelation {
    std::vector<double> r;      // 0, rmax/(nr-1), ..., rmax
    std::vector<double> trans;  // translation-corrected estimate (+inf at r = 0 as in spatstat)
    std::vector<double> iso;    // Ripley isotropic estimate
    double bandwidth = 0;       // kernel half-width h, m
};

// Throws InputError if rmax <= 0 or nr < 2. With fewer than 2 points every value is NaN.
PairCorrelation pairCorrelation(const std::vector<Eigen::Vector2d>& points, const Window& window, double rmax,
                                std::size_t nr, const PairCorrelationOptions& options = {});

// spatstat's default range for K and g (rmax.rule("K")): a quarter of the window frame's shorter side,
// at most the distance within which a Poisson pattern has 1000 neighbours per point.
double defaultPairCorrelationRmax(const Window& window, std::size_t nPoints);

// Pools estimates on the same r grid (e.g. the plots of a stand) as a weighted mean; estimates with
// weight 0 (plots with fewer than 2 stems) are left out. Throws InputError if the r grids differ.
PairCorrelation poolPairCorrelations(const std::vector<PairCorrelation>& estimates, const std::vector<double>& weights);

// One plot of a stand (or a single pattern) as g(r) sees it.
struct PlotPoints {
    Window window;
    std::vector<Eigen::Vector2d> points;
};

// Each plot of the inventory with its stems' positions (every stem, measured or not).
std::vector<PlotPoints> plotPoints(const Inventory& inventory);
// A plot of fewer than two stems holds no pair: it weighs nothing in the pooled g(r).
inline bool holdsAPair(const PlotPoints& plot) { return plot.points.size() >= 2; }
// The largest r for all plots: the smallest of their defaultPairCorrelationRmax over the plots that
// hold a pair (an empty 2 m plot cut a stand's range to 0.5 m), over all plots if none does.
double defaultPairCorrelationRmax(const std::vector<PlotPoints>& plots);

// A stand's g(r): each plot's estimate on one r grid, pooled with weights n(n-1), the number of
// ordered pairs (a single plot is its own pool).
PairCorrelation pooledPairCorrelation(const std::vector<PlotPoints>& plots, double rmax, std::size_t nr,
                                      const PairCorrelationOptions& options = {});

}  // namespace sylva::stand

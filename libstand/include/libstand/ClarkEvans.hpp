#pragma once
// The Clark-Evans aggregation index R = mean nearest-neighbour distance / its expectation under
// complete spatial randomness (paper Eqs. 24-25), with the edge corrections of spatstat's clarkevans().
// R < 1: aggregated (coppice stools), R = 1: random, R > 1: regular.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "libstand/Window.hpp"

namespace sylva::stand {

struct ClarkEvansIndex {
    // Each is empty when undefined: fewer than 2 points; donnelly for a non-rectangular window; guard
    // when no point lies in the clip region; cdf when no nearest-neighbour distance is uncensored.
    std::optional<double> naive;     // no edge correction
    std::optional<double> donnelly;  // Donnelly (1978), rectangles only
    std::optional<double> guard;     // only points at least guardDistance inside the window
    std::optional<double> cdf;       // mean of the Kaplan-Meier estimate of the nn-distance cdf G
    double meanNearestNeighbour = 0;  // d_obs, m
    double guardDistance = 0;         // erosion distance of the guard clip region, m
    std::size_t nInGuard = 0;         // points in the clip region
};

// The guard clip region is the window eroded by guardFraction * sqrt(area): the default 0.05 is what the
// spatstat reference values of this project use (spatstat itself has no default clip region).
ClarkEvansIndex clarkEvans(const std::vector<Eigen::Vector2d>& points, const Window& window,
                           double guardFraction = 0.05);

}  // namespace sylva::stand

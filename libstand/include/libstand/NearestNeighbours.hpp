#pragma once
// Neighbour searches on a planar point pattern (CGAL k-d tree), as spatstat's nndist() and closepairs().
#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace sylva::stand {

// Distance from each point to its nearest other point; 0 for a point that shares its position with
// another (as spatstat's nndist). Every entry is +infinity when there are fewer than 2 points.
std::vector<double> nearestNeighbourDistances(const std::vector<Eigen::Vector2d>& points);

struct ClosePair {
    std::size_t i, j;  // ordered: both (i, j) and (j, i) are listed
    double distance;
};

// All ordered pairs i != j with |p_i - p_j| <= rmax (spatstat's closepairs(X, rmax, what="all")).
std::vector<ClosePair> closePairs(const std::vector<Eigen::Vector2d>& points, double rmax);

}  // namespace sylva::stand

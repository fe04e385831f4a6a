#pragma once
// The stems already placed in a forest, bucketed in square cells so that "does a new stem keep
// its clearance from every placed stem?" looks at the 3x3 cells around it only: placing n stems
// costs O(n), not O(n^2). The cell side is at least the largest exclusion distance, 2 r_max +
// clearance, and large enough that the cells do not outnumber the stems expected by much: a sparse
// stand over a large extent would otherwise ask for more cells than memory holds.
#include <Eigen/Core>
#include <vector>

namespace sylva::stand {

class StemGrid {
public:
    // Covers [lower, upper]; maxRadiusM bounds every radius later passed to isFree/insert, and about
    // `expectedStems` will be inserted.
    StemGrid(const Eigen::Vector2d& lower, const Eigen::Vector2d& upper, double maxRadiusM, double clearanceM,
             std::size_t expectedStems);

    // True if a stem of radius r at p is at least r + r_j + clearance from every inserted stem j.
    bool isFree(const Eigen::Vector2d& p, double radiusM) const;
    void insert(const Eigen::Vector2d& p, double radiusM);

private:
    long cellIndex(long ix, long iy) const { return iy * nx_ + ix; }
    long column(double x) const;
    long row(double y) const;

    Eigen::Vector2d lower_;
    double cellSide_, clearance_;
    long nx_, ny_;
    std::vector<long> head_;  // per cell: last inserted stem in it, or -1
    std::vector<long> next_;  // per stem: previous stem in the same cell, or -1
    std::vector<Eigen::Vector2d> points_;
    std::vector<double> radii_;
};

}  // namespace sylva::stand

#include "StemGrid.hpp"

#include <algorithm>
#include <cmath>

namespace sylva::stand {

namespace {
constexpr double kCellsPerStem = 2;  // at most, on average: a few stems in the 3x3 cells a test reads
}  // namespace

StemGrid::StemGrid(const Eigen::Vector2d& lower, const Eigen::Vector2d& upper, double maxRadiusM, double clearanceM,
                   std::size_t expectedStems)
    : lower_(lower), clearance_(clearanceM) {
    const Eigen::Vector2d size = upper - lower;
    const double cells = kCellsPerStem * static_cast<double>(std::max<std::size_t>(1, expectedStems));
    cellSide_ = std::max(2 * maxRadiusM + clearanceM, std::sqrt(size.x() * size.y() / cells));
    nx_ = std::max(1L, static_cast<long>(std::ceil((upper.x() - lower.x()) / cellSide_)));
    ny_ = std::max(1L, static_cast<long>(std::ceil((upper.y() - lower.y()) / cellSide_)));
    head_.assign(static_cast<std::size_t>(nx_ * ny_), -1);
}

long StemGrid::column(double x) const {
    return std::clamp(static_cast<long>(std::floor((x - lower_.x()) / cellSide_)), 0L, nx_ - 1);
}

long StemGrid::row(double y) const {
    return std::clamp(static_cast<long>(std::floor((y - lower_.y()) / cellSide_)), 0L, ny_ - 1);
}

bool StemGrid::isFree(const Eigen::Vector2d& p, double radiusM) const {
    const long cx = column(p.x()), cy = row(p.y());
    for (long iy = std::max(0L, cy - 1); iy <= std::min(ny_ - 1, cy + 1); ++iy)
        for (long ix = std::max(0L, cx - 1); ix <= std::min(nx_ - 1, cx + 1); ++ix)
            for (long j = head_[cellIndex(ix, iy)]; j >= 0; j = next_[j]) {
                const double minDistance = radiusM + radii_[j] + clearance_;
                if ((points_[j] - p).squaredNorm() < minDistance * minDistance) return false;
            }
    return true;
}

void StemGrid::insert(const Eigen::Vector2d& p, double radiusM) {
    const long cell = cellIndex(column(p.x()), row(p.y()));
    next_.push_back(head_[cell]);
    head_[cell] = static_cast<long>(points_.size());
    points_.push_back(p);
    radii_.push_back(radiusM);
}

}  // namespace sylva::stand

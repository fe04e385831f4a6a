#include "libdem/SegmentGeometry.hpp"

#include <algorithm>
#include <limits>

namespace sylva::dem {

std::pair<double, double> closestBetweenSegments(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
    // Minimise |a0 + s u - b0 - t v|^2 over the unit square: the interior stationary point if it
    // lies inside, else the best of the edges (each a point-segment problem).
    const Vec3 u = a1 - a0, v = b1 - b0, w = a0 - b0;
    const double a = u.squaredNorm(), b = u.dot(v), c = v.squaredNorm(), d = u.dot(w), e = v.dot(w);
    const double den = a * c - b * b;
    if (den > 1e-12 * a * c) {
        const double s = (b * e - c * d) / den, t = (a * e - b * d) / den;
        if (s >= 0 && s <= 1 && t >= 0 && t <= 1) return {s, t};
    }
    std::pair<double, double> best{0, 0};
    double bestDist = std::numeric_limits<double>::infinity();
    auto consider = [&](double s, double t) {
        const double dist = (a0 + s * u - b0 - t * v).squaredNorm();
        if (dist < bestDist) bestDist = dist, best = {s, t};
    };
    consider(0, closestOnSegment(a0, b0, b1));
    consider(1, closestOnSegment(a1, b0, b1));
    consider(closestOnSegment(b0, a0, a1), 0);
    consider(closestOnSegment(b1, a0, a1), 1);
    return best;
}

}  // namespace sylva::dem

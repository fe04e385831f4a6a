#pragma once
// Closest points on the segments that carry a stem's connections (cylinders of Fig. 2).
#include <algorithm>
#include <utility>

#include "libdem/RigidBody.hpp"

namespace sylva::dem {

// Parameter t in [0, 1] of the point of segment [a, b] closest to p. Inline: the block's spheres are
// tested against each connection near them, and the segment's part of the work is then done once.
inline double closestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double len2 = ab.squaredNorm();
    if (len2 <= 0) return 0;
    return std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
}

// Parameters (s, t) in [0, 1]^2 of the closest points of segments [a0, a1] and [b0, b1].
std::pair<double, double> closestBetweenSegments(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1);

}  // namespace sylva::dem

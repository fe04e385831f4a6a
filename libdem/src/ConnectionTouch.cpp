#include "libdem/ConnectionTouch.hpp"

#include <tuple>

#include "libdem/SegmentGeometry.hpp"
#include "libdem/SphereContact.hpp"

namespace sylva::dem {

namespace {

// Along a connection, a closest point this near its lower node is the node: an interior closest
// point of two segments crossing at a node lands a rounding away from it.
constexpr double kAtNode = 1e-9;

bool belongsToTheConnectionBelow(const Stem& s, std::size_t c, double along) {
    return along <= kAtNode && c > 0 && !s.broken(c - 1);
}

}  // namespace

std::optional<ConnectionTouch> touchConnections(const Stem& A, std::size_t ca, const Stem& B, std::size_t cb) {
    if (A.broken(ca) || B.broken(cb)) return std::nullopt;
    const Vec3 &a0 = A.position[ca], &a1 = A.position[ca + 1];
    const Vec3 &b0 = B.position[cb], &b1 = B.position[cb + 1];
    ConnectionTouch touch{};
    std::tie(touch.s, touch.t) = closestBetweenSegments(a0, a1, b0, b1);
    if (belongsToTheConnectionBelow(A, ca, touch.s) || belongsToTheConnectionBelow(B, cb, touch.t)) return std::nullopt;
    const double ra = 0.5 * A.connectionDiameter(ca), rb = 0.5 * B.connectionDiameter(cb);
    if (!touchSpheres(a0 + touch.s * (a1 - a0), ra, b0 + touch.t * (b1 - b0), rb, touch.geometry)) return std::nullopt;
    return touch;
}

}  // namespace sylva::dem

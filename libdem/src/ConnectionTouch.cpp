#include "libdem/ConnectionTouch.hpp"

#include <tuple>

#include "libdem/SegmentGeometry.hpp"
#include "libdem/SphereContact.hpp"

namespace sylva::dem {

namespace {

// Along a connection, a closest point this near its lower node is the node: an interior closest
// point of two segments crossing at a node lands a rounding away from it.
constexpr double kAtNode = 1e-9;

}  // namespace

bool fusedAtRest(const PlantedStem& A, std::size_t ca, const PlantedStem& B, std::size_t cb) {
    const double za0 = A.foot.z() + A.stem.restHeight(ca), za1 = A.foot.z() + A.stem.restHeight(ca + 1);
    const double zb0 = B.foot.z() + B.stem.restHeight(cb), zb1 = B.foot.z() + B.stem.restHeight(cb + 1);
    constexpr double kSameHeight = 1e-6;  // m: heights are sums of connection lengths, equal up to round-off
    if (za1 < zb0 - kSameHeight || zb1 < za0 - kSameHeight) return false;  // sharing an end height counts
    return (A.foot - B.foot).head<2>().norm() < 0.5 * (A.stem.connectionDiameter(ca) + B.stem.connectionDiameter(cb));
}

std::optional<ConnectionTouch> touchConnections(const PlantedStem& A, std::size_t ca, const PlantedStem& B, std::size_t cb) {
    const Stem &sa = A.stem, &sb = B.stem;
    if (sa.broken(ca) || sb.broken(cb)) return std::nullopt;
    const Vec3 &a0 = sa.position[ca], &a1 = sa.position[ca + 1];
    const Vec3 &b0 = sb.position[cb], &b1 = sb.position[cb + 1];
    ConnectionTouch touch{};
    std::tie(touch.s, touch.t) = closestBetweenSegments(a0, a1, b0, b1);
    if (touch.s <= kAtNode && ca > 0 && !sa.broken(ca - 1) && !fusedAtRest(A, ca - 1, B, cb)) return std::nullopt;
    if (touch.t <= kAtNode && cb > 0 && !sb.broken(cb - 1) && !fusedAtRest(A, ca, B, cb - 1)) return std::nullopt;
    const double ra = 0.5 * sa.connectionDiameter(ca), rb = 0.5 * sb.connectionDiameter(cb);
    if (!touchSpheres(a0 + touch.s * (a1 - a0), ra, b0 + touch.t * (b1 - b0), rb, touch.geometry)) return std::nullopt;
    return touch;
}

}  // namespace sylva::dem

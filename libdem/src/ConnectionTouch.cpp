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
    const std::optional<TouchFeature> fa = touchFeature(sa, ca), fb = touchFeature(sb, cb);
    if (!fa || !fb) return std::nullopt;
    ConnectionTouch touch{};
    // A lone node is the upper end of its broken connection: the contact's force goes to it alone.
    if (fa->nodeOnly || fb->nodeOnly) {
        touch.s = fa->nodeOnly ? 1 : closestOnSegment(fb->a1, fa->a0, fa->a1);
        touch.t = fb->nodeOnly ? 1 : closestOnSegment(fa->a1, fb->a0, fb->a1);
    } else {
        std::tie(touch.s, touch.t) = closestBetweenSegments(fa->a0, fa->a1, fb->a0, fb->a1);
    }
    if (touch.s <= kAtNode && ca > 0 && !sa.broken(ca - 1) && !fusedAtRest(A, ca - 1, B, cb)) return std::nullopt;
    if (touch.t <= kAtNode && cb > 0 && !sb.broken(cb - 1) && !fusedAtRest(A, ca, B, cb - 1)) return std::nullopt;
    if (!touchSpheres(fa->a0 + touch.s * (fa->a1 - fa->a0), fa->radius, fb->a0 + touch.t * (fb->a1 - fb->a0), fb->radius,
                      touch.geometry))
        return std::nullopt;
    return touch;
}

}  // namespace sylva::dem

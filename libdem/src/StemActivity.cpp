#include "libdem/StemActivity.hpp"

#include <algorithm>
#include <cmath>

#include "libdem/SegmentGeometry.hpp"

namespace sylva::dem {

namespace {

double horizontalDistance(const Vec3& a, const Vec3& b) { return (a - b).head<2>().norm(); }

// Radius of a standing stem at its foot (the cone through the DBH at 1.3 m; Stem::diameterAt).
double baseRadius(const PlacedTree& p) {
    const double h = p.geometry.height;
    return h > 1.3 ? 0.5 * p.geometry.dbh * h / (h - 1.3) : 0.5 * p.geometry.dbh;
}

double fastestNode(const Stem& s) {
    double v2 = 0;
    for (const Vec3& v : s.velocity) v2 = std::max(v2, v.squaredNorm());
    return std::sqrt(v2);
}

// A stem sleeps only this far beyond the block's waking reach, so that one does not wake and
// sleep it step after step at the edge.
constexpr double kSleepHysteresis = 1.0;  // m

// A node closer than this to its tree's foot still stands where the tree grew.
constexpr double kStandingTolerance = 0.05;  // m

}  // namespace

double StemActivity::blockReach(const RigidBody& block, double travelAhead) const {
    return block.boundingRadius() + cfg_.wakeMargin + travelAhead;
}

bool StemActivity::blockReaches(const RigidBody& block, double reach, const PlacedTree& tree) {
    if (horizontalDistance(block.position, tree.foot) > reach + baseRadius(tree)) return false;
    return !(block.position.z() - block.boundingRadius() > tree.foot.z() + tree.geometry.height);
}

bool StemActivity::displaced(const Stem& s, std::size_t node, const PlacedTree& own) {
    return !(horizontalDistance(s.position[node], own.foot) < kStandingTolerance);
}

double StemActivity::nodeReach(const Stem& s, std::size_t node, double dt, int stepsBetweenChecks) const {
    const double r = s.nodeRadius(node);
    return r + cfg_.wakeMargin + s.velocity[node].norm() * dt * 2 * stepsBetweenChecks;
}

bool StemActivity::nodeReaches(const Vec3& node, double reach, const PlacedTree& other) {
    if (horizontalDistance(node, other.foot) > reach + baseRadius(other)) return false;
    return !(node.z() > other.foot.z() + other.geometry.height + reach);
}

bool StemActivity::blockCanReach(const RigidBody& block, const Stem& s, double gravity) const {
    const double horizon = cfg_.returnHorizon;
    // The block flies on under gravity over the horizon: its mean velocity then.
    const Vec3 blockVelocity = block.velocity - Vec3(0, 0, 0.5 * gravity * horizon);
    const double slack = block.boundingRadius();
    // The gap from the block's bounding sphere to the stem's surface at a point of its axis `radius`
    // thick moving at `velocity`. Both moving on so (the block under gravity), their distance shrinks
    // over the horizon by at most their relative velocity along the line between them times the
    // horizon (|d + u| >= |d| + u . d / |d|): a node swinging or falling away from the block, or past
    // it, does not close the gap.
    const auto reaches = [&](const Vec3& point, double radius, const Vec3& velocity) {
        const Vec3 d = point - block.position;
        const double distance = d.norm();
        const double gap = distance - slack - radius;
        if (gap <= 0) return true;
        return gap < (blockVelocity - velocity).dot(d) / distance * horizon;
    };
    // Each node, and each intact connection at its point closest to the block (the stem is a cone
    // between its nodes, and that point of the axis moves with the velocities of its nodes, weighed
    // by where it lies). The closing speed depends on the direction: a node the block falls
    // towards may close its gap first although the connection's closest point does not.
    for (std::size_t i = 0; i < s.nodeCount(); ++i)
        if (reaches(s.position[i], s.nodeRadius(i), s.velocity[i])) return true;
    for (std::size_t c = 0; c < s.connectionCount(); ++c) {
        if (s.broken(c)) continue;
        const Vec3 &a = s.position[c], &b = s.position[c + 1];
        const double t = closestOnSegment(block.position, a, b);
        const Vec3 velocity = (1 - t) * s.velocity[c] + t * s.velocity[c + 1];
        if (reaches(a + t * (b - a), s.nodeRadius(c) + t * (s.nodeRadius(c + 1) - s.nodeRadius(c)), velocity)) return true;
    }
    return false;
}

bool StemActivity::piecesFalling(const Stem& s, bool broken, double lastBlockContact, double t) const {
    return broken && t - lastBlockContact < cfg_.pieceMaxTime && fastestNode(s) > cfg_.pieceRestSpeed;
}

bool StemActivity::mayRest(const RigidBody& block, const Stem& s, bool broken, double lastBlockContact,
                           double lastOtherContact, double t, double gravity) const {
    // A falling top is not stopped mid-air, whatever it touches.
    if (piecesFalling(s, broken, lastBlockContact, t)) return false;
    // A stem just out of a contact with the soil or a neighbour, and still moving, is far from any
    // rest where it stands: stopped, it would be set moving again by that contact (and each such
    // cycle found with energy from nowhere, docs/performance.md).
    if (t - lastOtherContact < cfg_.sleepAfter && fastestNode(s) > cfg_.pieceRestSpeed) return false;
    return !blockCanReach(block, s, gravity);
}

std::optional<StemAwake> StemActivity::holds(const RigidBody& block, const PlacedTree& tree, const Stem& s, bool broken,
                                             double lastBlockContact, double t, double gravity) const {
    if (t - lastBlockContact < cfg_.sleepAfter) return StemAwake::Waiting;
    const double reach = blockReach(block, kSleepHysteresis);
    if (horizontalDistance(block.position, tree.foot) < reach + baseRadius(tree)) return StemAwake::BlockNear;
    if (piecesFalling(s, broken, lastBlockContact, t)) return StemAwake::PiecesFalling;
    // Its foot far from the block, a bent, broken or uprooted stem may still lie in the block's way:
    // it may not sleep where it may not rest (mayRest), or the block would pass through it asleep.
    if (blockCanReach(block, s, gravity)) return StemAwake::BlockNear;
    return std::nullopt;
}

}  // namespace sylva::dem

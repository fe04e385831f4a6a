// When a stem joins the run and when it leaves it (StemActivity): the block wakes what it can
// reach and nothing it flies over; a stem sleeps only once the block has gone, and a broken one
// only once its pieces rest.
#include <gtest/gtest.h>

#include "libdem/StemActivity.hpp"

using namespace sylva::dem;

namespace {

// A 20 cm beech at the origin, on flat ground at z = 0.
PlacedTree tree20() { return PlacedTree{1, Vec3::Zero(), beechStem(20), StemFoot::RootSpring}; }

// That beech built, standing still.
Stem stem20() {
    const PlacedTree t = tree20();
    return Stem(t.geometry, StemParams{}, t.foot, t.support);
}

// Resting and sleeping as the tests below ask them: a stem waits 0.3 s after the block, lies still
// below 0.2 m/s, and the block is looked ahead 0.1 s.
ForestActivity restingRules() {
    ForestActivity cfg;
    cfg.sleepAfter = 0.3;
    cfg.pieceRestSpeed = 0.2;
    cfg.returnHorizon = 0.1;
    return cfg;
}

// A single sphere of 0.5 m radius: its bounding radius is 0.5 m.
RigidBody ball(const Vec3& at) {
    RigidBody b(1000, Vec3(100, 100, 100), {ClumpSphere{Vec3::Zero(), 0.5}});
    b.position = at;
    return b;
}

}  // namespace

TEST(StemActivity, BlockWakesWhatItCanReachBeforeTheNextCheckAndNothingItFliesOver) {
    ForestActivity cfg;
    cfg.wakeMargin = 0.1;
    const StemActivity activity(cfg);
    const PlacedTree t = tree20();
    const double base = 0.5 * t.geometry.dbh * t.geometry.height / (t.geometry.height - 1.3);  // the cone at the foot
    const RigidBody b = ball(Vec3(2, 0, 0.5));
    EXPECT_DOUBLE_EQ(activity.blockReach(b, 0.3), 0.5 + 0.1 + 0.3);
    // 2 m away: reached only when the block's travel before the next check closes the gap.
    EXPECT_FALSE(StemActivity::blockReaches(b, activity.blockReach(b, 0.0), t));
    EXPECT_TRUE(StemActivity::blockReaches(b, activity.blockReach(b, 2.0 - 0.6 - base + 1e-9), t));
    EXPECT_FALSE(StemActivity::blockReaches(b, activity.blockReach(b, 2.0 - 0.6 - base - 1e-6), t));
    // Right beside it but with its lowest point above the top: flying over.
    const RigidBody over = ball(Vec3(0.3, 0, t.geometry.height + 0.6));
    EXPECT_FALSE(StemActivity::blockReaches(over, activity.blockReach(over, 0.0), t));
    const RigidBody grazing = ball(Vec3(0.3, 0, t.geometry.height + 0.4));
    EXPECT_TRUE(StemActivity::blockReaches(grazing, activity.blockReach(grazing, 0.0), t));
}

TEST(StemActivity, StemSleepsOnlyOnceTheBlockHasGoneAndItsPiecesRest) {
    ForestActivity cfg = restingRules();
    cfg.pieceMaxTime = 10;
    const StemActivity activity(cfg);
    const PlacedTree t = tree20();
    Stem s(t.geometry, StemParams{}, t.foot, t.support);
    const RigidBody near = ball(Vec3(1.5, 0, 0.5)), gone = ball(Vec3(20, 0, 0.5));
    const std::optional<StemAwake> maySleep;
    const double g = 9.81;
    // The block left 1 s ago.
    EXPECT_EQ(activity.holds(gone, t, s, false, 0.0, 1.0, g), maySleep);
    EXPECT_EQ(activity.holds(gone, t, s, false, 0.0, 0.2, g), StemAwake::Waiting) << "before sleepAfter";
    EXPECT_EQ(activity.holds(near, t, s, false, 0.0, 1.0, g), StemAwake::BlockNear) << "block still within reach";
    // A broken stem whose top still falls at 3 m/s.
    s.velocity.back() = Vec3(0, 0, -3);
    EXPECT_EQ(activity.holds(gone, t, s, false, 0.0, 1.0, g), maySleep) << "a whole stem's sway does not hold it";
    EXPECT_EQ(activity.holds(gone, t, s, true, 0.0, 1.0, g), StemAwake::PiecesFalling) << "a falling top is not frozen mid-air";
    EXPECT_EQ(activity.holds(gone, t, s, true, 0.0, 10.5, g), maySleep) << "a piece rolling on is let go after pieceMaxTime";
    s.velocity.back() = Vec3(0, 0, -0.1);
    EXPECT_EQ(activity.holds(gone, t, s, true, 0.0, 1.0, g), maySleep) << "pieces at rest";
    // Felled along +x, its foot 5 m from the block, which heads for it at 2 m/s 0.1 m away: the stem
    // lies in the block's way and may not sleep (it may not rest either), though its foot is far.
    for (std::size_t i = 0; i < s.nodeCount(); ++i) s.position[i] = Vec3(s.restHeight(i), 0, 0.15), s.velocity[i].setZero();
    RigidBody coming = ball(Vec3(5, 0.6, 0.5));
    coming.velocity = Vec3(0, -2, 0);
    EXPECT_FALSE(activity.mayRest(coming, s, true, 0.0, -1.0, 1.0, g));
    EXPECT_EQ(activity.holds(coming, t, s, true, 0.0, 1.0, g), StemAwake::BlockNear);
    coming.velocity = Vec3(0, 2, 0);  // going away from it
    EXPECT_EQ(activity.holds(coming, t, s, true, 0.0, 1.0, g), maySleep);
}

// The block can reach a stem within the horizon H if its bounding sphere touches a node's or a
// connection's surface, or closes the gap in H: its velocity (falling on under gravity) less the
// stem's there, along the line between them.
TEST(StemActivity, BlockCanReachAStemItHeadsForWithinTheHorizon) {
    ForestActivity cfg;
    cfg.wakeMargin = 0.1;
    cfg.returnHorizon = 0.1;
    const StemActivity activity(cfg);
    Stem s = stem20();
    const double g = 9.81, l = s.connectionLength(0);
    // The block level with node 1, beside it (+x), where both its connections come closest:
    // gap = x - 0.5 - r_1, from its bounding sphere. The wake margin (0.1 here) is not in it: the
    // horizon's approach covers what comes next, and a margin would keep a stem moving that nothing nears.
    const double z = s.restHeight(1), r = 0.5 * s.diameterAt(z);
    const double touching = 0.5 + r;
    EXPECT_TRUE(activity.blockCanReach(ball(Vec3(touching - 0.01, 0, z)), s, g)) << "within touching distance";
    EXPECT_FALSE(activity.blockCanReach(ball(Vec3(touching + 0.01, 0, z)), s, g)) << "just out of it, still";
    // Level with the middle of connection 1: its surface, not its nodes, sets the distance.
    const double rMid = 0.5 * s.diameterAt(z + 0.5 * l);
    EXPECT_TRUE(activity.blockCanReach(ball(Vec3(0.5 + rMid - 0.01, 0, z + 0.5 * l)), s, g));
    EXPECT_FALSE(activity.blockCanReach(ball(Vec3(0.5 + rMid + 0.01, 0, z + 0.5 * l)), s, g));
    // Coming back at 5 m/s: 0.5 m in 0.1 s (gravity pulls it down, across the line to node 1 only).
    RigidBody back = ball(Vec3(touching + 0.45, 0, z));
    back.velocity = Vec3(-5, 0, 0);
    EXPECT_TRUE(activity.blockCanReach(back, s, g));
    back.position.x() = touching + 0.55;
    EXPECT_FALSE(activity.blockCanReach(back, s, g));
    // Going away at 5 m/s, just out of touching distance: it cannot.
    RigidBody away = ball(Vec3(touching + 0.01, 0, z));
    away.velocity = Vec3(5, 0, 0);
    EXPECT_FALSE(activity.blockCanReach(away, s, g));
    // ... unless a node swings towards it faster: node 1 at 6 m/s closes 0.1 m net in 0.1 s.
    s.velocity[1] = Vec3(6, 0, 0);
    EXPECT_TRUE(activity.blockCanReach(away, s, g));
    // As fast, but swinging away from the block or past it (a top falling beside it), the node
    // does not close the gap: only its speed towards the block counts.
    s.velocity[1] = Vec3(-6, 0, 0);
    EXPECT_FALSE(activity.blockCanReach(away, s, g)) << "swinging away";
    s.velocity[1] = Vec3(0, 6, 0);
    EXPECT_FALSE(activity.blockCanReach(away, s, g)) << "swinging past";
    s.velocity[1] = Vec3(0, 0, -6);
    EXPECT_FALSE(activity.blockCanReach(away, s, g)) << "falling past";
}

// A stem the block cannot reach may stop where it stands if it has swung free of everything for
// sleep_after_s, whatever its speed, or lies still on what it touches; not if it has just left a
// contact at speed (stopped there, the contact would set it moving again and again).
TEST(StemActivity, StemRestsWhereItStandsOnlyFreeOfContactsOrStill) {
    const ForestActivity cfg = restingRules();
    const StemActivity activity(cfg);
    Stem s = stem20();
    const double g = 9.81;
    const RigidBody gone = ball(Vec3(20, 0, 0.5)), near = ball(Vec3(0.6, 0, 0.5));  // both at rest
    s.velocity.back() = Vec3(2, 0, 0);  // its top swings
    const bool whole = false;
    const double blockLeft = 0.5;  // the block's last contact
    EXPECT_TRUE(activity.mayRest(gone, s, whole, blockLeft, 0.0, 1.0, g)) << "free of contacts for 1 s";
    EXPECT_FALSE(activity.mayRest(gone, s, whole, blockLeft, 0.9, 1.0, g)) << "left a contact 0.1 s ago at 2 m/s";
    EXPECT_FALSE(activity.mayRest(near, s, whole, blockLeft, 0.0, 1.0, g)) << "the block can reach it";
    s.velocity.back() = Vec3(0.1, 0, 0);
    EXPECT_TRUE(activity.mayRest(gone, s, whole, blockLeft, 1.0, 1.0, g)) << "lying still on what it touches";
}

// A broken stem's top falling free of everything is not stopped mid-air while the pieces' time
// (piece_max_time_s after the block's last contact) runs; once it lies still, or that time is over,
// it may rest as a whole stem does. With no pieces' time (0) it rests as a whole stem.
TEST(StemActivity, AFallingTopDoesNotRestMidAir) {
    ForestActivity cfg = restingRules();
    cfg.pieceMaxTime = 2;
    const StemActivity activity(cfg);
    Stem s = stem20();
    const double g = 9.81;
    const RigidBody gone = ball(Vec3(20, 0, 0.5));
    const bool broken = true;
    s.velocity.back() = Vec3(0, 0, -3);  // falling, free of contacts for 1 s
    EXPECT_TRUE(activity.piecesFalling(s, broken, 0.5, 1.0));
    EXPECT_FALSE(activity.mayRest(gone, s, broken, 0.5, 0.0, 1.0, g)) << "0.5 s after the block left";
    EXPECT_TRUE(activity.mayRest(gone, s, broken, 0.5, 0.0, 2.6, g)) << "past piece_max_time_s";
    EXPECT_TRUE(activity.mayRest(gone, s, false, 0.5, 0.0, 1.0, g)) << "a whole stem swinging";
    s.velocity.back() = Vec3(0, 0, -0.1);
    EXPECT_TRUE(activity.mayRest(gone, s, broken, 0.5, 1.0, 1.0, g)) << "lying still";
    ForestActivity noPieces = cfg;
    noPieces.pieceMaxTime = 0;
    s.velocity.back() = Vec3(0, 0, -3);
    EXPECT_TRUE(StemActivity(noPieces).mayRest(gone, s, broken, 0.5, 0.0, 1.0, g));
}

TEST(StemActivity, DisplacedNodeWakesTheNeighboursItCanTouch) {
    ForestActivity cfg;
    cfg.wakeMargin = 0.1;
    const StemActivity activity(cfg);
    const PlacedTree own = tree20();
    Stem s(own.geometry, StemParams{}, own.foot, own.support);
    const std::size_t i = s.nodeCount() / 2;
    EXPECT_FALSE(StemActivity::displaced(s, i, own)) << "standing where it grew";
    s.position[i] += Vec3(2, 0, 0);
    EXPECT_TRUE(StemActivity::displaced(s, i, own));
    // At rest its reach is its radius and the margin; moving at 4 m/s, twice its travel is added.
    const double r = s.nodeRadius(i);
    EXPECT_DOUBLE_EQ(activity.nodeReach(s, i, 1e-4, 10), r + 0.1);
    s.velocity[i] = Vec3(4, 0, 0);
    EXPECT_NEAR(activity.nodeReach(s, i, 1e-4, 10), r + 0.1 + 4 * 1e-4 * 2 * 10, 1e-12);
    PlacedTree other = tree20();
    other.foot = Vec3(3, 0, 0);
    const Vec3& p = s.position[i];
    EXPECT_TRUE(StemActivity::nodeReaches(p, 1.0, other));
    EXPECT_FALSE(StemActivity::nodeReaches(p, 0.5, other));
    other.foot = Vec3(2, 0, -(other.geometry.height + 2 + p.z()));  // on a terrace below, its top under the node
    EXPECT_FALSE(StemActivity::nodeReaches(p, 1.0, other));
}

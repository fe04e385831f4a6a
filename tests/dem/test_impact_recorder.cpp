// The tree-impact records (ImpactRecorder): an impact opens when the block touches the standing
// stem, and pieces broken off a stem are debris, which opens no impact of its own, also once the
// stem's impact has closed.
#include <gtest/gtest.h>

#include "libdem/ImpactRecorder.hpp"

using namespace sylva::dem;

namespace {

RigidBody ball() {
    RigidBody b(1000, Vec3(100, 100, 100), {ClumpSphere{Vec3::Zero(), 0.5}});
    b.velocity = Vec3(10, 0, 0);
    return b;
}

}  // namespace

TEST(ImpactRecorder, OnlyTheStandingStemOpensAnImpact) {
    const PlacedTree tree{7, Vec3::Zero(), beechStem(20), StemFoot::RootSpring};
    const Stem stem(tree.geometry, StemParams{}, tree.foot, tree.support);
    const ImpactRecorder::StemOf stemOf = [&](std::uint32_t) -> const Stem& { return stem; };
    const RigidBody block = ball();
    ImpactRecorder r;
    const std::uint32_t piece = 1;  // a top broken off
    r.beginStep();
    r.touch(block, 0, tree, piece, Vec3(0, 0, 3), 0.1, stem);
    r.endStep(block, stemOf);
    EXPECT_FALSE(r.isOpen(0)) << "debris alone";
    r.beginStep();
    r.touch(block, 0, tree, 0, Vec3(0, 0, 1), 0.2, stem);
    r.endStep(block, stemOf);
    EXPECT_TRUE(r.isOpen(0));
    r.close(0, block, stem);  // the stem sleeps
    r.beginStep();
    r.touch(block, 0, tree, piece, Vec3(0, 0, 0.2), 0.5, stem);  // woken, its top on the block
    r.endStep(block, stemOf);
    const std::vector<TreeImpact> all = r.finish(block, stemOf);
    ASSERT_EQ(all.size(), 1u);
    EXPECT_EQ(all[0].tree, 7);
    EXPECT_DOUBLE_EQ(all[0].time, 0.2);
    EXPECT_DOUBLE_EQ(all[0].height, 1.0);
}

// The block leaves the standing stem ("after" is taken), then the stem's broken top lands on it
// while the impact is still open: debris, which neither moves "after" nor keeps the impact in contact.
TEST(ImpactRecorder, DebrisLandingOnTheBlockAfterItLeftDoesNotMoveAfter) {
    const PlacedTree tree{7, Vec3::Zero(), beechStem(20), StemFoot::RootSpring};
    const Stem stem(tree.geometry, StemParams{}, tree.foot, tree.support);
    const ImpactRecorder::StemOf stemOf = [&](std::uint32_t) -> const Stem& { return stem; };
    RigidBody block = ball();
    ImpactRecorder r;
    r.beginStep();
    r.touch(block, 0, tree, 0, Vec3(0, 0, 1), 0.1, stem);  // the standing stem: the impact opens
    r.endStep(block, stemOf);
    block.velocity = Vec3(6, 0, 0);  // slowed by the stem
    r.beginStep();  // no contact: the block has left, "after" is its state now
    r.endStep(block, stemOf);
    const double after = block.kineticEnergy();
    block.velocity = Vec3(2, 0, 0);  // sliding on, later
    const std::uint32_t top = 1;
    for (int step = 0; step < 3; ++step) {  // the top lies on the block for a few steps, then rolls off
        r.beginStep();
        if (step < 2) r.touch(block, 0, tree, top, Vec3(0.5, 0, 0.4), 0.9 + 0.01 * step, stem);
        r.endStep(block, stemOf);
    }
    const std::vector<TreeImpact> all = r.finish(block, stemOf);
    ASSERT_EQ(all.size(), 1u);
    EXPECT_DOUBLE_EQ(all[0].energyAfter, after);
    EXPECT_DOUBLE_EQ(all[0].speedAfter, 6.0);
}

// The step's phases are timed (StepPhases): every phase has its own name in summary.json, the
// phases are sampled and scaled, and a run through a tree spends time stepping it.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <set>
#include <string>

#include "libdem/BlockRun.hpp"
#include "libdem/Stem.hpp"
#include "libdem/StepPhases.hpp"

using namespace sylva::dem;

TEST(StepPhases, EveryPhaseHasItsOwnName) {
    std::set<std::string> names;
    for (std::size_t p = 0; p < kStepPhases; ++p) {
        const std::string n = name(static_cast<StepPhase>(p));
        EXPECT_NE(n, "?") << p;
        EXPECT_EQ(n.find_first_not_of("abcdefghijklmnopqrstuvwxyz_"), std::string::npos) << n;
        names.insert(n);
    }
    EXPECT_EQ(names.size(), kStepPhases);
}

// Only one step in kTimedStepEvery reads the clock, and its laps count for that many steps.
TEST(StepPhases, OneStepInEveryFewIsTimedForAllOfThem) {
    PhaseTimes times;
    for (long step = 1; step < kTimedStepEvery; ++step) {
        PhaseClock clock(times, step);
        clock.lap(StepPhase::Stems);
    }
    EXPECT_EQ(times.total(), 0.0);
    // The spin starts after the clock does and the wall time is read around both, so the lap is at
    // least the 2 ms spun and at most the wall: a spin begun before the clock's own start read
    // 1.99999 ms once in CI.
    const auto before = std::chrono::steady_clock::now();
    {
        PhaseClock clock(times, kTimedStepEvery);
        const auto t0 = std::chrono::steady_clock::now();
        while (std::chrono::steady_clock::now() - t0 < std::chrono::milliseconds(2)) {
        }
        clock.lap(StepPhase::Stems);
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count();
    EXPECT_GE(times[StepPhase::Stems], kTimedStepEvery * 2e-3);
    EXPECT_LE(times[StepPhase::Stems], kTimedStepEvery * wall);
}

// The phases are a sample of the steps (one in kTimedStepEvery) scaled up, which
// OneStepInEveryFewIsTimedForAllOfThem checks against a clock it controls; against the run's wall
// time they are not asserted: a timed step the scheduler interrupts counts kTimedStepEvery times, so
// a paused test process moves their sum either way. Printed for reading. The block hits the tree, so
// the stems' phase and the block/stem contacts took time.
TEST(StepPhases, EveryPhaseIsTimedAndTheTreeIsStepped) {
    const Scene scene(loadScene(std::string(SYLVAROCK_DATA) + "/scenes/single-tree.ini", {"stop.max_time_s=3"}));
    const auto t0 = std::chrono::steady_clock::now();
    const RunResult r = simulateBlock(scene, 0, 1);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("phases %.3f s against the run's %.3f s of wall time\n", r.phases.total(), wall);
    ASSERT_FALSE(r.impacts.empty());
    for (const double s : r.phases.seconds) EXPECT_GE(s, 0.0);
    EXPECT_GT(r.phases[StepPhase::Stems], 0.0);
    EXPECT_GT(r.phases[StepPhase::BlockStem], 0.0);
}

// One stem is stepped while the block touches it and after it leaves, first for forest.sleep_after_s:
// each count is a multiple of its node count, the touches at most one per step; a lone tree leans on
// no neighbour; without a forest there is nothing to count.
TEST(StepPhases, NodeStepsCountTheStemsWorkByWhatKeptItAwake) {
    const Scene scene(loadScene(std::string(SYLVAROCK_DATA) + "/scenes/single-tree.ini", {"stop.max_time_s=3"}));
    const RunResult r = simulateBlock(scene, 0, 1);
    ASSERT_EQ(r.impacts.size(), 1u);
    const SceneConfig& cfg = scene.config();
    const std::uint64_t nodes = Stem(beechStem(cfg.tree.dbhCm), cfg.stem, Vec3::Zero(), StemFoot::RootSpring).nodeCount();
    EXPECT_GT(r.nodeSteps[StemAwake::Touched], 0u);
    EXPECT_GT(r.nodeSteps[StemAwake::Waiting], 0u);
    EXPECT_EQ(r.nodeSteps[StemAwake::Leaning], 0u);
    for (const std::uint64_t n : r.nodeSteps.byReason) EXPECT_EQ(n % nodes, 0u);
    // The scene's 25 cm stem at 15 m/s breaks (its top snaps, docs/model-stems.md) and its pieces
    // fall on the soil: both shares are counted, each within the total.
    EXPECT_GT(r.nodeSteps.broken, 0u);
    EXPECT_GT(r.nodeSteps.onSoilOrStem, 0u);
    EXPECT_LE(r.nodeSteps.broken, r.nodeSteps.total());
    EXPECT_LE(r.nodeSteps.onSoilOrStem, r.nodeSteps.total());
    EXPECT_EQ(r.nodeSteps.broken % nodes, 0u);
    EXPECT_LE(r.nodeSteps.total(), static_cast<std::uint64_t>(r.steps) * nodes);
    const Scene bare(loadScene(std::string(SYLVAROCK_DATA) + "/scenes/no-forest.ini", {"stop.max_time_s=3"}));
    EXPECT_EQ(simulateBlock(bare, 0, 1).nodeSteps.total(), 0u);
}

// The paper's 30 cm tree struck at 10 m/s, its pieces let go as in a forest (piece_max_time_s = 0),
// with a horizon of 0.1 s instead of its scene's (never): the block rolls on slowly, near enough to
// keep the tree from sleeping but, soon, not near enough to reach it within 0.1 s, so the tree stops
// where it stands, is stepped for less, and what it still moved with is booked as left vibrating.
// The block stops where it did, within what the run resolves of a stop (stop.rest_distance_m).
TEST(StepPhases, AStemTheBlockCannotReachStopsBeingStepped) {
    const std::string ini = std::string(SYLVAROCK_DATA) + "/scenes/single-tree.ini";
    const std::vector<std::string> sets{"stop.max_time_s=3", "stem.parameters=toe2018", "tree.dbh_cm=30", "block.speed_m_s=10",
                                        "forest.piece_max_time_s=0"};
    std::vector<std::string> resting = sets;
    resting.push_back("forest.return_horizon_s=0.1");
    const RunResult followed = simulateBlock(Scene(loadScene(ini, sets)), 0, 1);
    const RunResult rested = simulateBlock(Scene(loadScene(ini, resting)), 0, 1);
    EXPECT_LT(rested.nodeSteps.total(), followed.nodeSteps.total());
    EXPECT_GT(rested.forestEnergy.frozen, 0.0);
    EXPECT_LT((rested.stop - followed.stop).norm(), SceneConfig{}.stop.restDistance);
}

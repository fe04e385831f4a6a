// A run's result crosses an MPI message whole (RunResultMessage): what `simulate` on several ranks
// writes is what one process writes, its impacts, breaks and trajectory included. Every field is
// compared with what was sent, so a field that put() and getRunResult() both forget fails here too.
#include <gtest/gtest.h>

#include <cstring>

#include "RunResultMessage.hpp"

using namespace sylva;

namespace {

dem::RunResult aResult() {
    dem::RunResult r;
    r.run = 7;
    r.seed = 123456789;
    r.release = {1, 2, 3};
    r.stop = {300, -4, -150};
    r.runoutAlongSlope = 350.5;
    r.runoutHorizontal = 301.25;
    r.energyLineDeg = 28.5;
    r.reason = dem::StopReason::Rest;
    r.maxSpeed = 17.5;
    r.meanSpeed = 9.25;
    r.maxBounce = 1.5;
    r.duration = 41.5;
    r.cpuSeconds = 0.75;
    r.steps = 123456;
    r.meanDt = 3.4e-4;
    r.energy.initialTotal = 1e6;
    r.energy.flagged = true;
    r.forestEnergy.rupture = 1234.5;
    dem::TreeImpact i;
    i.tree = 42;
    i.time = 3.25;
    i.energyBefore = 5e4;
    i.stemBreaks = 3;
    r.impacts = {i, i};
    r.impacts[1].tree = 43;
    r.breaks = {{42, 3.3, 4.5, 0.08}, {42, 3.31, 9.75, 0.02}, {43, 7.5, 0.25, 0.3}};
    r.trajectory = {{0.5, {1, 2, 3}, {4, 5, 6}, {7, 8, 9}, 10, 11}};
    r.failure = "integration.dt_s above the stable limit";
    return r;
}

}  // namespace

TEST(RunResultMessage, AResultCrossesWhole) {
    const dem::RunResult sent = aResult();
    assess::ByteWriter w;
    assess::put(w, sent);
    const std::string bytes = w.take();
    assess::ByteReader in(bytes);
    const dem::RunResult got = assess::getRunResult(in);
    EXPECT_NO_THROW(in.end());

    EXPECT_EQ(got.run, sent.run);
    EXPECT_EQ(got.seed, sent.seed);
    EXPECT_EQ(got.release, sent.release);
    EXPECT_EQ(got.stop, sent.stop);
    EXPECT_EQ(got.runoutAlongSlope, sent.runoutAlongSlope);
    EXPECT_EQ(got.runoutHorizontal, sent.runoutHorizontal);
    EXPECT_EQ(got.energyLineDeg, sent.energyLineDeg);
    EXPECT_EQ(got.reason, sent.reason);
    EXPECT_EQ(got.maxSpeed, sent.maxSpeed);
    EXPECT_EQ(got.meanSpeed, sent.meanSpeed);
    EXPECT_EQ(got.maxBounce, sent.maxBounce);
    EXPECT_EQ(got.duration, sent.duration);
    EXPECT_EQ(got.cpuSeconds, sent.cpuSeconds);
    EXPECT_EQ(got.steps, sent.steps);
    EXPECT_EQ(got.meanDt, sent.meanDt);
    EXPECT_EQ(got.energy.initialTotal, sent.energy.initialTotal);
    EXPECT_EQ(got.energy.flagged, sent.energy.flagged);
    EXPECT_EQ(got.forestEnergy.rupture, sent.forestEnergy.rupture);
    ASSERT_EQ(got.impacts.size(), sent.impacts.size());
    for (std::size_t k = 0; k < sent.impacts.size(); ++k) {
        EXPECT_EQ(got.impacts[k].tree, sent.impacts[k].tree) << k;
        EXPECT_EQ(got.impacts[k].time, sent.impacts[k].time) << k;
        EXPECT_EQ(got.impacts[k].stemBreaks, sent.impacts[k].stemBreaks) << k;
    }
    ASSERT_EQ(got.breaks.size(), sent.breaks.size());
    for (std::size_t k = 0; k < sent.breaks.size(); ++k)
        EXPECT_EQ(std::memcmp(&got.breaks[k], &sent.breaks[k], sizeof(dem::StemBreak)), 0) << k;
    ASSERT_EQ(got.trajectory.size(), 1u);
    EXPECT_EQ(got.trajectory[0].velocity, sent.trajectory[0].velocity);
    EXPECT_EQ(got.trajectory[0].rotationalEnergy, sent.trajectory[0].rotationalEnergy);
    EXPECT_EQ(got.failure, sent.failure);
}

// A message cut anywhere is refused, not read into a short or garbled result.
TEST(RunResultMessage, ACutMessageIsRefused) {
    assess::ByteWriter w;
    assess::put(w, aResult());
    const std::string bytes = w.take();
    for (const std::size_t keep : {std::size_t{0}, bytes.size() / 3, bytes.size() / 2, bytes.size() - 1}) {
        const std::string cut = bytes.substr(0, keep);
        assess::ByteReader in(cut);
        EXPECT_THROW(
            {
                assess::getRunResult(in);
                in.end();
            },
            std::runtime_error)
            << keep << " of " << bytes.size() << " bytes";
    }
}

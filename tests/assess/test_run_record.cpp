// A run as an MPI rank sends it to the coordinator (libassess/RunRecord.hpp): one line of text that
// reads back to the very same numbers, or is refused if garbled.
#include <gtest/gtest.h>

#include <cmath>

#include "libassess/RunRecord.hpp"

using sylva::assess::formatRunLine;
using sylva::assess::parseRunLine;
using sylva::assess::RunRecord;

namespace {
RunRecord record() {
    RunRecord r;
    r.run = 4;
    r.seed = 4294967295u;  // the largest run seed (dem::runSeed keeps 32 bits)
    r.runoutM = 300.0 + 4 / 3.0;
    r.stopY = 100.0 / 7.0;
    r.stopZ = -1e-300;
    r.treeImpacts = 4;
    r.reason = "rest";
    return r;
}
}  // namespace

TEST(RunLineParser, ReadsBackTheSameNumbers) {
    const auto back = parseRunLine(formatRunLine(record()));
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(back->seed, record().seed);
    EXPECT_EQ(back->runoutM, record().runoutM);  // bit for bit: 17 significant digits
    EXPECT_EQ(back->stopY, record().stopY);
    EXPECT_EQ(back->stopZ, record().stopZ);
}

// A run that stopped on a numerical error has no run-out (NaN) and reads back as such.
TEST(RunLineParser, FailedRunReadsBackWithoutRunout) {
    RunRecord r = record();
    r.reason = "failed";
    r.runoutM = r.runoutHorizontalM = r.stopX = r.stopY = r.stopZ = r.energyLineDeg = std::nan("");
    const auto back = parseRunLine(formatRunLine(r));
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(back->reason, "failed");
    EXPECT_TRUE(std::isnan(back->runoutM));
    r.reason = "exploded";  // not a stop reason: the line is refused
    EXPECT_FALSE(parseRunLine(formatRunLine(r)).has_value());
}

TEST(RunLineParser, RefusesAGarbledLine) {
    std::string line = formatRunLine(record());
    line[line.find("rest")] = 'R';
    EXPECT_FALSE(parseRunLine(line).has_value());
    EXPECT_FALSE(parseRunLine("").has_value());
}

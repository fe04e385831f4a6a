// Run logs (libassess/RunLog.hpp): what a kill or a damaged disk leaves behind is detected and
// dropped, everything else reads back to the very same numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "libassess/RunLog.hpp"
#include "libdem/Campaign.hpp"
#include "libstand/InputError.hpp"

namespace fs = std::filesystem;
using sylva::assess::RunLog;
using sylva::assess::RunRecord;

namespace {

constexpr std::uint64_t kSeed = 99;

RunRecord record(int run) {
    RunRecord r;
    r.run = run;
    r.seed = sylva::dem::runSeed(kSeed, run);
    r.runoutM = 300.0 + run / 3.0;  // not representable in a short decimal: exercises the round trip
    r.runoutHorizontalM = 250.1 + run;
    r.stopX = 389.123456789012345;
    r.stopY = 100.0 / 7.0;
    r.stopZ = -1e-300;
    r.energyLineDeg = 30.5;
    r.maxSpeed = 14.25;
    r.treeImpacts = run;
    r.reason = "rest";
    return r;
}

class RunLogReader : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("sylvarock-runlog-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        path_ = (dir_ / "c.csv").string();
    }
    void TearDown() override { fs::remove_all(dir_); }
    void writeThree() {
        std::vector<std::string> notes;
        RunLog log(path_, 5, kSeed, notes);
        for (int run : {0, 2, 1}) log.append(record(run));
    }
    std::string text() const {
        std::ifstream in(path_, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    }
    void setText(const std::string& t) const { std::ofstream(path_, std::ios::binary | std::ios::trunc) << t; }
    fs::path dir_;
    std::string path_;
};

TEST_F(RunLogReader, ReadsBackTheSameNumbers) {
    writeThree();
    std::vector<std::string> notes;
    RunLog log(path_, 5, kSeed, notes);
    EXPECT_TRUE(notes.empty());
    ASSERT_EQ(log.records().size(), 3u);
    EXPECT_EQ(log.missingRuns(), (std::vector<int>{3, 4}));
    for (int run : {0, 1, 2}) {
        const RunRecord& r = log.records().at(run);
        EXPECT_EQ(r.runoutM, record(run).runoutM);  // bit for bit: 17 significant digits
        EXPECT_EQ(r.stopY, record(run).stopY);
        EXPECT_EQ(r.stopZ, record(run).stopZ);
        EXPECT_EQ(r.treeImpacts, run);
        EXPECT_EQ(r.reason, "rest");
    }
}

TEST_F(RunLogReader, DropsALineCutByAKillAndRewritesTheFile) {
    writeThree();
    const std::string whole = text();
    setText(whole.substr(0, whole.size() - 20));  // the last line lost its end (and newline)
    std::vector<std::string> notes;
    {
        RunLog log(path_, 5, kSeed, notes);
        EXPECT_EQ(log.missingRuns(), (std::vector<int>{1, 3, 4}));
        ASSERT_EQ(notes.size(), 1u);
        EXPECT_NE(notes[0].find(path_ + ":4"), std::string::npos) << notes[0];
        log.append(record(1));
    }
    // The cut line is gone before the new one is appended: a clean log of three runs remains.
    notes.clear();
    RunLog again(path_, 5, kSeed, notes);
    EXPECT_TRUE(notes.empty());
    EXPECT_EQ(again.records().size(), 3u);
    EXPECT_EQ(text(), whole.substr(0, whole.find('\n', whole.find('\n', whole.find('\n') + 1) + 1) + 1) +
                          sylva::assess::formatRunLine(record(1)) + "\n");
}

TEST_F(RunLogReader, DropsALineWhoseChecksumFails) {
    writeThree();
    std::string t = text();
    t[t.find("rest")] = 'R';  // "Rest": one byte changed in the second line
    setText(t);
    std::vector<std::string> notes;
    RunLog log(path_, 5, kSeed, notes);
    EXPECT_EQ(log.records().size(), 2u);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("checksum"), std::string::npos);
}

TEST_F(RunLogReader, RefusesARunOutsideTheCampaign) {
    writeThree();
    std::vector<std::string> notes;
    try {
        RunLog log(path_, 2, kSeed, notes);  // run 2 cannot belong to a campaign of 2 runs
        FAIL() << "expected an InputError";
    } catch (const sylva::InputError& e) {
        EXPECT_NE(std::string(e.what()).find(path_ + ":3"), std::string::npos) << e.what();
    }
}

TEST_F(RunLogReader, RefusesAnotherCampaignsSeedsAndAForeignFile) {
    writeThree();
    std::vector<std::string> notes;
    EXPECT_THROW(RunLog(path_, 5, kSeed + 1, notes), sylva::InputError);
    setText("x,z\n0,1\n");
    EXPECT_THROW(RunLog(path_, 5, kSeed, notes), sylva::InputError);
}

}  // namespace

// A run that stopped on a numerical error is stored as failed (so a resumed campaign does not run
// it again), its missing run-out as NaN, and reads back as such.
TEST(RunLineParser, FailedRunReadsBackWithoutRunout) {
    RunRecord r = record(4);
    r.reason = "failed";
    r.runoutM = r.runoutHorizontalM = r.stopX = r.stopY = r.stopZ = r.energyLineDeg = std::nan("");
    const auto back = sylva::assess::parseRunLine(sylva::assess::formatRunLine(r));
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(back->reason, "failed");
    EXPECT_TRUE(std::isnan(back->runoutM));
    EXPECT_EQ(back->seed, r.seed);
    r.reason = "exploded";  // not a stop reason: the line is refused
    EXPECT_FALSE(sylva::assess::parseRunLine(sylva::assess::formatRunLine(r)).has_value());
}

// The campaign store (libassess/CampaignStore.hpp): runs and forest statistics read back to the very
// same numbers; what an edit or a damaged disk leaves behind is detected, and either run again or
// refused naming the store. The damage is done with SQL, as a user with sqlite3 would.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

#include "libassess/CampaignStore.hpp"
#include "libdem/Campaign.hpp"
#include "ShortCampaign.hpp"
#include "StoreEdit.hpp"
#include "libcommon/InputError.hpp"

namespace fs = std::filesystem;
using namespace sylva::assess;

namespace {

bool mentions(const std::vector<std::string>& notes, const std::string& text) {
    for (const auto& n : notes)
        if (n.find(text) != std::string::npos) return true;
    return false;
}

class CampaignStoreFile : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("sylvarock-store-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        design_ = shortCampaign(dir_, 5, 1, 3, 99).design;
        plan_ = planCampaigns(design_);  // baseline, GR1_A_001, GR1_NA_001
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::unique_ptr<CampaignStore> open(bool resume) const {
        return std::make_unique<CampaignStore>(dir_.string(), design_, plan_, resume);
    }
    RunRecord record(std::size_t campaign, int run) const {
        RunRecord r;
        r.run = run;
        r.seed = sylva::dem::runSeed(plan_[campaign].runSeed, run);
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
    static ForestSummary forest() {
        ForestSummary f;
        f.stems = 1234;
        f.stemsPerHa = 1234.0 / 3.0;
        f.basalAreaM2Ha = 35.1;
        f.meanDbhCm = 21.7;
        f.sdDbhCm = 8.9;
        f.clarkEvans = 0.5895;
        return f;
    }
    // Runs 0, 2 and 1 of GR1_A_001 (campaign 1), its forest's statistics with the first.
    void writeThree() const {
        auto store = open(false);
        const ForestSummary f = forest();
        store->save(1, record(1, 0), &f);
        store->save(1, record(1, 2));
        store->save(1, record(1, 1));
    }
    std::string db() const { return (dir_ / CampaignStore::kFileName).string(); }

    fs::path dir_;
    AssessmentDesign design_;
    std::vector<Campaign> plan_;
};

}  // namespace

TEST_F(CampaignStoreFile, ReadsBackTheSameNumbers) {
    writeThree();
    auto store = open(true);
    EXPECT_TRUE(store->resumed());
    EXPECT_TRUE(store->notes().empty());
    ASSERT_EQ(store->runs(1).size(), 3u);
    EXPECT_EQ(store->missingRuns(1), (std::vector<int>{3, 4}));
    EXPECT_EQ(store->missingRuns(0), (std::vector<int>{0, 1, 2}));
    for (int run : {0, 1, 2}) {
        const RunRecord& r = store->runs(1).at(run);
        EXPECT_EQ(r.runoutM, record(1, run).runoutM);  // bit for bit: SQLite keeps IEEE doubles
        EXPECT_EQ(r.stopY, record(1, run).stopY);
        EXPECT_EQ(r.stopZ, record(1, run).stopZ);
        EXPECT_EQ(r.seed, record(1, run).seed);
        EXPECT_EQ(r.treeImpacts, run);
        EXPECT_EQ(r.reason, "rest");
    }
    ASSERT_TRUE(store->forest(1).has_value());
    EXPECT_EQ(store->forest(1)->stemsPerHa, forest().stemsPerHa);
    EXPECT_FALSE(store->forest(2).has_value());
}

// A failed run keeps no run-out: NaN goes in as NULL and comes back as NaN, its checksum intact.
TEST_F(CampaignStoreFile, AFailedRunReadsBackWithoutRunout) {
    {
        auto store = open(false);
        RunRecord r = record(0, 1);
        r.reason = "failed";
        r.runoutM = r.runoutHorizontalM = r.energyLineDeg = std::nan("");
        r.stopX = -std::nan("");  // the sign of a NaN is not kept, nor needed
        store->save(0, r);
    }
    auto store = open(true);
    EXPECT_TRUE(store->notes().empty()) << store->notes().front();
    ASSERT_EQ(store->runs(0).count(1), 1u);
    EXPECT_TRUE(std::isnan(store->runs(0).at(1).runoutM));
    EXPECT_EQ(store->runs(0).at(1).reason, "failed");
}

TEST_F(CampaignStoreFile, DropsAnEditedRunAndRunsItAgain) {
    writeThree();
    editStore(db(), "UPDATE runs SET runout_m = 1.0 WHERE campaign = 'GR1_A_001' AND run = 2");
    {
        auto store = open(true);
        EXPECT_EQ(store->missingRuns(1), (std::vector<int>{2, 3, 4}));
        ASSERT_EQ(store->notes().size(), 1u);
        EXPECT_NE(store->notes()[0].find("GR1_A_001 run 2 fails its checksum"), std::string::npos) << store->notes()[0];
        store->save(1, record(1, 2));  // the row is gone: the run stored again is not a duplicate
    }
    auto store = open(true);
    EXPECT_TRUE(store->notes().empty());
    EXPECT_EQ(store->runs(1).at(2).runoutM, record(1, 2).runoutM);
}

// Issue 13: an edited Clark-Evans index (0.5895 -> 0.5) reached results.json.
TEST_F(CampaignStoreFile, AnEditedForestSummaryIsNotBelieved) {
    writeThree();
    editStore(db(), "UPDATE forests SET clark_evans = 0.5 WHERE campaign = 'GR1_A_001'");
    auto store = open(true);
    EXPECT_FALSE(store->forest(1).has_value());
    EXPECT_TRUE(mentions(store->notes(), "forest statistics of GR1_A_001 fail their checksum"));
    store->saveForest(1, forest());
    EXPECT_EQ(store->forest(1)->clarkEvans, 0.5895);
}

TEST_F(CampaignStoreFile, RefusesRunsThatAreNotThisCampaigns) {
    const std::pair<const char*, const char*> cases[] = {
        {"UPDATE runs SET seed = 1 WHERE run = 1", "has seed 1, not this campaign's"},
        {"UPDATE runs SET run = 7 WHERE run = 1", "GR1_A_001 run 7 is outside this campaign's 5 runs"},
        {"UPDATE design SET text = 'seed = 98' WHERE text = 'seed = 99'", "design line"},
        {"DELETE FROM campaigns WHERE id = 'GR1_NA_001'", "lists 2 campaigns, the design 3"},
        {"PRAGMA user_version = 1", "schema version 1"},
    };
    for (const auto& [sql, message] : cases) {
        fs::remove_all(dir_);
        writeThree();
        editStore(db(), std::string("PRAGMA foreign_keys = OFF; ") + sql);
        try {
            open(true);
            ADD_FAILURE() << sql << ": accepted";
        } catch (const sylva::InputError& e) {
            EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << sql << ": " << e.what();
        }
    }
}

TEST_F(CampaignStoreFile, RefusesAFileThatIsNotADatabase) {
    writeThree();
    fs::remove(db() + "-wal");
    std::ofstream(db(), std::ios::trunc) << "run,seed\n0,1\n";
    try {
        open(true);
        FAIL() << "a text file was taken for a campaign store";
    } catch (const sylva::InputError& e) {
        EXPECT_NE(std::string(e.what()).find(db()), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("not a database"), std::string::npos) << e.what();
    }
}

// The schema, design and plan are one transaction: a store killed before its commit holds none of
// them, and both a new assess and --resume start the campaign afresh in it.
TEST_F(CampaignStoreFile, AStoreWithoutItsDesignStartsAfresh) {
    for (const bool resume : {false, true}) {
        for (const bool emptyFile : {false, true}) {
            fs::remove_all(dir_);
            fs::create_directories(dir_);
            if (emptyFile)
                std::ofstream{db()};
            else
                editStore(db(), "PRAGMA journal_mode = WAL");  // what the store does before its first transaction
            auto store = open(resume);
            EXPECT_FALSE(store->resumed());
            EXPECT_EQ(store->missingRuns(1).size(), 5u);
            EXPECT_EQ(mentions(store->notes(), "holds no campaign yet"), resume);
        }
    }
}

TEST_F(CampaignStoreFile, AFolderOfAnEarlierVersionIsNamedAsSuch) {
    fs::create_directories(dir_ / "runs");
    std::ofstream(dir_ / "design.txt") << "stands = 1\n";
    try {
        open(true);
        FAIL() << "an earlier version's folder was accepted";
    } catch (const sylva::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("earlier sylvarock"), std::string::npos) << e.what();
    }
}

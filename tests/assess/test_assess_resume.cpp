// An assessment campaign (libassess/Assessment.hpp) interrupted anywhere resumes to the very results
// of an uninterrupted one, runs only what is missing, and refuses a directory or design it cannot trust.
// Small campaigns on a short slope, so each takes about a second.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "libassess/Assessment.hpp"
#include "libassess/CampaignPlan.hpp"
#include "libassess/CampaignStore.hpp"
#include "libassess/Report.hpp"
#include "ShortCampaign.hpp"
#include "StoreEdit.hpp"
#include "libcommon/InputError.hpp"

namespace fs = std::filesystem;
using namespace sylva::assess;

namespace {


void spit(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary | std::ios::trunc) << text; }

class AssessResume : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() /
                ("sylvarock-assess-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(root_);
    }
    void TearDown() override { fs::remove_all(root_); }

    AssessmentOptions options(const std::string& out, int threads) const {
        AssessmentOptions o = shortCampaign(root_ / out, 4, 2, 6, 3);
        o.threads = threads;
        o.bootstrapReplicates = 200;
        return o;
    }
    // Runs (or resumes) the campaign and writes results.json; returns how many runs were simulated.
    int assess(AssessmentOptions o) const {
        int simulated = 0;
        o.onRunDone = [&simulated](const std::string&, int, int) { ++simulated; };
        writeResultsJson(o.outDir + "/results.json", runAssessment(o));
        return simulated;
    }
    fs::path root_;
};

TEST_F(AssessResume, InterruptedCampaignResumesToIdenticalResults) {
    EXPECT_EQ(assess(options("whole", 1)), 6 + 2 * 2 * 4);
    EXPECT_EQ(assess(options("cut", 2)), 6 + 2 * 2 * 4);
    const fs::path cut = root_ / "cut";
    // What kills leave: runs never stored, a realisation never started (its forest with it).
    editStore((cut / CampaignStore::kFileName).string(),
              "DELETE FROM runs WHERE campaign = 'GR1_A_001' AND run = 3;"
              "DELETE FROM runs WHERE campaign = 'baseline' AND run >= 4;"
              "DELETE FROM runs WHERE campaign = 'GR1_NA_002'; DELETE FROM forests WHERE campaign = 'GR1_NA_002'");
    fs::remove(cut / "results.json");

    AssessmentOptions resume = options("cut", 2);
    resume.resume = true;
    EXPECT_EQ(assess(resume), 1 + 2 + 4);  // only the missing runs are simulated
    // Byte for byte, whatever the threads (1 then 2) and the interruptions.
    EXPECT_EQ(slurp(cut / "results.json"), slurp(root_ / "whole/results.json"));

    // Resuming a finished campaign simulates nothing and changes nothing.
    EXPECT_EQ(assess(resume), 0);
    EXPECT_EQ(slurp(cut / "results.json"), slurp(root_ / "whole/results.json"));
}

TEST_F(AssessResume, MismatchedDesignIsRefused) {
    assess(options("c", 2));
    AssessmentOptions more = options("c", 2);
    more.resume = true;
    more.design.runs = 5;
    try {
        runAssessment(more);
        FAIL() << "a resume with other runs was accepted";
    } catch (const sylva::InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("campaign.sqlite, design line 4"), std::string::npos) << what;
        EXPECT_NE(what.find("runs_per_realisation = 4"), std::string::npos) << what;
        EXPECT_NE(what.find("runs_per_realisation = 5"), std::string::npos) << what;
    }
    AssessmentOptions otherSeed = options("c", 2);
    otherSeed.resume = true;
    otherSeed.design.seed = 4;
    EXPECT_THROW(runAssessment(otherSeed), sylva::InputError);
    // A line one design has and the other lacks is named alone: it was paired with the next line of the
    // other ("started with 'stem_parameters = calibrated', this one asks for 'scene_set = ...'").
    const auto refusal = [](const AssessmentOptions& o) {
        try {
            runAssessment(o);
        } catch (const sylva::InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    AssessmentOptions withSet = options("c", 2);
    withSet.resume = true;
    withSet.design.sceneOverrides.push_back("soil.friction_deg=35");
    const std::string added = refusal(withSet);
    EXPECT_NE(added.find("this one adds 'scene_set = soil.friction_deg=35', which the campaign there was not started with"), std::string::npos)
        << added;
    AssessmentOptions both = options("c", 2);
    both.resume = true;
    both.design.models.push_back(sylva::dem::Model::Lumped);
    const std::string model = refusal(both);
    EXPECT_NE(model.find("this one adds 'model = lumped'"), std::string::npos) << model;
    // A changed file is said to be one, not left to a pair of fingerprints.
    AssessmentOptions edited = options("c", 2);
    edited.resume = true;
    const auto copy = root_ / "edited_stems.csv";
    std::filesystem::copy_file(edited.design.stands.front().stemsCsv, copy, std::filesystem::copy_options::overwrite_existing);
    std::ofstream(copy, std::ios::app) << "# a note\n";
    edited.design.stands.front().stemsCsv = copy.string();
    const std::string changed = refusal(edited);
    EXPECT_NE(changed.find("stand_stems = "), std::string::npos) << changed;
    EXPECT_NE(changed.find("(the file's contents are not those the campaign began with)"), std::string::npos) << changed;
}

// A lumped-only campaign recorded the DEM's run counts it never used: its results.json reported
// 100 runs per realisation and 1 000 baseline runs, and a resume with another --runs was refused.
TEST_F(AssessResume, ALumpedOnlyCampaignKeepsNoDemRunCounts) {
    AssessmentOptions lumped = options("l", 2);
    lumped.design.models = {sylva::dem::Model::Lumped};
    lumped.design.lumpedRuns = 5;
    lumped.design.lumpedBaselineRuns = 7;
    assess(lumped);
    const std::string json = [&] {
        std::ifstream in(lumped.outDir + "/results.json");
        return std::string(std::istreambuf_iterator<char>(in), {});
    }();
    EXPECT_EQ(json.find("\"runs_per_realisation\""), std::string::npos) << json;
    EXPECT_EQ(json.find("\"baseline_runs\""), std::string::npos) << json;
    EXPECT_NE(json.find("\"lumped_runs_per_realisation\": 5"), std::string::npos) << json;
    AssessmentOptions resumed = lumped;
    resumed.resume = true;
    resumed.design.runs = 7;
    resumed.design.baselineRuns = 9;
    EXPECT_EQ(assess(resumed), 0) << "the DEM's counts are not the lumped campaign's";
    // A store of the old layout (those counts as design lines 4 and 6) resumes too.
    const auto insertLine = [](int at, const std::string& text) {
        return "UPDATE design SET line = -line - 1 WHERE line >= " + std::to_string(at) + "; UPDATE design SET line = -line WHERE line < 0; " +
               "INSERT INTO design (line, text) VALUES (" + std::to_string(at) + ", '" + text + "');";
    };
    editStore(lumped.outDir + "/" + CampaignStore::kFileName,
              insertLine(4, "runs_per_realisation = 100") + insertLine(6, "baseline_runs = 1000"));
    EXPECT_EQ(assess(resumed), 0);
}

// A resume by another build reused the stored runs without a word, though a build that changed the
// model makes other runs of the same seeds (7 of 320 run-outs differed, and PF50 with them). The
// store records the build; a resume by another says so (it is not refused: most builds change no run).
TEST_F(AssessResume, AResumeByAnotherBuildIsSaid) {
    assess(options("c", 2));
    const auto notesOfResume = [&] {
        AssessmentOptions again = options("c", 2);
        again.resume = true;
        std::vector<std::string> notes;
        again.onNote = [&notes](const std::string& n) { notes.push_back(n); };
        EXPECT_EQ(assess(again), 0);
        return notes;
    };
    const auto mentions = [](const std::vector<std::string>& notes, const std::string& what) {
        return std::any_of(notes.begin(), notes.end(), [&](const std::string& n) { return n.find(what) != std::string::npos; });
    };
    EXPECT_FALSE(mentions(notesOfResume(), "made by sylvarock"));
    editStore((root_ / "c" / CampaignStore::kFileName).string(),
              "UPDATE design SET text = '# made by sylvarock 0123abcd' WHERE text LIKE '# made by sylvarock %'");
    const auto notes = notesOfResume();
    EXPECT_TRUE(mentions(notes, "its runs were made by sylvarock build 0123abcd, this is sylvarock build")) << ::testing::PrintToString(notes);
}

TEST_F(AssessResume, NonEmptyOutputWithoutResumeIsRefused) {
    fs::create_directories(root_ / "busy");
    spit(root_ / "busy/notes.txt", "someone's file\n");
    try {
        runAssessment(options("busy", 1));
        FAIL() << "a non-empty --out was accepted";
    } catch (const sylva::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("busy is not empty"), std::string::npos) << e.what();
    }
    AssessmentOptions resume = options("busy", 1);
    resume.resume = true;  // and it is no campaign to resume either
    EXPECT_THROW(runAssessment(resume), sylva::InputError);
    EXPECT_EQ(slurp(root_ / "busy/notes.txt"), "someone's file\n");
}

// Issue 16: a second writer on a campaign folder (a resume started while the job still runs, two MPI
// jobs given the same --out) would mix its runs into the first one's logs; the folder's lock refuses
// it while the first store is open, and lets it in once that store is closed.
TEST_F(AssessResume, AFolderBeingWrittenIsRefusedToASecondWriter) {
    const AssessmentOptions first = options("busy", 1);
    auto open = std::make_unique<CampaignStore>(first.outDir, first.design, planCampaigns(first.design), false);
    AssessmentOptions second = options("busy", 1);
    second.resume = true;
    try {
        runAssessment(second);
        FAIL() << "a second writer was let in";
    } catch (const sylva::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("being written by another sylvarock assess"), std::string::npos) << e.what();
    }
    open.reset();
    EXPECT_EQ(assess(second), 6 + 2 * 2 * 4);
}

// results.json and the report are written while the folder is still locked (the store was closed
// before them, so a resume started meanwhile mixed its intervals into the first one's report).
TEST_F(AssessResume, TheOutputsAreWrittenWhileTheFolderIsLocked) {
    AssessmentOptions first = options("busy", 1);
    bool refused = false, written = false;
    first.writeOutputs = [&](const std::vector<AssessmentResults>& results) {
        AssessmentOptions second = options("busy", 1);
        second.resume = true;
        try {
            runAssessment(second);
        } catch (const sylva::InputError& e) {
            refused = std::string(e.what()).find("being written by another sylvarock assess") != std::string::npos;
        }
        written = !results.empty();
    };
    runAssessment(first);
    EXPECT_TRUE(written);
    EXPECT_TRUE(refused) << "a resume was let in while the outputs were being written";
}

// A campaign all of whose runs failed has no Dist50: the assessment says which, instead of failing
// in the bootstrap ("a realisation without runs") or, for the bare slope, with "Dist50 without forest
// must be positive". A forced step far above the block's stable one on the soil fails every run.
TEST_F(AssessResume, ACampaignWhoseRunsAllFailedIsNamed) {
    AssessmentOptions o = options("failing", 2);
    o.design.sceneOverrides = {"integration.dt_s=1e-2"};
    try {
        runAssessment(o);
        FAIL() << "an assessment without a finished forested run gave results";
    } catch (const CampaignWithoutFinishedRuns& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("all 6 runs of campaign baseline stopped on a numerical error"), std::string::npos) << what;
    }
}

// Issue 13: a forest summary edited on disk (Clark-Evans 0.5895 -> 0.5) went into results.json.
// Its checksum now tells it from the campaign's: --resume computes it again (the forest is its
// seed's) and the results are those of the untouched campaign.
TEST_F(AssessResume, AnEditedForestSummaryIsComputedAgain) {
    assess(options("whole", 2));
    assess(options("edited", 2));
    editStore((root_ / "edited" / CampaignStore::kFileName).string(),
              "UPDATE forests SET clark_evans = 0.5 WHERE campaign = 'GR1_A_001'");
    AssessmentOptions resume = options("edited", 2);
    resume.resume = true;
    std::vector<std::string> notes;
    resume.onNote = [&notes](const std::string& n) { notes.push_back(n); };
    EXPECT_EQ(assess(resume), 0);
    EXPECT_EQ(slurp(root_ / "edited/results.json"), slurp(root_ / "whole/results.json"));
    EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& n) { return n.find("fail their checksum") != std::string::npos; }));
}

}  // namespace


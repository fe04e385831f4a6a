// `sylvarock assess` end to end: a small campaign on a short slope (1 stand, K = 1, M = 4, B = 6) writes
// results.json and the report; bad input is a clear error (exit 2), never a crash.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

class AssessCli : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() /
                ("sylvarock-assess-cli-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(root_);
        fs::create_directories(root_);
    }
    void TearDown() override { fs::remove_all(root_); }
    // Runs the CLI with `args`; returns its exit status, stderr in err_.
    int run(const std::string& args) {
        const fs::path errFile = root_ / "stderr.txt";
        const std::string cmd = std::string(SYLVAROCK_CLI) + " assess " + args + " > " + (root_ / "stdout.txt").string() + " 2> " +
                                errFile.string();
        const int status = std::system(cmd.c_str());
        err_ = slurp(errFile);
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    std::string smallCampaign(const std::string& out, int runs = 4) const {
        return "--stand " + std::string(SYLVAROCK_DATA) + "/stands/GR1 --scene " + std::string(SYLVAROCK_TEST_DATA) +
               "/../assess/data/short-scene.ini --runs " + std::to_string(runs) + " --realisations 1 --baseline-runs 6 --seed 9 --bootstrap 200 --out " +
               (root_ / out).string();
    }
    fs::path root_;
    std::string err_;
};

// A stand of one stem gives forests of almost nothing: assessed, with a warning that says so, and
// its figures drawn without gnuplot's.
TEST_F(AssessCli, AStandOfFewStemsIsWarnedOf) {
    std::ofstream(root_ / "ONE_stems.csv") << "plot,stem,x,y,dbh_cm,species,stool\n1,1,10,10,20,beech,\n";
    std::ofstream(root_ / "ONE_plots.csv") << "plot,xmin,ymin,xmax,ymax\n1,0,0,50,50\n";
    const std::string args = "--stand " + (root_ / "ONE").string() + " --scene " + std::string(SYLVAROCK_TEST_DATA) +
                             "/../assess/data/short-scene.ini --runs 2 --realisations 1 --baseline-runs 2 --seed 9 --bootstrap 200 --out " +
                             (root_ / "out").string();
    ASSERT_EQ(run(args), 0) << err_;
    EXPECT_NE(err_.find("stand ONE: warning: its inventory holds 1 stem(s)"), std::string::npos) << err_;
    // One stand is one value of G, D and N: the figures' range is set, not left to gnuplot to warn about.
    EXPECT_EQ(err_.find("empty x range"), std::string::npos) << err_;
    ASSERT_EQ(run(smallCampaign("gr1")), 0) << err_;
    EXPECT_EQ(err_.find("its inventory holds"), std::string::npos) << err_;
}

// One run gave "PF50 0.740 [0.740, 0.740]": an interval of zero width, read as certainty. Fewer than
// the paper's 100 runs are warned of, model by model; 100 of each are not.
TEST_F(AssessCli, APf50FromFewRunsIsWarnedOf) {
    ASSERT_EQ(run(smallCampaign("few")), 0) << err_;
    EXPECT_NE(err_.find("warning: dem: each PF50 rests on 4 forested run(s) and 6 without forest"), std::string::npos) << err_;
    const auto lumped = [&](int baseline, const std::string& out) {
        return "--stand " + std::string(SYLVAROCK_DATA) + "/stands/GR1 --scene " + std::string(SYLVAROCK_TEST_DATA) +
               "/../assess/data/short-scene.ini --model lumped --realisations 2 --lumped-runs 50 --lumped-baseline-runs " +
               std::to_string(baseline) + " --seed 9 --bootstrap 200 --out " + (root_ / out).string();
    };
    ASSERT_EQ(run(lumped(100, "enough")), 0) << err_;
    EXPECT_EQ(err_.find("rests on"), std::string::npos) << err_;  // 2 forests x 50 runs
    EXPECT_EQ(err_.find("--runs counts"), std::string::npos) << err_;
    // A count for a model the campaign does not run was passed over without a word (--runs 4 with
    // --model lumped ran its 2 000 runs a forest): said, with the count that holds.
    ASSERT_EQ(run(lumped(100, "dem-counts") + " --runs 4 --baseline-runs 6"), 0) << err_;
    EXPECT_NE(err_.find("warning: --runs counts the dem model's runs, which --model lumped does not make; its runs are counted by "
                        "--lumped-runs (50)"),
              std::string::npos) << err_;
    EXPECT_NE(err_.find("warning: --baseline-runs counts the dem model's runs"), std::string::npos) << err_;
    ASSERT_EQ(run(lumped(99, "bare-few")), 0) << err_;
    EXPECT_NE(err_.find("warning: lumped: each PF50 rests on 100 forested run(s) and 99 without forest"), std::string::npos) << err_;
}

// Runs cut by the time limit are lower bounds, and the PF50 built on them too: assess said nothing
// and gave a PF50 of -0.100 from runs that had all hit it. A campaign whose runs all came to rest
// says nothing of it.
TEST_F(AssessCli, RunsCutByTheTimeLimitAreWarnedOf) {
    ASSERT_EQ(run(smallCampaign("cut") + " --set stop.max_time_s=2"), 0) << err_;
    EXPECT_NE(err_.find("warning: dem: of 14 runs, 14 reached the time limit still moving"), std::string::npos) << err_;
    ASSERT_EQ(run(smallCampaign("whole")), 0) << err_;
    EXPECT_EQ(err_.find("reached the time limit"), std::string::npos) << err_;
}

TEST_F(AssessCli, SmallCampaignWritesResultsAndReport) {
    ASSERT_EQ(run(smallCampaign("out")), 0) << err_;
    const std::string json = slurp(root_ / "out/results.json");
    // One row per structure, each with a PF50 inside its interval.
    const std::regex row("\"name\": \"GR1\",\\s*\"structure\": \"(A|NA)\",\\s*\"pf50\": ([-0-9.e]+),\\s*"
                         "\"pf50_ci\": \\[\\s*([-0-9.e]+),\\s*([-0-9.e]+)\\s*\\]");
    int rows = 0;
    for (auto it = std::sregex_iterator(json.begin(), json.end(), row); it != std::sregex_iterator(); ++it, ++rows) {
        const double pf = std::stod((*it)[2]), low = std::stod((*it)[3]), high = std::stod((*it)[4]);
        EXPECT_LE(low, pf) << (*it)[1];
        EXPECT_LE(pf, high) << (*it)[1];
    }
    EXPECT_EQ(rows, 2) << json;
    EXPECT_NE(json.find("\"baseline\""), std::string::npos);
    EXPECT_NE(json.find("\"rank_pf50\""), std::string::npos);
    const std::string report = slurp(root_ / "out/report/report.md");
    EXPECT_NE(report.find("| GR1 |"), std::string::npos) << report;
    for (const char* table : {"stands.csv", "forests.csv", "correlations.csv", "runs.csv"})
        EXPECT_TRUE(fs::exists(root_ / "out/report" / table)) << table;
    // One stand has no correlation: its fields are empty, as results.json's nulls, not "nan".
    const std::string correlations = slurp(root_ / "out/report/correlations.csv");
    EXPECT_EQ(correlations.find("nan"), std::string::npos) << correlations;
    EXPECT_NE(correlations.find("\nA,1,,,,,,\n"), std::string::npos) << correlations;
    // The figures need gnuplot (a declared dependency); without it the report says why they are missing.
    if (std::system("gnuplot --version > /dev/null 2>&1") == 0) {
        for (const char* svg : {"runout_cdf.svg", "pf50.svg", "pf50_dendrometry.svg", "stop_map.svg"}) {
            EXPECT_TRUE(fs::exists(root_ / "out/report" / svg)) << svg;
            EXPECT_NE(report.find(std::string("](") + svg + ")"), std::string::npos) << svg;
        }
    } else {
        EXPECT_NE(report.find("Figures missing"), std::string::npos);
    }
}

TEST_F(AssessCli, SecondRunNeedsResumeAndThenRedoesNothing) {
    ASSERT_EQ(run(smallCampaign("out")), 0) << err_;
    const std::string first = slurp(root_ / "out/results.json");
    EXPECT_EQ(run(smallCampaign("out")), 2);
    EXPECT_NE(err_.find("use --resume"), std::string::npos) << err_;
    ASSERT_EQ(run(smallCampaign("out") + " --resume --threads 1"), 0) << err_;
    EXPECT_NE(err_.find("14 of 14 runs stored"), std::string::npos) << err_;
    EXPECT_EQ(slurp(root_ / "out/results.json"), first);
}

// --set changes the scene for the whole campaign; it is part of the design, so a resume that asks
// for other trees is refused rather than mixing two models in one result.
TEST_F(AssessCli, SceneOverridesArePartOfTheDesign) {
    ASSERT_EQ(run(smallCampaign("out", 2) + " --set stem.parameters=toe2018"), 0) << err_;
    EXPECT_TRUE(std::regex_search(slurp(root_ / "out/results.json"), std::regex("\"scene_set\": \\[\\s*\"stem.parameters=toe2018\"\\s*\\]")));
    EXPECT_NE(slurp(root_ / "out/report/report.md").find("--set stem.parameters=toe2018"), std::string::npos);
    EXPECT_EQ(run(smallCampaign("out", 2) + " --resume"), 2);
    EXPECT_NE(err_.find("stem_parameters"), std::string::npos) << err_;
    EXPECT_EQ(run(smallCampaign("o2", 2) + " --set stem.parameters=toe2017"), 2);
    EXPECT_NE(err_.find("toe2017"), std::string::npos) << err_;
}

// --model both: each model's report in its own folder, the comparison on top, and each model's
// results in results.json (the DEM's at the top level, as with --model dem).
TEST_F(AssessCli, BothModelsReportSideBySide) {
    ASSERT_EQ(run(smallCampaign("out", 2) + " --model both --lumped-runs 30 --lumped-baseline-runs 40"), 0) << err_;
    const std::string json = slurp(root_ / "out/results.json");
    for (const char* key : {"\"model\": \"dem\"", "\"lumped\": {", "\"model\": \"lumped\"", "\"model_comparison\": {",
                            "\"lumped_runs_per_realisation\": 30", "\"p_pf50_basal_area\""})
        EXPECT_NE(json.find(key), std::string::npos) << key;
    const std::string report = slurp(root_ / "out/report/report.md");
    EXPECT_NE(report.find("the two models side by side"), std::string::npos) << report;
    EXPECT_NE(report.find("| GR1 | A |"), std::string::npos) << report;
    for (const char* model : {"dem", "lumped"}) {
        EXPECT_NE(slurp(root_ / "out/report" / model / "report.md").find("| GR1 |"), std::string::npos) << model;
        EXPECT_TRUE(fs::exists(root_ / "out/report" / model / "runs.csv")) << model;
    }
    if (std::system("gnuplot --version > /dev/null 2>&1") == 0) {
        for (const char* svg : {"runout_cdf_models.svg", "pf50_models.svg", "pf50_dendrometry_models.svg"})
            EXPECT_TRUE(fs::exists(root_ / "out/report" / svg)) << svg;
    }
    // The models are part of the design: resuming with one of them only is refused.
    EXPECT_EQ(run(smallCampaign("out", 2) + " --resume"), 2);
    EXPECT_NE(err_.find("model = lumped"), std::string::npos) << err_;
}

TEST_F(AssessCli, BadInputsAreClearErrors) {
    EXPECT_EQ(run("--stand " + (root_ / "nowhere/XX1").string() + " --scene x.ini --out " + (root_ / "o").string()), 2);
    EXPECT_NE(err_.find("XX1_stems.csv does not exist"), std::string::npos) << err_;
    EXPECT_EQ(run(smallCampaign("o", 0)), 2);
    EXPECT_NE(err_.find("--runs must be at least 1"), std::string::npos) << err_;
    EXPECT_EQ(run("--stand " + std::string(SYLVAROCK_DATA) + "/stands/GR1 --stand " + std::string(SYLVAROCK_DATA) +
                  "/stands/GR1 --scene " + std::string(SYLVAROCK_DATA) + "/scenes/no-forest.ini --out " + (root_ / "o").string()),
              2);
    EXPECT_NE(err_.find("given twice"), std::string::npos) << err_;
    EXPECT_EQ(run(smallCampaign("o") + " --model rf3d"), 2);
    EXPECT_NE(err_.find("--model 'rf3d': expected dem"), std::string::npos) << err_;
    EXPECT_EQ(run(smallCampaign("o") + " --model both --lumped-runs 0"), 2);
    EXPECT_NE(err_.find("--lumped-runs must be at least 1"), std::string::npos) << err_;
    EXPECT_EQ(run(smallCampaign("o", 1000000000)), 2);
    EXPECT_NE(err_.find("--runs 1000000000 is above 10000000: a typo?"), std::string::npos) << err_;
    // A stem thinner than the stems' tip diameter (1 cm) cannot be built: named by its inventory line
    // (it was a virtual stem of the first forest, after the store and the runs without forest).
    std::ofstream(root_ / "THIN_stems.csv") << "plot,stem,x,y,dbh_cm,species,stool\n1,1,10,10,20,beech,\n1,2,30,30,0.5,beech,\n";
    std::ofstream(root_ / "THIN_plots.csv") << "plot,xmin,ymin,xmax,ymax\n1,0,0,50,50\n";
    EXPECT_EQ(run("--stand " + (root_ / "THIN").string() + " --scene " + std::string(SYLVAROCK_TEST_DATA) +
                  "/../assess/data/short-scene.ini --runs 2 --realisations 1 --baseline-runs 2 --out " + (root_ / "o").string()),
              2);
    EXPECT_NE(err_.find("THIN_stems.csv:3: stem '2': a DBH of 0.5 cm is below the stems' tip diameter"), std::string::npos) << err_;
    EXPECT_FALSE(fs::exists(root_ / "o"));  // nothing is written before the inputs are known to be good
}

}  // namespace

// Campaigns: same seed, same results whatever the thread count; the CLI's files; and the stand-in
// slope reproducing the paper's Sect. 3.2 without forest.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "../CliRun.hpp"
#include "DemTestScenes.hpp"
#include "libcommon/CsvTable.hpp"
#include "libcommon/InputError.hpp"
#include "libdem/Campaign.hpp"
#include "libdem/CampaignSummary.hpp"

using namespace sylva::dem;

// --runs 2000000000 took 8 GB for the runs' index and then died in the allocator (std::bad_alloc,
// exit 1, or the kernel's killer on a smaller machine): refused before anything is held, with what
// it would take. 2^31 - 1 records of more than a hundred bytes exceed half of any machine this runs on.
TEST(Campaign, RunsBeyondTheMachinesMemoryAreRefusedUpFront) {
    const Scene scene(sylva::dem::testing::straightSlopeScene(30, 120, 40, {"release.x_m=10", "release.y_m=20"}));
    static_assert(sizeof(RunResult) > 100, "the record is larger than this test assumes");
    CampaignOptions o;
    o.runs = std::numeric_limits<int>::max();
    try {
        runCampaign(scene, o);
        ADD_FAILURE() << "accepted";
    } catch (const sylva::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("2147483647 runs"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("GB"), std::string::npos) << e.what();
    }
}

TEST(Campaign, ResultsDoNotDependOnTheNumberOfThreads) {
    const Scene scene(sylva::dem::testing::straightSlopeScene(30, 120, 40, {"release.x_m=10", "release.y_m=20", "stop.max_time_s=6"}));
    CampaignOptions o;
    o.runs = 6;
    o.seed = 42;
    o.threads = 1;
    const auto one = runCampaign(scene, o);
    o.threads = 3;
    const auto three = runCampaign(scene, o);
    ASSERT_EQ(one.size(), three.size());
    for (std::size_t i = 0; i < one.size(); ++i) {
        EXPECT_EQ(one[i].seed, three[i].seed);
        EXPECT_EQ(one[i].stop, three[i].stop);  // bit for bit
        EXPECT_EQ(one[i].steps, three[i].steps);
    }
    EXPECT_NE(one[0].stop, one[1].stop);  // runs do differ (random orientation)
}

// A hazard map's block-volume classes: the scene's block at another volume, its shape kept (a cube's
// or a cuboid's lengths scale with the cube root of the volume ratio), the scene itself untouched.
TEST(Campaign, SceneWithAnotherBlockVolumeScalesItsBlock) {
    const Scene cube(sylva::dem::testing::straightSlopeScene(30, 120, 40, {}));
    const Scene big = cube.withBlockVolume(4.0);
    EXPECT_DOUBLE_EQ(cube.blockTemplate().mass(), 2700 * 0.5);
    EXPECT_DOUBLE_EQ(big.blockTemplate().mass(), 2700 * 4.0);
    EXPECT_NEAR(big.blockTemplate().boundingRadius() / cube.blockTemplate().boundingRadius(), 2.0, 1e-12);  // (4 / 0.5)^(1/3)
    EXPECT_EQ(&big.soil(), &cube.soil());  // the bed is shared, not rebuilt
    const Scene cuboid(sylva::dem::testing::straightSlopeScene(30, 120, 40, {"block.shape=cuboid", "block.d1_m=1.2", "block.d2_m=0.8", "block.d3_m=0.4"}));
    const Scene twice = cuboid.withBlockVolume(2 * 1.2 * 0.8 * 0.4);
    EXPECT_NEAR(twice.config().block.d1 / 1.2, std::cbrt(2.0), 1e-12);
    EXPECT_NEAR(twice.config().block.d3 / twice.config().block.d2, 0.5, 1e-12);
    EXPECT_NEAR(twice.blockTemplate().mass(), 2 * cuboid.blockTemplate().mass(), 1e-9);
    EXPECT_THROW(cube.withBlockVolume(0), sylva::InputError);
}

TEST(Campaign, QuantilesFollowGslsDefinition) {
    EXPECT_DOUBLE_EQ(quantile({3, 1, 2}, 0.5), 2.0);
    EXPECT_DOUBLE_EQ(quantile({4, 1, 2, 3}, 0.5), 2.5);
    EXPECT_DOUBLE_EQ(quantile({0, 10}, 0.25), 2.5);
}

// The forest's energy is summed over the runs that did not fail (a failed run's ledger stops
// mid-run), so that what was left vibrating in stems can be read against what the trees took.
TEST(Campaign, ForestEnergyIsSummedOverTheRunsThatFinished) {
    std::vector<RunResult> runs(3);
    for (int k = 0; k < 3; ++k) {
        runs[k].reason = StopReason::Rest;
        runs[k].runoutAlongSlope = 100 + k;
        runs[k].forestEnergy.bendingPlasticity = 1000 * (k + 1);
        runs[k].forestEnergy.rupture = 10;
        runs[k].forestEnergy.frozen = 100;
        runs[k].forestEnergy.frozenPieces = 60;
    }
    runs[2].reason = StopReason::Failed;
    const CampaignSummary s = summarise(runs);
    EXPECT_DOUBLE_EQ(s.forestEnergy.bendingPlasticity, 3000);
    EXPECT_DOUBLE_EQ(s.forestEnergy.treeTerms(), 3020);
    EXPECT_DOUBLE_EQ(s.forestEnergy.frozen, 200);
    EXPECT_DOUBLE_EQ(s.forestEnergy.frozenPieces, 120);
}

namespace {
std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}
int cli(const std::string& args) { return std::system((std::string(SYLVAROCK_CLI) + " " + args + " >/dev/null 2>&1").c_str()); }
}  // namespace

TEST(SimulateCli, WritesRunsSummaryAndTrajectories) {
    const auto out = std::filesystem::temp_directory_path() / "sylvarock-tests" / "simulate-cli";
    std::filesystem::remove_all(out);
    ASSERT_EQ(cli(std::string("simulate --scene ") + SYLVAROCK_DATA + "/scenes/no-forest.ini --runs 3 --seed 2 --threads 2 "
                  "--trajectory --no-figures --out " + out.string()), 0);
    const std::string runs = slurp((out / "runs.csv").string());
    for (const char* col : {"run", "stop_x", "stop_y", "stop_z", "runout_m", "runout_horizontal_m", "stop_reason",
                            "max_speed_m_s", "max_bounce_m", "duration_s", "cpu_s"})
        EXPECT_NE(runs.substr(0, runs.find('\n')).find(col), std::string::npos) << col;
    EXPECT_EQ(std::count(runs.begin(), runs.end(), '\n'), 4);
    const std::string summary = slurp((out / "summary.json").string());
    for (const char* key : {"\"dist50_m\"", "\"energy_line_deg\"", "\"runs\"", "\"wall_s\""})
        EXPECT_NE(summary.find(key), std::string::npos) << key;
    EXPECT_TRUE(std::filesystem::exists(out / "trajectories" / "run_0002.vtk"));
}

// An --out that cannot be made (a folder under a file; /proc on Linux) was "filesystem error: cannot
// create directories", exit 1, as if the program had failed: it is the user's path, named, exit 2.
// A run cut by stop.max_time_s while the block still moved has a run-out that is a lower bound, as
// one that left the terrain has: said, where it went by as an ordinary result (Dist50 89.1 m).
TEST(SimulateCli, RunsCutByTheTimeLimitAreWarnedOf) {
    const std::string base = std::string("simulate --scene ") + SYLVAROCK_DATA + "/scenes/no-forest.ini --runs 2 --seed 2 --threads 2 --no-figures --out " +
                             (std::filesystem::temp_directory_path() / "sylvarock-simulate-time-limit").string();
    const auto cut = sylva::testing::runCli(base + " --set stop.max_time_s=3");
    ASSERT_EQ(cut.status, 0) << cut.output;
    EXPECT_NE(cut.output.find("warning: 2 of 2 runs reached stop.max_time_s (3 s) still moving"), std::string::npos) << cut.output;
    EXPECT_NE(cut.output.find("and so is Dist50"), std::string::npos) << cut.output;
    const auto whole = sylva::testing::runCli(base);
    ASSERT_EQ(whole.status, 0) << whole.output;
    EXPECT_EQ(whole.output.find("stop.max_time_s"), std::string::npos) << whole.output;
}

TEST(SimulateCli, AnOutFolderThatCannotBeMadeIsNamed) {
    const auto file = std::filesystem::temp_directory_path() / "sylvarock-tests" / "a-file";
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << "not a folder\n";
    const std::string out = (file / "runs").string();
    const sylva::testing::CliRun r = sylva::testing::runCli(std::string("simulate --scene ") + SYLVAROCK_DATA +
                                                            "/scenes/no-forest.ini --runs 1 --no-figures --out " + out);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("cannot create or write"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(file.string()), std::string::npos) << r.output;
}

// simulate wrote over any folder: a bare run into a forested run's folder left that run's
// impacts.csv beside its own runs.csv, and a run into a hazard map's folder replaced its summary.json.
// An earlier simulate run's outputs are now removed first, and another command's folder is refused.
TEST(SimulateCli, AnEarlierRunsOutputsAreReplacedAndAnotherCommandsFolderRefused) {
    const auto out = std::filesystem::temp_directory_path() / "sylvarock-tests" / "simulate-again";
    std::filesystem::remove_all(out);
    const std::string base = std::string("simulate --scene ") + SYLVAROCK_DATA + "/scenes/no-forest.ini --seed 2 --no-figures ";
    ASSERT_EQ(cli(base + "--runs 2 --trajectory --out " + out.string()), 0);
    std::ofstream(out / "impacts.csv") << "run,tree\n0,1\n";  // as a forested run leaves it
    std::ofstream(out / "notes.txt") << "mine\n";
    ASSERT_TRUE(std::filesystem::exists(out / "trajectories" / "run_0001.csv"));
    std::ofstream(out / "trajectories" / "field-survey.gpx") << "mine\n";
    ASSERT_EQ(cli(base + "--runs 1 --out " + out.string()), 0);
    EXPECT_FALSE(std::filesystem::exists(out / "impacts.csv"));
    EXPECT_FALSE(std::filesystem::exists(out / "trajectories" / "run_0001.csv"));
    EXPECT_TRUE(std::filesystem::exists(out / "notes.txt")) << "a file simulate does not write is left alone";
    EXPECT_TRUE(std::filesystem::exists(out / "trajectories" / "field-survey.gpx")) << "in trajectories/ too";
    const std::string runs = slurp((out / "runs.csv").string());
    EXPECT_EQ(std::count(runs.begin(), runs.end(), '\n'), 2);
    // A bad option leaves the earlier outputs where they were.
    EXPECT_NE(cli(base + "--runs 1 --set soil.frction_deg=3 --out " + out.string()), 0);
    EXPECT_TRUE(std::filesystem::exists(out / "runs.csv"));

    std::ofstream(out / "hazard.sqlite") << "";
    EXPECT_EQ(cli(base + "--runs 1 --out " + out.string()), 2 << 8);  // an input error
    EXPECT_TRUE(std::filesystem::exists(out / "runs.csv"));

    // Files of simulate's names that no earlier simulate run wrote (no runs.csv of its own) are the
    // user's: refused, left as they were.
    const auto theirs = out.parent_path() / "simulate-theirs";
    std::filesystem::remove_all(theirs);
    std::filesystem::create_directories(theirs / "trajectories");
    std::ofstream(theirs / "summary.json") << "{\"mine\": 1}\n";
    std::ofstream(theirs / "trajectories" / "events.gpx") << "mine\n";
    EXPECT_EQ(cli(base + "--runs 1 --out " + theirs.string()), 2 << 8);
    EXPECT_EQ(slurp((theirs / "summary.json").string()), "{\"mine\": 1}\n");
    EXPECT_TRUE(std::filesystem::exists(theirs / "trajectories" / "events.gpx"));
    EXPECT_FALSE(std::filesystem::exists(theirs / "runs.csv"));
    // A runs.csv simulate did not write (another tool's, or an older build's columns) is theirs too.
    std::ofstream(theirs / "runs.csv") << "plot,runout\n1,2\n";
    EXPECT_EQ(cli(base + "--runs 1 --out " + theirs.string()), 2 << 8);
    EXPECT_EQ(slurp((theirs / "runs.csv").string()), "plot,runout\n1,2\n");
}

// --only-run runs one run of a campaign again, seeded as in the whole campaign: its row is the
// same as the whole campaign's, field for field but the CPU time.
TEST(SimulateCli, OnlyRunRepeatsThatRunOfTheCampaign) {
    const auto dir = std::filesystem::temp_directory_path() / "sylvarock-tests";
    const std::string base = std::string("simulate --scene ") + SYLVAROCK_DATA + "/scenes/no-forest.ini --runs 3 --seed 5 --no-figures ";
    std::filesystem::remove_all(dir / "only-all");
    std::filesystem::remove_all(dir / "only-one");
    ASSERT_EQ(cli(base + "--out " + (dir / "only-all").string()), 0);
    ASSERT_EQ(cli(base + "--only-run 2 --out " + (dir / "only-one").string()), 0);
    const sylva::CsvTable all = sylva::CsvTable::read((dir / "only-all" / "runs.csv").string());
    const sylva::CsvTable one = sylva::CsvTable::read((dir / "only-one" / "runs.csv").string());
    ASSERT_EQ(all.rows(), 3u);
    ASSERT_EQ(one.rows(), 1u);
    ASSERT_EQ(all.header(), one.header());
    for (std::size_t col = 0; col < all.header().size(); ++col) {
        if (all.header()[col] == "cpu_s") continue;
        EXPECT_EQ(all.text(2, col), one.text(0, col)) << all.header()[col];
    }
    EXPECT_NE(cli(base + "--only-run 3 --out " + (dir / "only-bad").string()), 0);
    EXPECT_NE(cli(base + "--only-run -1 --out " + (dir / "only-bad").string()), 0);
    EXPECT_NE(cli(base + "--only-run 1 --only-run 1 --out " + (dir / "only-bad").string()), 0);
}

TEST(SimulateCli, BadSceneKeyIsRefusedWithItsName) {
    EXPECT_NE(cli(std::string("simulate --scene ") + SYLVAROCK_DATA + "/scenes/no-forest.ini --set soil.frction_deg=3 --out /tmp/x"), 0);
    EXPECT_NE(cli("simulate --scene /nonexistent.ini --out /tmp/x"), 0);
}

// program_options reads "-1" into an unsigned seed as 2^64 - 1 and into --threads as a count: both
// would run, on a seed or a thread count the user never gave (issue 13).
// A seed decides every result: one given twice (a wrapper appending its default) is refused as
// every other repeated option is, not read as the last one.
TEST(SimulateCli, NegativeRepeatedSeedsAndThreadCountsAreRefused) {
    const std::string base = std::string("simulate --scene ") + SYLVAROCK_DATA + "/scenes/no-forest.ini --runs 1 --no-figures ";
    const auto out = std::filesystem::temp_directory_path() / "sylvarock-tests" / "simulate-seed";
    for (const char* bad : {"--seed -1", "--seed 1.5", "--seed 18446744073709551616", "--threads -1", "--seed 1 --seed 2"}) {
        std::filesystem::remove_all(out);
        EXPECT_NE(cli(base + bad + " --out " + out.string()), 0) << bad;
        EXPECT_FALSE(std::filesystem::exists(out / "runs.csv")) << bad;
    }
    EXPECT_EQ(cli(base + "--seed 18446744073709551615 --threads 1 --out " + out.string()), 0);
}

// Boost's option errors loop forever on a value or option holding one of their placeholders
// ('%value%', '%canonical_option%'): the command hung instead of refusing it (tests/fuzz found it).
TEST(SimulateCli, OptionsHoldingBoostPlaceholdersAreRefused) {
    const std::string out = (std::filesystem::temp_directory_path() / "sylvarock-tests" / "simulate-percent").string();
    EXPECT_EQ(WEXITSTATUS(cli("simulate --runs '%value%' --out " + out)), 2);
    EXPECT_EQ(WEXITSTATUS(cli("simulate '--%canonical_option%' 1 --out " + out)), 2);
}

// A whole number too large for a count was "is invalid" and nothing more, as if it were mistyped.
TEST(SimulateCli, ANumberOutOfAnOptionsRangeIsSaidToBe) {
    const std::string out = (std::filesystem::temp_directory_path() / "sylvarock-tests" / "simulate-range").string();
    const auto large = sylva::testing::runCli("simulate --runs 99999999999999 --out " + out);
    EXPECT_EQ(large.status, 2);
    EXPECT_NE(large.output.find("'--runs' is invalid: out of the range this option takes"), std::string::npos) << large.output;
    const auto typo = sylva::testing::runCli("simulate --runs 12x --out " + out);
    EXPECT_EQ(typo.status, 2);
    EXPECT_NE(typo.output.find("'--runs' is invalid"), std::string::npos) << typo.output;
    EXPECT_EQ(typo.output.find("out of the range"), std::string::npos) << typo.output;
}

// A run that goes numerically wrong is kept as failed, with its message, and left out of the
// statistics; the other runs of the campaign still run. Forcing a step 20 times the soil contacts'
// limit makes every run fail at its first landing.
TEST(Campaign, FailedRunsAreKeptNamedAndLeftOutOfTheStatistics) {
    const Scene scene(sylva::dem::testing::straightSlopeScene(30, 120, 40, {"release.x_m=10", "release.y_m=20", "integration.dt_s=0.05"}));
    CampaignOptions o;
    o.runs = 3;
    o.threads = 2;
    int reported = 0;
    o.onRunDone = [&reported](const RunResult&, int, int) { ++reported; };
    const auto results = runCampaign(scene, o);
    ASSERT_EQ(results.size(), 3u);
    EXPECT_EQ(reported, 3);
    for (const auto& r : results) {
        EXPECT_EQ(r.reason, StopReason::Failed);
        EXPECT_NE(r.failure.find("stable limit"), std::string::npos) << r.failure;
        EXPECT_TRUE(std::isnan(r.runoutAlongSlope));
        EXPECT_EQ(r.release.x(), 10.0);
    }
    const CampaignSummary s = summarise(results);
    EXPECT_EQ(s.runs, 3);
    EXPECT_EQ(s.failedRuns, 3);
    EXPECT_EQ(s.stopReasons.at("failed"), 3);
    EXPECT_EQ(s.dist50, 0);  // nothing to take a median of
}

TEST(SimulateCli, FailedRunsGiveTheirOwnExitStatusAndRows) {
    const auto out = std::filesystem::temp_directory_path() / "sylvarock-tests" / "simulate-failed";
    std::filesystem::remove_all(out);
    const int status = cli(std::string("simulate --scene ") + SYLVAROCK_DATA +
                           "/scenes/no-forest.ini --runs 2 --set integration.dt_s=0.05 --no-figures --out " + out.string());
    EXPECT_EQ(WEXITSTATUS(status), 3);  // kRunsFailed: results written, but not a success
    const std::string runs = slurp((out / "runs.csv").string());
    EXPECT_EQ(std::count(runs.begin(), runs.end(), '\n'), 3);
    EXPECT_NE(runs.find(",failed,"), std::string::npos);
    EXPECT_NE(slurp((out / "summary.json").string()).find("\"failed_runs\": 2"), std::string::npos);
}

// A single-tree run that failed used to write an energy.json of zeros, "impacts": 0 and
// "stem_broken": false, which a sweep over DBH and speed reads as a block that missed the tree.
TEST(SimulateCli, AFailedSingleTreeRunSaysSoInItsEnergyFile) {
    const auto out = std::filesystem::temp_directory_path() / "sylvarock-tests" / "single-tree-failed";
    std::filesystem::remove_all(out);
    const int status = cli(std::string("simulate --scene ") + SYLVAROCK_DATA +
                           "/scenes/single-tree.ini --set integration.dt_s=0.05 --no-figures --out " + out.string());
    EXPECT_EQ(WEXITSTATUS(status), 3);
    const std::string energy = slurp((out / "energy.json").string());
    EXPECT_NE(energy.find("\"run_failed\": true"), std::string::npos) << energy;
    EXPECT_NE(energy.find("\"failure\": \"integration.dt_s"), std::string::npos) << energy;
}

// A launch above the tree passes it by: energy.json holds no impact, and the run says so.
TEST(SimulateCli, ALaunchThatMissesTheTreeIsSaid) {
    const auto out = std::filesystem::temp_directory_path() / "sylvarock-tests" / "single-tree-missed";
    std::filesystem::remove_all(out);
    const auto r = sylva::testing::runCli(std::string("simulate --scene ") + SYLVAROCK_DATA +
                                          "/scenes/single-tree.ini --set tree.dbh_cm=20 --set block.impact_height_m=20 --no-figures --out " +
                                          out.string());
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("warning: the block passed the tree without touching it (block.impact_height_m 20 m on a stem 13.9 m tall"),
              std::string::npos)
        << r.output;
    const std::string energy = slurp((out / "energy.json").string());
    EXPECT_NE(energy.find("\"impacts\": 0"), std::string::npos);
    EXPECT_NE(energy.find("\"stem_breaks\": 0"), std::string::npos) << energy;
}

// A stem the block breaks: energy.json counts the connections it lost, at least the one that broke
// and at most all of them (a 15 cm beech, Eq. 11's 11.1 m, is 23 connections at 0.5 m).
TEST(SimulateCli, TheEnergyFileCountsTheConnectionsABrokenStemLost) {
    const auto out = std::filesystem::temp_directory_path() / "sylvarock-tests" / "single-tree-breaks";
    std::filesystem::remove_all(out);
    const auto r = sylva::testing::runCli(std::string("simulate --scene ") + SYLVAROCK_DATA +
                                          "/scenes/single-tree.ini --set tree.dbh_cm=15 --set block.speed_m_s=10 "
                                          "--set stem.node_spacing_m=0.5 --no-figures --out " + out.string());
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string energy = slurp((out / "energy.json").string());
    EXPECT_NE(energy.find("\"stem_broken\": true"), std::string::npos) << energy;
    const std::string key = "\"stem_breaks\": ";
    const auto at = energy.find(key);
    ASSERT_NE(at, std::string::npos) << energy;
    const int breaks = std::stoi(energy.substr(at + key.size()));
    EXPECT_GE(breaks, 1);
    EXPECT_LE(breaks, 23);
    // And each, with when it broke: at least those counted, the impact closed before later ones.
    int listed = 0;
    for (auto k = energy.find("\"time_s\""); k != std::string::npos; k = energy.find("\"time_s\"", k + 1)) ++listed;
    EXPECT_GE(listed, breaks) << energy;
    EXPECT_NE(energy.find("\"diameter_cm\""), std::string::npos) << energy;
}

// With a fracture energy, the impact that stopped on the energy audit at t = 1.04 s when a
// half-broken connection let its node slide 2.2 m sideways (the prototype, opened by |theta|;
// docs/model-stems.md, "A fracture energy"): it runs to its end, and the stem still breaks. Opened by
// plastic work, it runs even without the faces' bound, which ConnectionFracture.* test on their own.
TEST(SimulateCli, AStemWithAFractureEnergyBreaksWithinTheEnergyAudit) {
    const auto out = std::filesystem::temp_directory_path() / "sylvarock-tests" / "single-tree-fracture";
    std::filesystem::remove_all(out);
    const auto r = sylva::testing::runCli(std::string("simulate --scene ") + SYLVAROCK_DATA +
                                          "/scenes/single-tree.ini --set tree.dbh_cm=20 --set block.speed_m_s=10 "
                                          "--set block.impact_height_m=1 --set block.eccentricity=0 "
                                          "--set stem.node_spacing_m=0.5 --set stem.fracture_energy_j_m2=5e4 "
                                          "--no-figures --out " + out.string());
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string energy = slurp((out / "energy.json").string());
    EXPECT_NE(energy.find("\"stem_broken\": true"), std::string::npos) << energy;
}

// Validation (short form; SYLVAROCK_LONG_VALIDATION=1 runs 300 blocks): without forest, the stand-in
// slope and Table 2 give the paper's Sect. 3.2: most blocks stop between 325 and 375 m along the
// slope, energy lines between 25 and 32 deg, bounces mostly under 1 m, speeds of 10-15 m/s.
TEST(ValidationNoForest, StandInSlopeReproducesSection32) {
    const bool longForm = std::getenv("SYLVAROCK_LONG_VALIDATION") != nullptr;
    const Scene scene(loadScene(std::string(SYLVAROCK_DATA) + "/scenes/no-forest.ini"));
    CampaignOptions o;
    o.runs = longForm ? 300 : 60;
    o.seed = 11;
    const auto s = summarise(runCampaign(scene, o));
    EXPECT_GE(s.dist50, 325);
    EXPECT_LE(s.dist50, 375);
    EXPECT_GE(s.energyLine50, 25);
    EXPECT_LE(s.energyLine50, 32);
    EXPECT_GE(s.shareBounceBelow1m, 0.5);  // "mostly <= 1 m"
    EXPECT_GE(s.maxSpeed50, 10);           // top speeds of 10-15 m/s
    EXPECT_LE(s.maxSpeed50, 15);
    EXPECT_EQ(s.stopReasons.count("rest") ? s.stopReasons.at("rest") : 0, o.runs);
    std::printf("Dist50 %.1f m, energy line %.1f deg, max speed median %.1f m/s, bounce <= 1 m %.0f %%\n", s.dist50,
                s.energyLine50, s.maxSpeed50, 100 * s.shareBounceBelow1m);
}

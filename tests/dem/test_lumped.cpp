// The lumped-mass model (docs/lumped.md): free flight, rebounds against hand-computed restitution,
// tree impacts against Dorren & Berger (2006), thread-independence and the calibration on a target.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "../CliRun.hpp"
#include "DemTestScenes.hpp"
#include "libdem/Campaign.hpp"
#include "libdem/LumpedCalibration.hpp"
#include "libdem/LumpedRebound.hpp"
#include "libdem/LumpedRun.hpp"
#include "libdem/LumpedTreeImpact.hpp"
#include "libcommon/InputError.hpp"

using namespace sylva::dem;

namespace {

const std::string kNoForest = std::string(SYLVAROCK_DATA) + "/scenes/no-forest.ini";

double sphereRadius(double volume) { return std::cbrt(3 * volume / (4 * M_PI)); }

}  // namespace

// Soil type 0 (R_n = 0) on flat ground: the sphere falls freely, lands, keeps no velocity and stops
// where it landed (energy line 90 degrees), after the fall time of its lowest point through fall height - radius.
TEST(LumpedRun, FallsFreelyAndStopsOnASoilThatTakesEverything) {
    const Scene scene(sceneFromOverrides({"terrain.profile=" + std::string(SYLVAROCK_DATA) + "/slopes/flat.csv",
                                          "terrain.width_m=20", "release.x_m=30", "release.y_m=10",
                                          "release.fall_height_m=5", "lumped.soil_type=0"}));
    const RunResult r = simulateLumped(scene, 0, 1);
    const double drop = 5 - sphereRadius(0.5);
    EXPECT_NEAR(r.duration, std::sqrt(2 * drop / 9.81), 1e-6);  // the bisection's tolerance is 1e-7 s
    EXPECT_EQ(r.reason, StopReason::Rest);
    EXPECT_NEAR(r.stop.x(), 30, 1e-12);
    EXPECT_NEAR(r.stop.y(), 10, 1e-12);
    EXPECT_NEAR(r.maxSpeed, std::sqrt(2 * 9.81 * drop), 1e-5);
    // It dropped where it was released: no run-out, and the energy line is vertical (it read 0).
    EXPECT_NEAR(r.runoutHorizontal, 0, 1e-12);
    EXPECT_NEAR(r.energyLineDeg, 90, 1e-9);
}

// A block whose sphere (of the block's volume) reaches into the ground at its release landed at once: a
// run-out of 0 m reported as a rest, where the DEM refuses the release. Refused alike, at its depth.
TEST(LumpedRun, ABlockReleasedInsideTheGroundIsRefused) {
    const auto sceneWith = [](const std::string& fallHeight) {
        return Scene(sceneFromOverrides({"terrain.profile=" + std::string(SYLVAROCK_DATA) + "/slopes/flat.csv", "terrain.width_m=20",
                                         "release.x_m=30", "release.y_m=10", "release.fall_height_m=" + fallHeight}));
    };
    // The 0.5 m^3 sphere's radius is 0.49 m: released 0.4 m up, its centre stands 0.4 m above the ground.
    try {
        simulateLumped(sceneWith("0.4"), 0, 1);
        FAIL() << "a block released inside the ground ran";
    } catch (const sylva::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("the block is released inside the ground at (30, 10, 0.4): its sphere of 0.49 m radius "
                                             "reaches 0.09 m below the surface: raise release.fall_height_m"),
                  std::string::npos) << e.what();
    }
    EXPECT_GT(simulateLumped(sceneWith("0.6"), 0, 1).duration, 0);
}

// v = (3, 0, -4) on flat ground, no deviation: the tangential part comes back as R_t = 1/(1 + h/R)
// times itself, the normal part reversed and scaled by R_n drawn in the soil type's range (talus:
// 0.38 +- 0.04); over 20 000 rebounds the mean R_n is the type's mean (uniform draws: standard error
// 0.023/sqrt(20000) = 1.6e-4, the bound is 10 of them).
TEST(LumpedRebound, MatchesTheRestitutionOfTheSoilTypeAndTheObstacle) {
    LumpedParams p;
    p.soilType = 4;
    p.rg70 = p.rg20 = p.rg10 = 0.05;
    p.deviationSdDeg = 0;
    const double radius = 0.5;
    const LumpedRebound rebound(p, radius);
    EXPECT_DOUBLE_EQ(rebound.tangentialRestitution(0.05), 1 / 1.1);
    sylva::SeededRandom rng(3);
    double sum = 0, lo = 1, hi = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        const Vec3 out = rebound.apply(Vec3(3, 0, -4), Vec3::UnitZ(), rng);
        ASSERT_NEAR(out.x(), 3 / 1.1, 1e-12);
        ASSERT_NEAR(out.y(), 0, 1e-12);
        const double rn = out.z() / 4;  // |v_n| = 4 exceeds the obstacle's lift sin(a) R_t |v_t| = 1.1
        sum += rn;
        lo = std::min(lo, rn);
        hi = std::max(hi, rn);
    }
    EXPECT_NEAR(sum / n, 0.38, 1.6e-3);
    EXPECT_GE(lo, 0.34);
    EXPECT_LE(hi, 0.42);
    EXPECT_LT(lo, 0.345);  // the whole range is drawn
    EXPECT_GT(hi, 0.415);
}

// A grazing rebound (no normal velocity) still leaves the ground: the obstacle of height h turns the
// path up by a, cos a = 1 - h/R, and R_n applies to that (rolling as a succession of rebounds).
TEST(LumpedRebound, RollingIsASuccessionOfSmallRebounds) {
    LumpedParams p;
    p.rg70 = p.rg20 = p.rg10 = 0.1;
    p.deviationSdDeg = 0;
    const LumpedRebound rebound(p, 0.5);
    sylva::SeededRandom rng(1);
    const Vec3 out = rebound.apply(Vec3(10, 0, 0), Vec3::UnitZ(), rng);
    const double rt = 1 / 1.2, sinA = std::sqrt(1 - 0.8 * 0.8);
    EXPECT_NEAR(out.x(), 10 * rt, 1e-12);
    EXPECT_GE(out.z(), 0.34 * sinA * 10 * rt);
    EXPECT_LE(out.z(), 0.42 * sinA * 10 * rt);
}

TEST(LumpedTreeImpact, TakesTheEnergyOfDorrenAndBerger2006) {
    LumpedParams p;
    const LumpedTreeImpact impact(p);
    const double e20 = 38.7 * std::pow(20.0, 2.31);  // J, DBH in cm
    EXPECT_NEAR(impact.capacity(0.20), e20, 1e-9 * e20);
    EXPECT_EQ(LumpedTreeImpact::eccentricityShare(0.2), 1.0);
    EXPECT_NEAR(LumpedTreeImpact::eccentricityShare(-0.8), 0.3, 1e-12);
    EXPECT_EQ(LumpedTreeImpact::eccentricityShare(1.0), 0.0);
    sylva::SeededRandom rng(5);
    const double mass = 1350;
    // Twice what the tree takes: half is left, the path turned by at most 22.5 degrees (central).
    const double speed = std::sqrt(2 * 2 * e20 / mass);
    const auto out = impact.apply(Vec3(speed, 0, 0), 0.20, 0.1, 1.0, mass, rng);
    EXPECT_TRUE(out.treeBroken);
    EXPECT_NEAR(0.5 * mass * out.velocity.squaredNorm(), e20, 1e-9 * e20);
    EXPECT_GE(out.velocity.normalized().x(), std::cos(22.5 * M_PI / 180) - 1e-12);
    // Less than it takes: the block stops at the tree.
    const auto stopped = impact.apply(Vec3(0.5 * speed, 0, 0), 0.20, 0.0, 1.0, mass, rng);
    EXPECT_FALSE(stopped.treeBroken);
    EXPECT_EQ(stopped.velocity, Vec3::Zero());
}

// The path turns away from the stem: a block passing on the stem's left (e > 0, left of its direction
// of travel, as ImpactRecorder and firstTouch sign it) turns left, one on its right turns right. The
// turn used to go the other way, sending the block's centre through or across the trunk.
TEST(LumpedTreeImpact, TurnsThePathAwayFromTheStem) {
    LumpedParams p;
    const LumpedTreeImpact impact(p);
    sylva::SeededRandom rng(7);
    const double mass = 1350, speed = 20;  // 270 kJ against the 20 cm stem's 39 kJ
    for (int k = 0; k < 200; ++k)
        for (const double e : {0.2, 0.5, -0.2, -0.5}) {
            const Vec3 out = impact.apply(Vec3(speed, 0, 0), 0.20, e, 1.0, mass, rng).velocity;
            ASSERT_GT(out.x(), 0);
            ASSERT_GE(e * out.y(), 0) << "e " << e << ": turned towards the stem, vy " << out.y();
        }
}

// A block released within reach of a stem, below its top, hits it at once: it used to be counted only
// when entering the stem's reach, so it passed through the trunk unslowed (Dist50 as without trees).
TEST(LumpedRun, ABlockReleasedWithinReachOfAStemHitsIt) {
    sylva::stand::Tree tree;
    tree.id = 1;
    tree.x = 100.2;
    tree.y = 100.3;
    tree.dbhCm = 30;
    tree.heightM = 20;
    sylva::stand::Forest forest;
    forest.trees.push_back(tree);
    const Scene scene(loadScene(kNoForest, {"release.y_m=100", "release.y_min_m=100", "release.y_max_m=100",
                                            "lumped.deviation_sd_deg=0"}),
                      forest);
    ASSERT_NEAR(scene.config().release.x, 100, 1e-9);  // 0.36 m from the stem's axis, within R + DBH/2 = 0.64 m
    const RunResult r = simulateLumped(scene, 0, 3);
    // Released without horizontal speed, it hits the stem as soon as it moves, where it landed.
    ASSERT_EQ(r.impacts.size(), 1u);
    EXPECT_EQ(r.impacts[0].tree, 1);
    EXPECT_LT(r.impacts[0].energyAfter, r.impacts[0].energyBefore);
    EXPECT_DOUBLE_EQ(r.impacts[0].stemHeight, 20);  // impacts.csv stem_height_m (it was 0 for every lumped impact)
    EXPECT_TRUE(std::isnan(r.impacts[0].breakHeight));  // the lumped model does not place a break
    EXPECT_EQ(r.impacts[0].stemBreaks, r.impacts[0].stemBroken ? 1u : 0u);  // and has no pieces
}

TEST(LumpedRun, ResultsDoNotDependOnTheNumberOfThreads) {
    const Scene scene(loadScene(kNoForest, {"release.y_min_m=80", "release.y_max_m=120"}));
    CampaignOptions o;
    o.model = Model::Lumped;
    o.runs = 200;
    o.seed = 9;
    o.threads = 1;
    const auto one = runCampaign(scene, o);
    o.threads = 2;
    const auto two = runCampaign(scene, o);
    for (std::size_t i = 0; i < one.size(); ++i) {
        ASSERT_EQ(one[i].stop, two[i].stop);  // bit for bit
        ASSERT_EQ(one[i].steps, two[i].steps);
    }
    EXPECT_NE(one[0].stop, one[1].stop);
}

// The calibration finds the roughness that made a target: lumped run-outs at rg = 0.12 m (another
// seed) as the "DEM". Dist50 falls by ~30 m per cm of roughness here and its standard error over 600
// runs is ~1 m, so the roughness is found to ~0.5 mm; 5 % is ten times that.
TEST(LumpedCalibration, RecoversTheRoughnessOfATarget) {
    const Scene scene(loadScene(kNoForest, {"lumped.rg70_m=0.12", "lumped.rg20_m=0.12", "lumped.rg10_m=0.12"}));
    CampaignOptions o;
    o.model = Model::Lumped;
    o.runs = 600;
    o.seed = 77;
    std::vector<double> target;
    for (const auto& r : runCampaign(scene, o)) target.push_back(r.runoutAlongSlope);
    LumpedCalibrationOptions c;
    c.runs = 600;
    c.seed = 1;
    const auto fit = calibrateLumped(scene, target, c);
    EXPECT_NEAR(fit.roughness, 0.12, 0.006);
    EXPECT_NEAR(fit.lumpedDist50.value, fit.demDist50.value, 2 * c.tolerance);
    EXPECT_LE(fit.roughnessLow, fit.roughness);
    EXPECT_GE(fit.roughnessHigh, fit.roughness);
}

// A Dist50 known to an interval narrower than the fit's tolerance (0.5 m: here the DEM's run-outs
// evenly spread over 7 m, as tight as the paper's slope makes them) still gives a roughness known to
// an interval, not a single value: the ends used to be found to the fit's tolerance, so both stopped
// at the first roughness within it of the centre.
TEST(LumpedCalibration, ANarrowDist50IntervalGivesARoughnessInterval) {
    const Scene scene(loadScene(kNoForest));
    std::vector<double> target;
    for (int i = 0; i < 600; ++i) target.push_back(412 + 7.0 * i / 599);
    LumpedCalibrationOptions c;
    c.runs = 600;
    c.seed = 1;
    const auto fit = calibrateLumped(scene, target, c);
    std::printf("DEM Dist50 %.2f [%.2f, %.2f] m: roughness %.4f [%.4f, %.4f] m\n", fit.demDist50.value, fit.demDist50.low,
                fit.demDist50.high, fit.roughness, fit.roughnessLow, fit.roughnessHigh);
    ASSERT_LT(fit.demDist50.high - fit.demDist50.low, 2 * c.tolerance);
    EXPECT_LT(fit.roughnessLow, fit.roughnessHigh);
}

// One 20 cm tree 0.4 m beside a straight path (no random turn, release at y = 100 m): the paper's
// reach R + DBH/2 = 0.49 + 0.10 m takes it in, the block's centre alone (DBH/2 = 0.1 m, Rockyfor3D's
// code before v6.0) passes it by; a tree 5 cm off the path is hit either way.
TEST(LumpedRun, TreeReachIsTheBlocksRadiusPlusTheStemsOrTheStemsAlone) {
    const auto impacts = [](const std::string& reach, double offset) {
        sylva::stand::Tree tree;
        tree.id = 1;
        tree.x = 150;
        tree.y = 100 + offset;
        tree.dbhCm = 20;
        tree.heightM = 20;
        sylva::stand::Forest forest;
        forest.trees.push_back(tree);
        const Scene scene(loadScene(kNoForest, {"release.y_m=100", "release.y_min_m=100", "release.y_max_m=100",
                                                "lumped.deviation_sd_deg=0", "lumped.tree_reach=" + reach}),
                          forest);
        return simulateLumped(scene, 0, 3).impacts.size();
    };
    EXPECT_EQ(impacts("block", 0.4), 1u);
    EXPECT_EQ(impacts("centre", 0.4), 0u);
    EXPECT_EQ(impacts("block", 0.05), 1u);
    EXPECT_EQ(impacts("centre", 0.05), 1u);
    EXPECT_THROW(sceneFromOverrides({"lumped.tree_reach=stem"}), sylva::InputError);
}

TEST(LumpedRun, RefusesAnUnknownSoilType) {
    try {
        sceneFromOverrides({"lumped.soil_type=9"});
        FAIL() << "accepted soil type 9";
    } catch (const sylva::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("0 to 7"), std::string::npos) << e.what();
    }
    EXPECT_THROW(sceneFromOverrides({"lumped.rg70_m=-0.1"}), sylva::InputError);
    EXPECT_THROW(parseModel("rf3d"), sylva::InputError);
}

// The lumped soil is calibrated on bare ground: a runs.csv whose blocks hit trees is refused at the
// first such row, before any lumped run.
TEST(LumpedCalibration, RefusesRunOutsShortenedByTrees) {
    const auto dir = std::filesystem::temp_directory_path() / "sylvarock-calibrate-forested";
    std::filesystem::create_directories(dir);
    const std::string runs = (dir / "runs.csv").string();
    std::ofstream out(runs);
    out << "run,runout_m,stop_reason,tree_impacts\n";
    for (int i = 0; i < 120; ++i) out << i << "," << 300 + i << ",rest," << (i == 7 ? 2 : 0) << "\n";
    out.close();
    const auto r = sylva::testing::runCli("calibrate-lumped --scene " + std::string(SYLVAROCK_DATA) + "/scenes/no-forest.ini --dem " + runs);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find(runs + ":9"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("this run hit trees"), std::string::npos) << r.output;
}

// Rows one bare campaign's runs.csv cannot have are refused at their line, before any lumped run: a
// run twice (two files joined), a stop reason simulate never writes, a run-out past any path on the
// scene's bed (another scene's file, or a unit slip). Each was counted into the fit.
TEST(LumpedCalibration, RefusesRowsThatAreNotOneBareCampaigns) {
    const auto dir = std::filesystem::temp_directory_path() / "sylvarock-calibrate-rows";
    std::filesystem::create_directories(dir);
    struct Case {
        int row;
        std::string line, message;
    };
    const Case cases[] = {{5, "3,310,rest,0", "run 3 is also on line 5"},
                          {8, "120,310,stopped,0", "stop reason 'stopped'"},
                          {12, "120,3.1e6,rest,0", "run-out 3.1e6 m: outside 0 to"},
                          {12, "120,-4,rest,0", "run-out -4 m"}};
    for (const Case& c : cases) {
        const std::string runs = (dir / "runs.csv").string();
        std::ofstream out(runs);
        out << "run,runout_m,stop_reason,tree_impacts\n";
        for (int i = 0; i < 120; ++i) out << (i + 1 == c.row ? c.line : std::to_string(i) + "," + std::to_string(300 + i) + ",rest,0") << "\n";
        out.close();
        const auto r = sylva::testing::runCli("calibrate-lumped --scene " + std::string(SYLVAROCK_DATA) + "/scenes/no-forest.ini --dem " + runs);
        EXPECT_EQ(r.status, 2) << r.output;
        EXPECT_NE(r.output.find(runs + ":" + std::to_string(c.row + 1)), std::string::npos) << c.line << ": " << r.output;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << c.line << ": " << r.output;
    }
}

// A campaign released elsewhere (here 100 m further down) was fitted as this scene's: each run's
// release must be one this scene draws, at its x, in its y range, its fall height above its bed.
TEST(LumpedCalibration, RefusesTheRunsOfAnotherScenesRelease) {
    const auto dir = std::filesystem::temp_directory_path() / "sylvarock-calibrate-elsewhere";
    std::filesystem::remove_all(dir);
    const std::string scene = std::string(SYLVAROCK_DATA) + "/scenes/no-forest.ini";
    ASSERT_EQ(sylva::testing::runCli("simulate --scene " + scene + " --set release.x_m=200 --runs 3 --no-figures --out " + dir.string()).status, 0);
    const std::string runs = (dir / "runs.csv").string();
    std::ifstream in(runs);
    std::string header, row, text;
    std::getline(in, header);
    std::getline(in, row);
    text = header + "\n";
    for (int i = 0; i < 120; ++i) text += std::to_string(i) + row.substr(row.find(',')) + "\n";  // the first run, 120 times
    in.close();
    std::ofstream(runs) << text;
    const auto r = sylva::testing::runCli("calibrate-lumped --scene " + scene + " --dem " + runs);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find(runs + ":2: column 'release_x': released at (200.0000, "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("where this scene releases at x = 100 m, y = 100 m, 5 m above its bed"), std::string::npos) << r.output;
}

// A lumped campaign's runs.csv has the DEM's columns: fitted on it, the roughness fitted itself (exit
// 0). simulate's summary.json beside it names the model.
TEST(LumpedCalibration, RefusesTheLumpedModelsOwnRuns) {
    const auto dir = std::filesystem::temp_directory_path() / "sylvarock-calibrate-lumped-runs";
    std::filesystem::remove_all(dir);
    const std::string scene = std::string(SYLVAROCK_DATA) + "/scenes/no-forest.ini";
    ASSERT_EQ(sylva::testing::runCli("simulate --scene " + scene + " --model lumped --runs 120 --no-figures --out " + dir.string()).status, 0);
    const auto r = sylva::testing::runCli("calibrate-lumped --scene " + scene + " --dem " + (dir / "runs.csv").string());
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("these are runs of the lumped model"), std::string::npos) << r.output;
}

std::string writeText(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
    return path;
}

// --write sets the fit's keys and keeps the section's others: the fit was made with them, and the
// scene must give the fitted Dist50 again (they used to be dropped: Dist50 346 m instead of 338.5 m).
// A scene written on Windows keeps its CRLF line ends (the section was appended with LF ones), one from
// an old Mac editor its CR ones.
TEST(LumpedCalibration, WriteKeepsTheSectionsOtherKeysAndTheFilesLineEnds) {
    for (const std::string lineEnd : {"\n", "\r\n", "\r"}) {
        SCOPED_TRACE(lineEnd == "\n" ? "LF" : lineEnd == "\r" ? "CR" : "CRLF");
        const auto dir = std::filesystem::temp_directory_path() / "sylvarock-calibrate-write";
        std::filesystem::create_directories(dir);
        const std::string runs = (dir / "runs.csv").string(), scene = (dir / "scene.ini").string();
        std::ofstream out(runs);
        out << "run,runout_m,stop_reason,tree_impacts\n";
        for (int i = 0; i < 120; ++i) out << i << "," << 330 + 0.1 * i << ",rest,0\n";
        out.close();
        std::ifstream in(kNoForest);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const std::string relative = "../slopes/";  // the scene's profile, relative to data/scenes
        text.replace(text.find(relative), relative.size(), std::string(SYLVAROCK_DATA) + "/slopes/");
        text += "deviation_sd_deg = 8\ntree_reach = centre\n# a note of the user's\n";
        // A fitted key given before any section, with its section's name (and not in the section): replaced
        // too, or the scene would set it twice once the section does, and no longer load.
        const std::string inSection = "\nrg70_m = ";
        const auto at = text.find(inSection);
        ASSERT_NE(at, std::string::npos);
        text.erase(at + 1, text.find('\n', at + 1) - at);
        text = "lumped.rg70_m = 0.05\n" + text;
        std::string ended;
        for (const char c : text) ended += c == '\n' ? lineEnd : std::string(1, c);
        text = ended;
        ASSERT_NO_THROW(loadScene(writeText(scene, text)));
        const auto r = sylva::testing::runCli("calibrate-lumped --scene " + scene + " --dem " + runs + " --runs 200 --write");
        ASSERT_EQ(r.status, 0) << r.output;
        std::ifstream written(scene, std::ios::binary);
        const std::string after((std::istreambuf_iterator<char>(written)), std::istreambuf_iterator<char>());
        for (const char* kept : {"deviation_sd_deg = 8", "tree_reach = centre", "# a note of the user's", "[terrain]"})
            EXPECT_NE(after.find(kept), std::string::npos) << kept << " lost:\n" << after;
        const auto count = [&](const std::string& s) {
            std::size_t n = 0;
            for (auto at = after.find(s); at != std::string::npos; at = after.find(s, at + 1)) ++n;
            return n;
        };
        EXPECT_EQ(count("[lumped]"), 1u) << after;
        EXPECT_EQ(count("rg70_m ="), 1u) << after;
        EXPECT_EQ(count("soil_type ="), 1u) << after;
        EXPECT_EQ(count("# calibrated with:"), 1u) << after;
        const SceneConfig c = loadScene(scene);
        EXPECT_EQ(c.lumped.treeReach, TreeReach::Centre);
        EXPECT_DOUBLE_EQ(c.lumped.deviationSdDeg, 8);
        // Every line end is the file's own: as many of its kind as of either character it is made of.
        const std::size_t ends = count(lineEnd);
        EXPECT_GT(ends, 30u) << after;
        EXPECT_EQ(count("\n"), lineEnd == "\r" ? 0u : ends) << after;
        EXPECT_EQ(count("\r"), lineEnd == "\n" ? 0u : ends) << after;
    }
}


// `sylvarock scene export`: stems.csv holds every stem of the forest at rest, node by node, with the
// cone's radii and the feet on the terrain; a forest file that cannot be read is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../CliRun.hpp"
#include "../WholeFile.hpp"
#include "libstand/Allometry.hpp"

namespace {

using sylva::testing::CliRun;

CliRun sceneExport(const std::string& arguments) { return sylva::testing::runCli("scene export " + arguments); }

struct Node {
    int node, linkedTo;
    double x, y, z, radius;
};

// stems.csv by tree id, nodes in file order.
std::map<long, std::vector<Node>> readStems(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line.substr(0, 32), "tree,node,x,y,z,radius,linked_to");
    std::map<long, std::vector<Node>> stems;
    while (std::getline(in, line)) {
        std::istringstream row(line);
        long tree;
        Node n;
        char comma;
        row >> tree >> comma >> n.node >> comma >> n.x >> comma >> n.y >> comma >> n.z >> comma >> n.radius >> comma >>
            n.linkedTo;
        EXPECT_FALSE(row.fail()) << line;
        stems[tree].push_back(n);
    }
    return stems;
}

std::filesystem::path exportDir() {
    const auto dir = std::filesystem::temp_directory_path() / "sylvarock-tests" / "scene-export";
    std::filesystem::create_directories(dir);
    return dir;
}

// A straight slope 100 m long, 40 m wide, whose surface is z = 0.6 (100 - x). The release must lie on
// it too (export writes run 0's).
double surfaceZ(double x) { return 0.6 * (100 - x); }

std::string slopeScene() {
    const std::string profile = sylva::testfiles::writeWholeFile(exportDir() / "slope.csv", "x,z\n0,60\n100,0\n");
    return sylva::testfiles::writeWholeFile(exportDir() / "slope.ini", "[terrain]\nprofile = " + profile +
                                                                         "\nwidth_m = 40\n[release]\nx_m = 5\ny_min_m = 15\ny_max_m = 25\n");
}

struct ListedTree {
    long id;
    double x, y, dbhCm, heightM;
};
const std::vector<ListedTree> kForest = {{3, 20, 10, 18, 12.0}, {7, 45.5, 22, 30, 17.3}, {9, 70, 31, 41, 20.25}};

std::string forestFile() {
    std::ostringstream out;
    out << "stem,x,y,dbh_cm,height_m\n";
    for (const auto& t : kForest) out << t.id << ',' << t.x << ',' << t.y << ',' << t.dbhCm << ',' << t.heightM << '\n';
    return sylva::testfiles::writeWholeFile(exportDir() / "forest.csv", out.str());
}

}  // namespace

TEST(SceneExportCli, WritesEveryStemAtRestNodeByNode) {
    // stem.node_spacing_m, stem.upper_spacing_factor, stem.struck_zone_m, stem.tip_diameter_m and
    // stem.foot_zone_m (the calibrated set's)
    const double spacing = 0.75, upper = 1.5, struckZone = 4, tip = 0.01, foot = 1;  // upper: 2 x the node spacing
    const std::string out = (exportDir() / "forest-out").string();
    std::filesystem::remove_all(out);
    const CliRun r = sceneExport("--scene " + slopeScene() + " --forest " + forestFile() +
                                 " --set stem.node_spacing_m=0.75 --set stem.upper_spacing_factor=2 --out " + out);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("3 stems"), std::string::npos) << r.output;
    const auto stems = readStems(out + "/stems.csv");
    ASSERT_EQ(stems.size(), kForest.size());
    for (const auto& t : kForest) {
        ASSERT_EQ(stems.count(t.id), 1u) << t.id;
        const auto& nodes = stems.at(t.id);
        // The foot zone's metre in equal connections of at most 0.375 m (three), equal ones of at most
        // 0.75 m up to the crown base (Eq. 12: 7.1, 10.3 and 12.0 m for 12, 17.3 and 20.25 m, all
        // above the 4 m struck zone), then ceil((H - base) / 1.5) equal ones.
        const double zone = std::max(struckZone, t.heightM - sylva::stand::crownLengthM(t.heightM));
        ASSERT_GT(zone, struckZone) << t.id;
        const std::size_t inFoot = static_cast<std::size_t>(std::ceil(foot / (0.5 * spacing)));
        const std::size_t lower = inFoot + static_cast<std::size_t>(std::ceil((zone - foot) / spacing));
        const std::size_t above = static_cast<std::size_t>(std::ceil((t.heightM - zone) / upper));
        const auto restHeight = [&](std::size_t k) {
            if (k <= inFoot) return k * foot / inFoot;
            if (k <= lower) return foot + (zone - foot) * static_cast<double>(k - inFoot) / (lower - inFoot);
            return zone + (t.heightM - zone) * static_cast<double>(k - lower) / above;
        };
        ASSERT_EQ(inFoot, 3u);
        ASSERT_EQ(nodes.size(), lower + above + 1) << t.id;
        // 9 significant digits in the file: 1e-6 m on coordinates below 100 m.
        const double tol = 1e-6;
        EXPECT_NEAR(nodes[0].z, surfaceZ(t.x), tol) << "foot on the surface, tree " << t.id;
        // The cone through the DBH at 1.3 m and the tip diameter at H_T.
        const double dbh = t.dbhCm / 100;
        EXPECT_NEAR(nodes[0].radius, 0.5 * (tip + (dbh - tip) * t.heightM / (t.heightM - 1.3)), tol) << t.id;
        EXPECT_NEAR(nodes.back().radius, 0.5 * tip, tol) << t.id;
        for (std::size_t k = 0; k < nodes.size(); ++k) {
            EXPECT_EQ(nodes[k].node, static_cast<int>(k));
            EXPECT_EQ(nodes[k].linkedTo, static_cast<int>(k) - 1);
            EXPECT_NEAR(nodes[k].x, t.x, tol);
            EXPECT_NEAR(nodes[k].y, t.y, tol);
            EXPECT_NEAR(nodes[k].z, nodes[0].z + restHeight(k), tol);  // standing straight
            if (k > 0) {
                EXPECT_LT(nodes[k].radius, nodes[k - 1].radius) << "tree " << t.id << " node " << k;
            }
        }
    }
}

TEST(SceneExportCli, SingleTreeSceneExportsItsTree) {
    const std::string out = (exportDir() / "single-out").string();
    std::filesystem::remove_all(out);
    const CliRun r = sceneExport("--scene " + std::string(SYLVAROCK_DATA) + "/scenes/single-tree.ini --out " + out);
    ASSERT_EQ(r.status, 0) << r.output;
    const auto stems = readStems(out + "/stems.csv");
    ASSERT_EQ(stems.size(), 1u);
    const auto& nodes = stems.begin()->second;
    ASSERT_GT(nodes.size(), 2u);
    EXPECT_DOUBLE_EQ(nodes[0].x, 20);  // tree.x_m, tree.y_m of the scene, on its flat ground
    EXPECT_DOUBLE_EQ(nodes[0].y, 10);
    EXPECT_DOUBLE_EQ(nodes[0].z, 0);
}

TEST(SceneExportCli, UnreadableForestIsRefusedWithItsName) {
    const std::string missing = (exportDir() / "no-such-forest.csv").string();
    const CliRun r = sceneExport("--scene " + slopeScene() + " --forest " + missing + " --out " + (exportDir() / "bad-out").string());
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("error"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(missing), std::string::npos) << r.output;
}

// A run number a campaign cannot have (runs are numbered by an int) once wrapped to another run's
// release; an action other than export, given as --action, was ignored; a file as --out was a raw
// filesystem error.
TEST(SceneExportCli, ImpossibleRunsActionsAndOutputsAreRefused) {
    const std::string out = " --out " + (exportDir() / "refused").string();
    for (const std::string bad : {"--run 4294967297", "--run 2147483648", "--run -1"}) {
        const CliRun r = sceneExport("--scene " + slopeScene() + " " + bad + out);
        EXPECT_EQ(r.status, 2) << bad << ": " << r.output;
        EXPECT_NE(r.output.find("is not a run of a campaign"), std::string::npos) << r.output;
    }
    const CliRun action = sylva::testing::runCli("scene --action delete --scene " + slopeScene() + out);
    EXPECT_EQ(action.status, 2) << action.output;
    EXPECT_NE(action.output.find("unknown scene action 'delete'"), std::string::npos) << action.output;
    const CliRun file = sceneExport("--scene " + slopeScene() + " --out " + slopeScene());
    EXPECT_EQ(file.status, 2) << file.output;
    EXPECT_NE(file.output.find("is a file, not a folder"), std::string::npos) << file.output;
    EXPECT_FALSE(std::filesystem::exists(exportDir() / "refused"));
}

// A file that cannot be written is named: the block's spheres went unwritten without a word, the
// release and the soil law said "disk full?" of a file that never opened, and a full disk went unseen.
TEST(SceneExportCli, AnOutputThatCannotBeWrittenIsNamed) {
    for (const std::string name : {"soil_spheres.csv", "block_spheres.csv", "release.csv", "soil_contact.csv", "stems.csv"}) {
        const auto out = exportDir() / ("blocked-" + name);
        std::filesystem::remove_all(out);
        std::filesystem::create_directories(out / name);  // a folder where the file should go
        const CliRun r = sceneExport("--scene " + slopeScene() + " --out " + out.string());
        EXPECT_EQ(r.status, 2) << name << ": " << r.output;
        EXPECT_NE(r.output.find((out / name).string() + ": is a folder"), std::string::npos) << name << ": " << r.output;
        // Opened, but every write refused: the small files' failures came only when their buffers
        // were flushed, after the check.
        if (!std::filesystem::exists("/dev/full")) continue;
        std::filesystem::remove_all(out);
        std::filesystem::create_directories(out);
        std::filesystem::create_symlink("/dev/full", out / name);
        const CliRun full = sceneExport("--scene " + slopeScene() + " --out " + out.string());
        EXPECT_EQ(full.status, 2) << name << ": " << full.output;
        EXPECT_NE(full.output.find("write failed"), std::string::npos) << name << ": " << full.output;
    }
}

// What another DEM code needs to rerun simulate's run i (the Yade cross-check, bench/yade): run i's
// release, the solid's mass and inertia, the domain the run ends on leaving, and the block/soil law.
TEST(SceneExportCli, WritesTheReleaseOfTheRunAskedAndTheBlockSoilLaw) {
    const auto dir = std::filesystem::temp_directory_path() / "sylvarock-export-release";
    std::filesystem::remove_all(dir);
    const std::string scene = std::string(SYLVAROCK_DATA) + "/scenes/no-forest.ini";
    const std::string common = "--scene " + scene + " --set terrain.width_m=20 --set release.y_m=10 --seed 4 ";
    ASSERT_EQ(sceneExport(common + "--run 0 --out " + (dir / "r0").string()).status, 0);
    ASSERT_EQ(sceneExport(common + "--run 3 --out " + (dir / "r3").string()).status, 0);
    auto row = [](const std::filesystem::path& p) {
        std::ifstream in(p);
        std::string header, values;
        std::getline(in, header);
        std::getline(in, values);
        std::map<std::string, double> r;
        std::istringstream h(header), v(values);
        for (std::string k, x; std::getline(h, k, ',') && std::getline(v, x, ',');) r[k] = std::stod(x);
        return r;
    };
    const auto r0 = row(dir / "r0/release.csv"), r3 = row(dir / "r3/release.csv");
    EXPECT_NE(r0.at("qw"), r3.at("qw")) << "runs 0 and 3 drew the same orientation";
    EXPECT_NEAR(r0.at("mass_kg"), 1350, 1e-6);                   // 0.5 m^3 at 2700 kg/m^3
    EXPECT_NEAR(r0.at("ixx_kg_m2"), 1350 * std::pow(0.5, 2.0 / 3) / 6, 1e-6);  // cube: m a^2 / 6
    EXPECT_EQ(r0.at("ymin"), 0);
    EXPECT_EQ(r0.at("ymax"), 20);
    const auto law = row(dir / "r0/soil_contact.csv");
    EXPECT_EQ(law.at("kn_n_m"), 1e6);
    EXPECT_EQ(law.at("kt_n_m"), 0.05e6);                                       // Eq. 19
    EXPECT_NEAR(law.at("damping_n_s"), 0.54 * 2 * std::sqrt(1e6 * 1350), 1e-3);  // Eqs. 15-16
    // Refused before any file is written (a release outside the terrain left the soil's and the
    // block's files behind).
    EXPECT_FALSE(sceneExport(common + "--run -1 --out " + (dir / "bad").string()).status == 0);
    EXPECT_FALSE(std::filesystem::exists(dir / "bad"));
    const CliRun outside = sceneExport(common + "--set release.x_m=5000 --out " + (dir / "outside").string());
    EXPECT_EQ(outside.status, 2) << outside.output;
    EXPECT_NE(outside.output.find("--set release.x_m: release point (5000, "), std::string::npos) << outside.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "outside"));
    // A terrain changed on --set under an unchanged release names the terrain, not the release's line.
    const CliRun shorter = sceneExport(common + "--set terrain.profile=" + std::string(SYLVAROCK_DATA) + "/slopes/flat.csv --out " + (dir / "shorter").string());
    EXPECT_EQ(shorter.status, 2) << shorter.output;
    EXPECT_NE(shorter.output.find("--set terrain.profile: release point"), std::string::npos) << shorter.output;
    // What simulate refuses to start is refused too: the block inside the soil, a soil too soft to hold it.
    for (const char* start : {"--set release.fall_height_m=0.1", "--set soil.kn_n_m=1000"}) {
        const CliRun refused = sceneExport(common + start + " --out " + (dir / "unstartable").string());
        EXPECT_EQ(refused.status, 2) << start << "\n" << refused.output;
        // Named by the key typed on --set: the scene file's name led to a line the user had not changed.
        EXPECT_NE(refused.output.find(std::string(start).find("fall") != std::string::npos ? "--set release.fall_height_m: the block is released inside the soil"
                                                                                           : "more than a soil sphere's radius"),
                  std::string::npos) << refused.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "unstartable"));
    }
    // A single-tree launch's velocity goes with the release (another code dropped the block from rest).
    EXPECT_EQ(r0.at("vx_m_s"), 0);
    ASSERT_EQ(sceneExport("--scene " + std::string(SYLVAROCK_DATA) + "/scenes/single-tree.ini --set block.speed_m_s=15 --out " +
                          (dir / "launch").string()).status, 0);
    const auto launch = row(dir / "launch/release.csv");
    EXPECT_EQ(launch.at("vx_m_s"), 15);
    EXPECT_EQ(launch.at("vy_m_s"), 0);
    EXPECT_EQ(launch.at("vz_m_s"), 0);
    std::filesystem::remove_all(dir);
}

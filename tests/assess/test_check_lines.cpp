// Check lines of a hazard run (libassess CheckLines): crossings against hand-computed ones, the reader
// against good and bad files, and the tally's files on hand-made crossings.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "GeoTestFolder.hpp"
#include "libassess/CheckLines.hpp"
#include "libcommon/InputError.hpp"

namespace fs = std::filesystem;
using namespace sylva::assess;
using sylva::dem::TrajectorySample;

namespace {

class CheckLines : public GeoTestFolder {
protected:
    // An ESRI ASCII DTM of 4 x 4 cells of 5 m, south-west corner at the origin: the plane
    // z = 100 - 0.5 x - 0.25 y at the cell centres, which the bilinear surface then is everywhere
    // between them.
    Dtm plane() const {
        std::string text = "ncols 4\nnrows 4\nxllcorner 0\nyllcorner 0\ncellsize 5\nNODATA_value -9999\n";
        for (int r = 0; r < 4; ++r) {
            for (int c = 0; c < 4; ++c) text += std::to_string(100 - 0.5 * (2.5 + 5 * c) - 0.25 * (17.5 - 5 * r)) + " ";
            text += "\n";
        }
        return readDtm(write("plane.asc", text));
    }
    // 6 x 4 cells of 5 m in Lambert-93: x 700000 to 700030, y 6600000 to 6600020.
    Dtm lambert() const {
        std::string text = "ncols 6\nnrows 4\nxllcorner 700000\nyllcorner 6600000\ncellsize 5\nNODATA_value -9999\n";
        for (int r = 0; r < 4; ++r) text += "10 9 8 7 6 5\n";
        write("l93.prj", kLambert93Prj);
        return readDtm(write("l93.asc", text));
    }
    // A GeoJSON FeatureCollection of `features` (each `{"type": "Feature", ...}`), no crs member.
    std::string geojson(const std::string& name, const std::string& features) const {
        return write(name, R"({"type": "FeatureCollection", "features": [)" + features + "]}");
    }
    static std::string feature(const std::string& properties, const std::string& type, const std::string& coordinates) {
        return R"({"type": "Feature", "properties": )" + properties + R"(, "geometry": {"type": ")" + type +
               R"(", "coordinates": )" + coordinates + "}}";
    }
};

TrajectorySample sample(double t, Eigen::Vector3d position, Eigen::Vector3d velocity = Eigen::Vector3d::Zero(), double translationalJ = 0,
                        double rotationalJ = 0) {
    return {t, position, velocity, Eigen::Vector3d::Zero(), translationalJ, rotationalJ};
}

CheckLine line(const std::string& name, std::vector<Eigen::Vector2d> vertices) { return {name, std::move(vertices)}; }

// The step (1, 2) -> (11, 12) meets the line x + y / 2 = 8, drawn from (8, 0) to (0, 16), where
// 1 + 10 s + (2 + 10 s) / 2 = 8: s = 0.4, at (5, 6). There the block's centre is at z = 101 - 0.4 x 5
// = 99 over the plane's 100 - 2.5 - 1.5 = 96 (3 m up), its energy 25 - 0.4 x 15 = 19 kJ, its speed
// 5 + 0.4 x 5 = 7 m/s (the speeds', not the velocities' interpolation: that would give 5 m/s), the
// time 1 + 0.4 x 0.5 = 1.2 s.
TEST_F(CheckLines, CrossingIsInterpolatedWhereTheStepMeetsTheLine) {
    const Dtm d = plane();
    const std::vector<TrajectorySample> path = {sample(1.0, {1, 2, 101}, {3, 4, 0}, 20000, 5000), sample(1.5, {11, 12, 96}, {0, 0, -10}, 10000, 0)};
    for (const auto& l : {line("down", {{8, 0}, {0, 16}}), line("up", {{0, 16}, {8, 0}})}) {
        const auto crossings = crossCheckLines(path, d, {l});
        ASSERT_EQ(crossings.size(), 1u) << l.name;
        const LineCrossing& c = crossings[0];
        EXPECT_EQ(c.line, 0);
        EXPECT_NEAR(c.x, 5, 1e-9);
        EXPECT_NEAR(c.y, 6, 1e-9);
        EXPECT_NEAR(c.heightM, 3, 3e-6);
        EXPECT_NEAR(c.energyKj, 19, 19e-6);
        EXPECT_NEAR(c.speedMs, 7, 7e-6);
        EXPECT_NEAR(c.time, 1.2, 1.2e-6);
    }
}

// Back and forth over x = 5: the first crossing only (a barrier there stops the block). The lines
// come out in their own order, not in the order the block met them.
TEST_F(CheckLines, OnlyTheFirstCrossingOfEachLineCounts) {
    const Dtm d = plane();
    const std::vector<TrajectorySample> path = {sample(0, {1, 5, 100}), sample(1, {9, 5, 100}), sample(2, {1, 6, 100}), sample(3, {9, 6, 100})};
    const auto crossings = crossCheckLines(path, d, {line("lower", {{8, 0}, {8, 20}}), line("upper", {{5, 0}, {5, 20}})});
    ASSERT_EQ(crossings.size(), 2u);
    EXPECT_EQ(crossings[0].line, 0);
    EXPECT_NEAR(crossings[0].time, 0.875, 1e-6);  // x = 1 + 8 t = 8
    EXPECT_NEAR(crossings[0].y, 5, 1e-12);
    EXPECT_EQ(crossings[1].line, 1);
    EXPECT_NEAR(crossings[1].time, 0.5, 1e-6);
    EXPECT_NEAR(crossings[1].y, 5, 1e-12);
}

// A step holds its first sample, not its last: a path ending on the line, or before it, has not
// crossed it; a sample on the line mid-path is the crossing, once.
TEST_F(CheckLines, PathEndingOnOrBeforeALineDoesNotCrossIt) {
    const Dtm d = plane();
    const std::vector<CheckLine> x5 = {line("x5", {{5, 0}, {5, 20}})};
    EXPECT_TRUE(crossCheckLines({sample(0, {1, 5, 100}), sample(1, {5, 5, 100})}, d, x5).empty());
    EXPECT_TRUE(crossCheckLines({sample(0, {1, 5, 100}), sample(1, {4.999, 5, 100})}, d, x5).empty());
    EXPECT_TRUE(crossCheckLines({sample(0, {1, 5, 100})}, d, x5).empty());
    // Past the line's end, and along it.
    EXPECT_TRUE(crossCheckLines({sample(0, {1, 15, 100}), sample(1, {9, 15, 100})}, d, {line("short", {{5, 0}, {5, 10}})}).empty());
    EXPECT_TRUE(crossCheckLines({sample(0, {5, 1, 100}), sample(1, {5, 9, 100})}, d, x5).empty());

    const auto on = crossCheckLines({sample(0, {1, 5, 100}), sample(1, {5, 5, 99}, {2, 0, 0}, 7000), sample(2, {9, 5, 98})}, d, x5);
    ASSERT_EQ(on.size(), 1u);
    EXPECT_EQ(on[0].x, 5);
    EXPECT_EQ(on[0].time, 1);
    EXPECT_EQ(on[0].energyKj, 7);
    EXPECT_EQ(on[0].speedMs, 2);
}

// A bent line: a step crossing it twice gives the crossing first along the step, whatever the
// order of the segments; a step through the vertex two segments share crosses the line once.
TEST_F(CheckLines, BentLineGivesTheFirstCrossingAlongTheStep) {
    const Dtm d = plane();
    const CheckLine u = line("u", {{8, 0}, {8, 10}, {5, 10}, {5, 0}});  // x = 8 is its first segment, x = 5 its last
    const auto through = crossCheckLines({sample(0, {1, 5, 100}), sample(1, {9, 5, 100})}, d, {u});
    ASSERT_EQ(through.size(), 1u);
    EXPECT_NEAR(through[0].x, 5, 1e-12);
    EXPECT_NEAR(through[0].time, 0.5, 1e-6);
    const auto back = crossCheckLines({sample(0, {9, 5, 100}), sample(1, {1, 5, 100})}, d, {u});
    ASSERT_EQ(back.size(), 1u);
    EXPECT_NEAR(back[0].x, 8, 1e-12);

    const CheckLine v = line("v", {{2, 12}, {5, 10}, {8, 12}});
    const auto vertex = crossCheckLines({sample(0, {5, 2, 100}), sample(1, {5, 18, 100})}, d, {v});
    ASSERT_EQ(vertex.size(), 1u);
    EXPECT_NEAR(vertex[0].y, 10, 1e-12);
    // A step meeting the second segment only.
    const auto second = crossCheckLines({sample(0, {7, 10, 100}), sample(1, {7, 13, 100})}, d, {v});
    ASSERT_EQ(second.size(), 1u);
    EXPECT_NEAR(second[0].y, 10 + 2.0 * 2 / 3, 1e-12);
}

// Names from the "name" field, "line <n>" without it (n counting the file's line features), a
// multiline's parts each a line; points passed over, a repeated vertex dropped, and a line crossing
// the DTM with both ends outside it kept.
TEST_F(CheckLines, ReadsNamedAndUnnamedLinesAndMultilineParts) {
    const Dtm d = lambert();
    const std::string named = geojson(
        "named.geojson",
        feature(R"({"name": "crest"})", "LineString", "[[700001, 6600001], [700001, 6600001], [700029, 6600019]]") + ", " +
            feature(R"({"name": "tree"})", "Point", "[700010, 6600010]") + ", " +
            feature(R"({"name": "gully"})", "MultiLineString", "[[[700002, 6600002], [700004, 6600004]], [[700005, 6600005], [700006, 6600006], [700007, 6600005]]]") +
            ", " + feature(R"({"name": null})", "LineString", "[[700003, 6600003], [700008, 6600003]]") + ", " +
            feature(R"({"name": "road"})", "LineString", "[[699990, 6600010], [700040, 6600010]]"));
    int passedOver = -1;
    const auto lines = readCheckLines(named, d, &passedOver);
    ASSERT_EQ(lines.size(), 5u);
    EXPECT_EQ(passedOver, 1);  // the point, for the caller to mention
    EXPECT_EQ(lines[0].name, "crest");
    ASSERT_EQ(lines[0].vertices.size(), 2u);
    EXPECT_EQ(lines[0].vertices[1], Eigen::Vector2d(700029, 6600019));
    EXPECT_EQ(lines[1].name, "gully part 1");
    EXPECT_EQ(lines[2].name, "gully part 2");
    ASSERT_EQ(lines[2].vertices.size(), 3u);
    EXPECT_EQ(lines[2].vertices[2], Eigen::Vector2d(700007, 6600005));
    EXPECT_EQ(lines[3].name, "line 3");
    EXPECT_EQ(lines[4].name, "road");

    const std::string unnamed = geojson("unnamed.geojson", feature("{}", "LineString", "[[700001, 6600001], [700009, 6600009]]") + ", " +
                                                               feature("{}", "MultiLineString", "[[[700002, 6600002], [700004, 6600004]], [[700005, 6600005], [700006, 6600006]]]"));
    const auto plain = readCheckLines(unnamed, d);
    ASSERT_EQ(plain.size(), 3u);
    EXPECT_EQ(plain[0].name, "line 1");
    EXPECT_EQ(plain[1].name, "line 2 part 1");
    EXPECT_EQ(plain[2].name, "line 2 part 2");
    EXPECT_EQ(plain[2].vertices[0], Eigen::Vector2d(700005, 6600005));
}

TEST_F(CheckLines, RefusedInputsSayWhatIsWrong) {
    const Dtm d = lambert();
    const auto refused = [&](const std::string& path) { return errorOf([&] { readCheckLines(path, d); }); };
    const auto expectIn = [](const std::string& message, const std::string& part) {
        EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
    };
    const std::string none = (dir_ / "none.geojson").string();
    expectIn(refused(none), none + ": cannot read it as vector data");

    const std::string points = geojson("points.geojson", feature(R"({"name": "a"})", "Point", "[700010, 6600010]"));
    expectIn(refused(points), points + ": no line in the file");

    // Degrees: GeoJSON's own CRS (WGS 84), not the DTM's.
    const std::string wgs = geojson("wgs.geojson", feature("{}", "LineString", "[[3, 46], [3.1, 46.1]]"));
    expectIn(refused(wgs), "layer 'wgs' is in WGS 84");
    expectIn(refused(wgs), "reproject it");

    const std::string stub = geojson("stub.geojson", feature(R"({"name": "ok"})", "LineString", "[[700001, 6600001], [700009, 6600009]]") + ", " +
                                                         feature(R"({"name": "stub"})", "LineString", "[[700005, 6600005], [700005, 6600005]]"));
    expectIn(refused(stub), stub + ": line 'stub' (layer 'stub', feature 2) has fewer than 2 distinct vertices");

    const std::string far = geojson("far.geojson", feature(R"({"name": "far"})", "LineString", "[[700031, 6600000], [700040, 6600020]]"));
    expectIn(refused(far), far + ": line 'far' (layer 'far', feature 1) lies entirely outside the DTM");
    expectIn(refused(far), "spans x 700000 to 700030, y 6600000 to 6600020");

    const std::string twice = geojson("twice.geojson", feature(R"({"name": "a"})", "LineString", "[[700001, 6600001], [700009, 6600009]]") + ", " +
                                                           feature(R"({"name": "a"})", "LineString", "[[700002, 6600001], [700009, 6600019]]"));
    expectIn(refused(twice), twice + ": two lines are named 'a' (layer 'twice', feature 1 and layer 'twice', feature 2)");
}

// Two passes by hand. Forest: 4 blocks, line "upper" crossed by runs 1 and 3 (10 and 20 kJ, 1 and
// 3 m, 5 and 9 m/s), so fraction 2 / 4 and GSL's percentiles 10 + p x 10 (p95 19.5), 1 + p x 2,
// 5 + p x 4; line "lower, west" by none (empty percentiles). Bare: 1 block, crossing the second line.
TEST_F(CheckLines, TallyWritesEachCrossingAndEachLinesDistribution) {
    CheckLineTally tally({line("upper", {{0, 0}, {1, 0}}), line("lower, west", {{0, 1}, {1, 1}})});
    const auto crossing = [](int l, double x, double y, float e, float h, float v, float t) {
        LineCrossing c;
        c.line = l;
        c.x = x;
        c.y = y;
        c.energyKj = e;
        c.heightM = h;
        c.speedMs = v;
        c.time = t;
        return c;
    };
    tally.add("forest", 0, {});
    tally.add("forest", 1, {crossing(0, 700001.25, 6600002.5, 10, 1, 5, 2)});
    tally.add("forest", 2, {});
    tally.add("forest", 3, {crossing(0, 700003, 6600004.125, 20, 3, 9, 3.5f)});
    tally.setBlocks("forest", 4);
    tally.add("bare", 0, {crossing(1, 700005, 6600006, 0.125f, 0.5f, 1.5f, 7.25f)});
    tally.setBlocks("bare", 1);
    tally.write(dir_.string());
    EXPECT_EQ(read("check_lines.csv"),
              "pass,line,run,x,y,time_s,energy_kj,height_m,speed_m_s\n"
              "forest,upper,1,700001.250,6600002.500,2,10,1,5\n"
              "forest,upper,3,700003.000,6600004.125,3.5,20,3,9\n"
              "bare,\"lower, west\",0,700005.000,6600006.000,7.25,0.125,0.5,1.5\n");
    EXPECT_EQ(read("check_lines_summary.csv"),
              "pass,line,blocks,crossings,fraction,energy_kj_p50,energy_kj_p95,energy_kj_p99,height_m_p50,height_m_p95,height_m_p99,"
              "speed_m_s_p50,speed_m_s_p95,speed_m_s_p99\n"
              "forest,upper,4,2,0.5,15,19.5,19.9,2,2.9,2.98,7,8.8,8.96\n"
              "forest,\"lower, west\",4,0,0,,,,,,,,,\n"
              "bare,upper,1,0,0,,,,,,,,,\n"
              "bare,\"lower, west\",1,1,1,0.125,0.125,0.125,0.5,0.5,0.5,1.5,1.5,1.5\n");

    EXPECT_THROW(tally.add("forest", 3, {}), std::logic_error);  // a run twice: its crossings would count twice
    EXPECT_THROW(tally.add("bare", 1, {crossing(2, 0, 0, 1, 1, 1, 1)}), std::logic_error);  // no line 2
    const std::string missing = (dir_ / "missing").string();
    EXPECT_NE(errorOf([&] { tally.write(missing); }).find(missing + "/check_lines.csv: cannot write"), std::string::npos);
    CheckLineTally uncounted({line("upper", {{0, 0}, {1, 0}})});
    uncounted.add("forest", 0, {});
    EXPECT_THROW(uncounted.write(dir_.string()), std::logic_error);
}

}  // namespace

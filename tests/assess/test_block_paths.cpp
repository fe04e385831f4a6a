// Block paths for GIS and ParaView (libassess BlockPaths): the thinning rule on hand-made samples, the
// impacts placed at their trees on a planar DTM, the GeoPackage read back with OGR, and the VTK files
// parsed back against what was written.
#include <gtest/gtest.h>

#include <ogrsf_frmts.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "GeoTestFolder.hpp"
#include "libassess/BlockPaths.hpp"
#include "libassess/GeoRaster.hpp"
#include "libcommon/InputError.hpp"

namespace fs = std::filesystem;
using namespace sylva::assess;
namespace dem = sylva::dem;
namespace stand = sylva::stand;

namespace {

// The plane the test DTM samples at its cell centres: bilinear interpolation gives it back exactly.
constexpr double kX0 = 700000, kY0 = 6600000;
double plane(double x, double y) { return 200 - 0.5 * (x - kX0) + 0.25 * (y - kY0); }

class BlockPaths : public GeoTestFolder {
protected:
    // A 4 x 3 ESRI ASCII DTM of 10 m cells, south-west corner (kX0, kY0), in Lambert-93, on `plane`.
    Dtm planarDtm() const {
        std::string text = "ncols 4\nnrows 3\nxllcorner " + std::to_string(kX0) + "\nyllcorner " + std::to_string(kY0) +
                           "\ncellsize 10\nNODATA_value -9999\n";
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 4; ++c) text += std::to_string(plane(kX0 + 5 + 10 * c, kY0 + 25 - 10 * r)) + " ";
            text += "\n";
        }
        std::ofstream(dir_ / "dtm.asc") << text;
        std::ofstream(dir_ / "dtm.prj") << kLambert93Prj;
        return readDtm((dir_ / "dtm.asc").string());
    }
};

dem::TrajectorySample sample(double t, double x, double y, double z, double speed = 0, double energyJ = 0) {
    const Eigen::Vector3d still = Eigen::Vector3d::Zero();
    return {t, {x, y, z}, {speed, 0, 0}, still, energyJ, 0};
}

stand::Tree tree(long id, double x, double y, double dbhCm, double heightM) {
    stand::Tree t;
    t.id = id;
    t.x = x;
    t.y = y;
    t.dbhCm = dbhCm;
    t.heightM = heightM;
    return t;
}

// Times in eighths of a second and positions in halves of a metre: every distance and gap below is
// exact, so the kept indices are the rule's, not rounding's. Spacing 1 m, gap 0.5 s.
TEST_F(BlockPaths, ThinningKeepsEndsAndEverySpacingOrGap) {
    const std::vector<dem::TrajectorySample> samples = {
        sample(0.0, 0, 0, 0, 2, 1000),      // 0 first
        sample(0.125, 0.5, 0, 0),           // 1 0.5 m
        sample(0.25, 0.5, 0, 1, 3, 4500),   // 2 kept: 1.118 m in 3-D, only 0.5 m across (a bounce's apex)
        sample(0.375, 1.0, 0, 0.75),        // 3 0.56 m from 2
        sample(0.5, 1.25, 0, 0.5),          // 4 0.90 m from 2
        sample(0.75, 1.25, 0, 0.5),         // 5 kept: 0.5 s after 2, at rest
        sample(0.875, 1.25, 0, 0.5),        // 6
        sample(1.0, 1.25, 0, 0.5),          // 7
        sample(1.125, 1.25, 0, 0.5, 0, 7),  // 8 last
    };
    const std::vector<PathPoint> kept = thinPath(samples, 1.0, 0.5);
    ASSERT_EQ(kept.size(), 4u);
    EXPECT_FLOAT_EQ(kept[0].time, 0);
    EXPECT_FLOAT_EQ(kept[1].time, 0.25f);
    EXPECT_FLOAT_EQ(kept[2].time, 0.75f);
    EXPECT_FLOAT_EQ(kept[3].time, 1.125f);
    EXPECT_DOUBLE_EQ(kept[1].x, 0.5);
    EXPECT_DOUBLE_EQ(kept[1].z, 1);
    EXPECT_FLOAT_EQ(kept[1].speedMs, 3);
    EXPECT_FLOAT_EQ(kept[1].energyKj, 4.5f);
    EXPECT_FLOAT_EQ(kept[3].energyKj, 0.007f);

    // A gap of 0.25 s keeps 4 (0.25 s after 2) and then every other sample of the resting block.
    std::vector<float> times;
    for (const PathPoint& p : thinPath(samples, 1.0, 0.25)) times.push_back(p.time);
    EXPECT_EQ(times, (std::vector<float>{0, 0.25f, 0.5f, 0.75f, 1.0f, 1.125f}));
    // The last sample once, even when the rule keeps it too.
    EXPECT_EQ(thinPath({samples[0], samples[2]}, 1.0, 0.5).size(), 2u);
    EXPECT_EQ(thinPath({samples[0]}, 1.0, 0.5).size(), 1u);
    EXPECT_TRUE(thinPath({}, 1.0, 0.5).empty());
    EXPECT_THROW(thinPath(samples, 0, 0.5), std::invalid_argument);
    EXPECT_THROW(thinPath(samples, 1.0, -1), std::invalid_argument);
}

TEST_F(BlockPaths, ImpactsSitAtTheirTreesFootOnTheDtm) {
    const Dtm dtm = planarDtm();
    stand::Forest forest;
    forest.source = "trees.csv";
    forest.trees = {tree(3, kX0 + 30, kY0 + 20, 18, 15), tree(7, kX0 + 12, kY0 + 11, 30, 20)};
    dem::TreeImpact hit;
    hit.tree = 7;
    hit.speedBefore = 8;
    hit.energyBefore = 50000;
    hit.energyAfter = 20000;
    hit.height = 1.2;
    hit.stemBroken = true;
    const std::vector<ImpactPoint> points = impactPoints(12, {hit}, forest, dtm);
    ASSERT_EQ(points.size(), 1u);
    const ImpactPoint& p = points[0];
    EXPECT_EQ(p.run, 12);
    EXPECT_EQ(p.tree, 7);
    EXPECT_DOUBLE_EQ(p.x, kX0 + 12);
    EXPECT_DOUBLE_EQ(p.y, kY0 + 11);
    EXPECT_NEAR(p.z, 200 - 0.5 * 12 + 0.25 * 11, 1e-9);  // 196.75, between four cell centres
    EXPECT_DOUBLE_EQ(p.dbhCm, 30);
    EXPECT_DOUBLE_EQ(p.heightAboveFootM, 1.2);
    EXPECT_DOUBLE_EQ(p.energyBeforeKj, 50);
    EXPECT_DOUBLE_EQ(p.energyAfterKj, 20);
    EXPECT_DOUBLE_EQ(p.speedBeforeMs, 8);
    EXPECT_TRUE(p.stemBroken);
    EXPECT_FALSE(p.rootYielded);

    // A tree the forest does not have: the run was simulated with another forest.
    hit.tree = 99;
    try {
        impactPoints(12, {hit}, forest, dtm);
        ADD_FAILURE() << "no error for tree 99";
    } catch (const std::logic_error& e) {
        EXPECT_NE(std::string(e.what()).find("tree 99"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("trees.csv"), std::string::npos) << e.what();
    }
}

BlockPath pathOf(long run, std::uint64_t seed, std::vector<PathPoint> points) {
    BlockPath p;
    p.run = run;
    p.seed = seed;
    p.points = std::move(points);
    return p;
}

TEST_F(BlockPaths, GeoPackageLayersReadBackWithOgr) {
    const Dtm dtm = planarDtm();
    BlockPath rolled = pathOf(4, 18446744073709551557ull, {{kX0 + 5, kY0 + 25, 201.5}, {kX0 + 15.25, kY0 + 20.5, 196.125}, {kX0 + 30, kY0 + 6, 188}});
    rolled.releaseColumn = 0;
    rolled.releaseRow = 0;
    rolled.reason = dem::StopReason::LeftDomain;
    rolled.pathLengthM = 31.5;
    rolled.reachM = 30.25;
    BlockPath stuck = pathOf(5, 77, {{kX0 + 25, kY0 + 15, 190}});
    stuck.releaseColumn = 2;
    stuck.releaseRow = 1;
    stuck.reason = dem::StopReason::Rest;
    ImpactPoint hit;
    hit.run = 4;
    hit.tree = 7;
    hit.x = kX0 + 12;
    hit.y = kY0 + 11;
    hit.z = 196.75;
    hit.dbhCm = 30;
    hit.heightAboveFootM = 1.2;
    hit.energyBeforeKj = 50;
    hit.energyAfterKj = 20;
    hit.speedBeforeMs = 8;
    hit.rootYielded = true;
    const std::string gpkg = (dir_ / "paths.gpkg").string();
    writePathLayers(gpkg, dtm, "forest", {rolled, stuck}, {hit});
    writePathLayers(gpkg, dtm, "bare", {rolled}, {});

    GDALDatasetUniquePtr ds(GDALDataset::Open(gpkg.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
    ASSERT_TRUE(ds);
    EXPECT_EQ(ds->GetLayerCount(), 4);
    OGRLayer* paths = ds->GetLayerByName("paths_forest");
    OGRLayer* impacts = ds->GetLayerByName("impacts_forest");
    ASSERT_TRUE(paths && impacts);
    ASSERT_TRUE(ds->GetLayerByName("paths_bare") && ds->GetLayerByName("impacts_bare"));
    EXPECT_EQ(ds->GetLayerByName("paths_bare")->GetFeatureCount(), 1);
    EXPECT_EQ(ds->GetLayerByName("impacts_bare")->GetFeatureCount(), 0);
    EXPECT_EQ(paths->GetGeomType(), wkbLineString25D);
    EXPECT_EQ(impacts->GetGeomType(), wkbPoint25D);
    ASSERT_TRUE(paths->GetSpatialRef() && impacts->GetSpatialRef());
    EXPECT_EQ(std::string(paths->GetSpatialRef()->GetName()), crsName(dtm.grid.crsWkt));
    EXPECT_EQ(std::string(impacts->GetSpatialRef()->GetName()), "RGF93 v1 / Lambert-93");
    ASSERT_EQ(paths->GetFeatureCount(), 2);

    paths->ResetReading();
    OGRFeatureUniquePtr first(paths->GetNextFeature());
    ASSERT_TRUE(first);
    EXPECT_EQ(first->GetFieldAsInteger64("run"), 4);
    EXPECT_EQ(std::string(first->GetFieldAsString("seed")), "18446744073709551557");
    EXPECT_EQ(first->GetFieldAsInteger("release_col"), 1);  // counted from 1 in the file
    EXPECT_EQ(first->GetFieldAsInteger("release_row"), 1);
    EXPECT_EQ(std::string(first->GetFieldAsString("stop")), "left_domain");
    EXPECT_DOUBLE_EQ(first->GetFieldAsDouble("path_m"), 31.5);
    EXPECT_DOUBLE_EQ(first->GetFieldAsDouble("reach_m"), 30.25);
    const OGRGeometry* g = first->GetGeometryRef();
    ASSERT_TRUE(g);
    ASSERT_EQ(wkbFlatten(g->getGeometryType()), wkbLineString);
    EXPECT_TRUE(g->Is3D());
    const OGRLineString* line = g->toLineString();
    ASSERT_EQ(line->getNumPoints(), 3);
    EXPECT_DOUBLE_EQ(line->getX(1), kX0 + 15.25);
    EXPECT_DOUBLE_EQ(line->getY(1), kY0 + 20.5);
    EXPECT_DOUBLE_EQ(line->getZ(1), 196.125);
    OGRFeatureUniquePtr second(paths->GetNextFeature());
    ASSERT_TRUE(second);
    EXPECT_EQ(second->GetFieldAsInteger("release_col"), 3);
    EXPECT_EQ(second->GetFieldAsInteger("release_row"), 2);
    EXPECT_EQ(std::string(second->GetFieldAsString("stop")), "rest");
    EXPECT_EQ(second->GetGeometryRef(), nullptr);  // one point: no line to draw

    ASSERT_EQ(impacts->GetFeatureCount(), 1);
    impacts->ResetReading();
    OGRFeatureUniquePtr i(impacts->GetNextFeature());
    ASSERT_TRUE(i && i->GetGeometryRef());
    const OGRPoint* foot = i->GetGeometryRef()->toPoint();
    EXPECT_DOUBLE_EQ(foot->getX(), kX0 + 12);
    EXPECT_DOUBLE_EQ(foot->getY(), kY0 + 11);
    EXPECT_DOUBLE_EQ(foot->getZ(), 196.75);
    EXPECT_EQ(i->GetFieldAsInteger64("run"), 4);
    EXPECT_EQ(i->GetFieldAsInteger64("tree"), 7);
    EXPECT_DOUBLE_EQ(i->GetFieldAsDouble("dbh_cm"), 30);
    EXPECT_DOUBLE_EQ(i->GetFieldAsDouble("height_m"), 1.2);
    EXPECT_DOUBLE_EQ(i->GetFieldAsDouble("energy_before_kj"), 50);
    EXPECT_DOUBLE_EQ(i->GetFieldAsDouble("energy_after_kj"), 20);
    EXPECT_DOUBLE_EQ(i->GetFieldAsDouble("speed_before_m_s"), 8);
    EXPECT_EQ(i->GetFieldAsInteger("stem_broken"), 0);
    EXPECT_EQ(i->GetFieldAsInteger("root_yielded"), 1);
    const OGRFieldDefn* broken = impacts->GetLayerDefn()->GetFieldDefn(impacts->GetLayerDefn()->GetFieldIndex("stem_broken"));
    ASSERT_TRUE(broken);
    EXPECT_EQ(broken->GetSubType(), OFSTBoolean);
    ds.reset();

    EXPECT_NE(errorOf([&] { writePathLayers(gpkg, dtm, "bare", {rolled}, {}); }).find("paths.gpkg: already holds a layer 'paths_bare'"),
              std::string::npos);
    const std::string nowhere = (dir_ / "no-such-folder" / "paths.gpkg").string();
    EXPECT_NE(errorOf([&] { writePathLayers(nowhere, dtm, "forest", {rolled}, {}); }).find(nowhere + ": cannot write"), std::string::npos)
        << errorOf([&] { writePathLayers(nowhere, dtm, "forest", {rolled}, {}); });
    std::ofstream(dir_ / "text.gpkg") << "not a GeoPackage\n";
    EXPECT_NE(errorOf([&] { writePathLayers((dir_ / "text.gpkg").string(), dtm, "forest", {rolled}, {}); }).find("text.gpkg: exists but is not a GeoPackage"),
              std::string::npos);
}

// A legacy VTK file: its header lines, then its words (keywords, counts and numbers).
struct Vtk {
    std::vector<std::string> header;  // version, title, ASCII, DATASET ...
    std::vector<std::string> words;   // after the DATASET line
    explicit Vtk(const fs::path& path) {
        std::ifstream in(path);
        std::string line;
        for (int i = 0; i < 4 && std::getline(in, line); ++i) header.push_back(line);
        for (std::string w; in >> w;) words.push_back(w);
    }
    std::size_t at(const std::string& keyword, std::size_t from = 0) const {
        for (std::size_t i = from; i < words.size(); ++i)
            if (words[i] == keyword) return i;
        return words.size();
    }
    double number(std::size_t i) const { return std::stod(words.at(i)); }
};

TEST_F(BlockPaths, VtkSceneHasTheDtmsCentresAndTheStems) {
    const Dtm dtm = planarDtm();
    stand::Forest forest;
    forest.trees = {tree(3, kX0 + 30, kY0 + 20, 18, 15), tree(7, kX0 + 12, kY0 + 11, 30, 20)};
    const std::string vtkDir = (dir_ / "vtk").string();  // created by the writer
    writeVtkScene(vtkDir, dtm, forest);

    const Vtk terrain(dir_ / "vtk/terrain.vtk");
    ASSERT_EQ(terrain.header.size(), 4u);
    EXPECT_EQ(terrain.header[0], "# vtk DataFile Version 3.0");
    EXPECT_EQ(terrain.header[2], "ASCII");
    EXPECT_EQ(terrain.header[3], "DATASET STRUCTURED_GRID");
    const auto& t = terrain.words;
    ASSERT_GE(t.size(), 7u);
    EXPECT_EQ(std::vector<std::string>(t.begin(), t.begin() + 7), (std::vector<std::string>{"DIMENSIONS", "4", "3", "1", "POINTS", "12", "double"}));
    // The first point is the south-west cell's centre, the second its eastern neighbour's.
    EXPECT_DOUBLE_EQ(terrain.number(7), kX0 + 5);
    EXPECT_DOUBLE_EQ(terrain.number(8), kY0 + 5);
    EXPECT_NEAR(terrain.number(9), plane(kX0 + 5, kY0 + 5), 1e-6);
    EXPECT_DOUBLE_EQ(terrain.number(10), kX0 + 15);
    EXPECT_NEAR(terrain.number(7 + 3 * 11 + 1), kY0 + 25, 1e-6);  // the last point: the north-east centre
    const std::size_t data = 7 + 3 * 12;
    ASSERT_EQ(terrain.at("POINT_DATA"), data);  // exactly 12 points before it
    EXPECT_EQ(std::vector<std::string>(t.begin() + data, t.begin() + data + 7),
              (std::vector<std::string>{"POINT_DATA", "12", "SCALARS", "elevation_m", "double", "1", "LOOKUP_TABLE"}));
    ASSERT_EQ(t.size(), data + 8 + 12);  // "default", then 12 heights
    EXPECT_NEAR(terrain.number(data + 8), plane(kX0 + 5, kY0 + 5), 1e-6);
    EXPECT_NEAR(terrain.number(data + 8 + 11), plane(kX0 + 35, kY0 + 25), 1e-6);

    const Vtk trees(dir_ / "vtk/trees.vtk");
    ASSERT_EQ(trees.header.size(), 4u);
    EXPECT_EQ(trees.header[3], "DATASET POLYDATA");
    const auto& w = trees.words;
    ASSERT_EQ(trees.at("POINTS"), 0u);
    EXPECT_EQ(w.at(1), "4");
    EXPECT_EQ(w.at(2), "double");
    // Tree 7, the second: foot on the DTM, top 20 m above.
    EXPECT_DOUBLE_EQ(trees.number(3 + 6), kX0 + 12);
    EXPECT_NEAR(trees.number(3 + 8), 196.75, 1e-6);
    EXPECT_NEAR(trees.number(3 + 11), 196.75 + 20, 1e-6);
    const std::size_t lines = trees.at("LINES");
    ASSERT_EQ(lines, 3 + 12u);
    EXPECT_EQ(std::vector<std::string>(w.begin() + lines, w.begin() + lines + 9),
              (std::vector<std::string>{"LINES", "2", "6", "2", "0", "1", "2", "2", "3"}));
    const std::size_t cells = trees.at("CELL_DATA");
    ASSERT_EQ(cells, lines + 9);
    EXPECT_EQ(w.at(cells + 1), "2");
    EXPECT_EQ(w.at(cells + 3), "dbh_cm");
    ASSERT_EQ(w.size(), cells + 8 + 2);
    EXPECT_DOUBLE_EQ(trees.number(cells + 8), 18);
    EXPECT_DOUBLE_EQ(trees.number(cells + 9), 30);

    // No stems, no trees.vtk.
    const std::string bare = (dir_ / "bare").string();
    writeVtkScene(bare, dtm, stand::Forest{});
    EXPECT_TRUE(fs::exists(dir_ / "bare/terrain.vtk"));
    EXPECT_FALSE(fs::exists(dir_ / "bare/trees.vtk"));
}

TEST_F(BlockPaths, VtkPathsArePolylinesWithTheirScalars) {
    PathPoint a{kX0 + 5.125, kY0 + 25, 201.5, 0, 0, 0}, b{kX0 + 15, kY0 + 20, 196, 0.5f, 6, 40}, c{kX0 + 30, kY0 + 6, 188, 1.5f, 0.25f, 1.5f};
    const std::vector<BlockPath> paths = {pathOf(4, 1, {a, b, c}), pathOf(5, 2, {c}), pathOf(9, 3, {b, c})};
    writeVtkPaths(dir_.string(), "forest", paths);
    const Vtk v(dir_ / "paths_forest.vtk");
    ASSERT_EQ(v.header.size(), 4u);
    EXPECT_EQ(v.header[0], "# vtk DataFile Version 3.0");
    EXPECT_EQ(v.header[3], "DATASET POLYDATA");
    const auto& w = v.words;
    // Runs 4 and 9: 5 points (run 5's single point draws nothing and is left out).
    ASSERT_EQ(v.at("POINTS"), 0u);
    EXPECT_EQ(w.at(1), "5");
    EXPECT_EQ(w.at(2), "double");
    EXPECT_DOUBLE_EQ(v.number(3), kX0 + 5.125);  // absolute, to the millimetre and beyond
    EXPECT_DOUBLE_EQ(v.number(4), kY0 + 25);
    const std::size_t lines = v.at("LINES");
    ASSERT_EQ(lines, 3 + 15u);
    EXPECT_EQ(std::vector<std::string>(w.begin() + lines, w.begin() + lines + 10),
              (std::vector<std::string>{"LINES", "2", "7", "3", "0", "1", "2", "2", "3", "4"}));
    const std::size_t data = v.at("POINT_DATA");
    ASSERT_EQ(data, lines + 10);
    EXPECT_EQ(w.at(data + 1), "5");
    std::size_t s = data + 2;
    for (const char* name : {"speed_m_s", "energy_kj", "time_s"}) {
        ASSERT_EQ(w.at(s), "SCALARS");
        EXPECT_EQ(w.at(s + 1), name);
        EXPECT_EQ(w.at(s + 2), "float");
        s += 6 + 5;  // SCALARS name float 1 LOOKUP_TABLE default, then a value per point
    }
    EXPECT_DOUBLE_EQ(v.number(data + 2 + 6 + 1), 6);          // speed at b
    EXPECT_DOUBLE_EQ(v.number(data + 2 + 11 + 6 + 2), 1.5);   // energy at c
    EXPECT_DOUBLE_EQ(v.number(data + 2 + 22 + 6 + 3), 0.5);   // time at run 9's b
    ASSERT_EQ(v.at("CELL_DATA"), s);
    EXPECT_EQ(w.at(s + 1), "2");
    EXPECT_EQ(w.at(s + 3), "run");
    ASSERT_EQ(w.size(), s + 8 + 2);
    EXPECT_EQ(w.at(s + 8), "4");
    EXPECT_EQ(w.at(s + 9), "9");

    EXPECT_NE(errorOf([&] { writeVtkPaths((dir_ / "paths_forest.vtk").string(), "x", paths); }).find("cannot create the folder"), std::string::npos);
}

}  // namespace

// The run-out on a DTM (libdem/SurfacePath.hpp, issue 15): the length of the path along the ground,
// positive whichever way the block runs, exact on a plane, converging with its chord on a curve.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "libdem/BlockRun.hpp"
#include "libdem/LumpedRun.hpp"
#include "libdem/Scene.hpp"
#include "libdem/SurfacePath.hpp"

using namespace sylva::dem;

namespace {

// A slope falling to the west, z = 0.5 (x - 100) (26.6 deg) above x = 100 m, flat below, 300 m by
// 100 m in cells of 5 m.
ElevationGrid westwardSlope() {
    const int cols = 61, rows = 21;
    std::vector<double> z(static_cast<std::size_t>(cols) * rows);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) z[static_cast<std::size_t>(r) * cols + c] = 0.5 * std::max(0.0, 5.0 * c - 100);
    return ElevationGrid::fromValues(cols, rows, 0, 0, 5, z, "west.asc");
}

}  // namespace

// The lumped block released without random turns runs straight west down the slope and stops on the
// flat: its run-out is the length of the ground along that line (ElevationGrid::lengthAlongX, exact),
// to 1e-4 (a chord across one of the grid's kinks cuts its corner). Before issue 15 it was the signed
// x difference, negative here.
TEST(SurfacePath, RunOutOnADtmIsThePathLengthWhicheverWayTheBlockRuns) {
    SceneConfig c = sceneFromOverrides({"release.x_m=150", "release.y_m=50", "lumped.deviation_sd_deg=0", "stop.max_time_s=60"});
    c.terrain.profile.clear();
    const Scene scene(c, westwardSlope());
    const RunResult lumped = simulateLumped(scene, 0, 5);
    ASSERT_EQ(lumped.reason, StopReason::Rest);
    EXPECT_LT(lumped.stop.x(), 100);  // it went west, onto the flat
    const double ground = scene.soil().alongSlope(lumped.stop.x(), lumped.release.x(), 50);
    EXPECT_NEAR(lumped.runoutAlongSlope, ground, 1e-4 * ground);
    // The DEM's cube wanders: its path is at least the straight line from release to stop, and at most
    // its horizontal length on ground no steeper than the slope's 1 in 2 (sqrt(1.25) per metre), with
    // 5 % for its wander across (a path 5 % longer than the straight line goes 32 % as far sideways;
    // measured 0.998 of the bound without it).
    const RunResult dem = simulateBlock(scene, 0, 5);
    EXPECT_LT(dem.stop.x(), 140);
    EXPECT_GE(dem.runoutAlongSlope, dem.runoutHorizontal);
    EXPECT_LT(dem.runoutAlongSlope, 1.05 * dem.runoutHorizontal * std::sqrt(1.25));
}

// Points every millimetre along a quarter circle of radius 10 m on flat ground: the chord polyline's
// length converges to 5 pi as the chord is halved, its error shrinking ~4-fold (second order, c^2/24R^2).
TEST(SurfacePath, ChordIsAResolution) {
    const SceneConfig c = sceneFromOverrides({"terrain.profile=" + std::string(SYLVAROCK_DATA) + "/slopes/flat.csv", "terrain.width_m=40"});
    const Scene scene(c);
    const double exact = 0.5 * M_PI * 10;
    double previous = 1;
    for (double chord : {0.5, 0.25, 0.125}) {
        SurfacePath path(scene.soil(), Vec3(30, 10, 0), chord);
        Vec3 p;
        for (int i = 1; i <= 15708; ++i) {
            const double a = i * 1e-4;
            p = Vec3(20 + 10 * std::cos(a), 10 + 10 * std::sin(a), 0);
            path.moveTo(p);
        }
        const double error = std::fabs(path.length(p) - exact) / exact;
        EXPECT_LT(error, previous / 3) << chord;
        previous = error;
    }
    EXPECT_LT(previous, 1e-4);
    // A block shaking in place adds nothing.
    SurfacePath still(scene.soil(), Vec3(30, 10, 0));
    for (int i = 0; i < 1000; ++i) still.moveTo(Vec3(30 + 0.01 * std::sin(i), 10, 0));
    EXPECT_EQ(still.length(Vec3(30, 10, 0)), 0);
}

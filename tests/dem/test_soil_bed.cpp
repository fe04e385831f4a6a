// The soil bed: sphere spacing from the roughness (Fig. 6), placement under profiles and DTMs
// against the analytic surface, the row offsets of Fig. 7, the implicit neighbour query against
// brute force, along-slope distances, memory of the full-size slope and the CSV export.
#include <gtest/gtest.h>

#include <malloc.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "libdem/Terrain.hpp"
#include "libcommon/CsvTable.hpp"
#include "libcommon/InputError.hpp"

using sylva::InputError;
using namespace sylva::dem;

namespace {

const std::string kDir = std::string(SYLVAROCK_TEST_DATA) + "/dem/";
const std::string kSlopes = std::string(SYLVAROCK_DATA) + "/slopes/";
const double kPi = std::acos(-1.0);

SoilBedParams params(double width, std::uint64_t seed = 1) {
    SoilBedParams p;
    p.width = width;
    p.seed = seed;
    return p;
}

// Distance in the (x, z) plane from c to the polyline of a profile.
double distanceToProfile(const SlopeProfile& p, double cx, double cz) {
    double best = INFINITY;
    for (std::size_t i = 0; i + 1 < p.xs().size(); ++i) {
        const double ax = p.xs()[i], az = p.zs()[i], dx = p.xs()[i + 1] - ax, dz = p.zs()[i + 1] - az;
        const double t = std::clamp(((cx - ax) * dx + (cz - az) * dz) / (dx * dx + dz * dz), 0.0, 1.0);
        best = std::min(best, std::hypot(cx - ax - t * dx, cz - az - t * dz));
    }
    return best;
}

std::vector<std::uint32_t> bruteForceNear(const SoilBed& bed, const Eigen::Vector3d& p, double reach) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t id = 0; id < bed.size(); ++id)
        if ((bed.center(id) - p).squaredNorm() <= reach * reach) out.push_back(id);
    return out;
}

// Compares near() with brute force at random points around the bed (beyond the row ends and
// the y edges, above and below the surface) and at the corners and edges themselves.
void expectNearMatchesBruteForce(const SoilBed& bed, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> ux(bed.xmin() - 3, bed.xmax() + 3), uy(bed.ymin() - 3, bed.ymax() + 3),
        uz(-3, 3), ureach(0.3, 3.0);
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < 300; ++i) {
        const double x = ux(rng), y = uy(rng);
        points.emplace_back(x, y, bed.surfaceHeight(x, y) + uz(rng));
    }
    for (const double x : {bed.xmin(), bed.xmax()})
        for (const double y : {bed.ymin(), bed.ymax(), 0.5 * (bed.ymin() + bed.ymax())})
            for (const double dz : {-1.0, 0.0, 0.5}) points.emplace_back(x, y, bed.surfaceHeight(x, y) + dz);
    std::size_t found = 0;
    for (const Eigen::Vector3d& p : points) {
        const double reach = ureach(rng);
        std::vector<std::uint32_t> got;
        bed.near(p, reach, got);
        std::sort(got.begin(), got.end());
        const auto want = bruteForceNear(bed, p, reach);
        EXPECT_EQ(got, want) << "p = " << p.transpose() << ", reach = " << reach;
        found += want.size();
    }
    EXPECT_GT(found, points.size()) << "the queries must reach spheres for the comparison to mean something";
}

}  // namespace

TEST(SoilSpacing, InvertsTheRoughnessRelation) {
    // Table 2 as read in model-notes.md: R = 0.7 m, h = 0.1 m gives d = 2 sqrt(0.13) = 0.7211 m
    EXPECT_NEAR(soilSpacing(0.7, 0.1), 2 * std::sqrt(0.13), 1e-15);
    for (const auto& [R, h] : {std::pair{0.7, 0.1}, {0.7, 0.7}, {0.5, 0.01}, {2.0, 0.3}}) {
        const double d = soilSpacing(R, h);
        EXPECT_NEAR(R - std::sqrt(R * R - d * d / 4), h, 1e-12) << "R = " << R << ", h = " << h;  // Fig. 6
    }
}

TEST(SoilSpacing, RejectsImpossibleRoughness) {
    EXPECT_THROW(soilSpacing(0.7, 0.0), InputError);
    EXPECT_THROW(soilSpacing(0.7, -0.1), InputError);
    EXPECT_THROW(soilSpacing(0.7, 0.71), InputError);
    EXPECT_THROW(soilSpacing(0.0, 0.1), InputError);
    EXPECT_THROW(soilSpacing(0.7, NAN), InputError);
    // The message names the keys a user sets, not the paper's symbols.
    try {
        soilSpacing(0.011, 0.1);
        FAIL() << "a bump above the radius was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("terrain.roughness_m = 0.1: the bump between soil spheres must be in (0, terrain.soil_radius_m = 0.011] m"),
                  std::string::npos)
            << e.what();
    }
}

TEST(SoilBed, RejectsANonPositiveWidth) {
    const SlopeProfile p({0, 10}, {10, 0});
    EXPECT_THROW(SoilBed::fromProfile(p, params(0.0)), InputError);
    EXPECT_THROW(SoilBed::fromProfile(p, params(-5.0)), InputError);
}

// A profile 1e9 m long (a typo, or mm) would need 4e11 spheres: refused at once, before any
// allocation, naming the extent (issue 13: std::bad_alloc after a minute).
TEST(SoilBed, RefusesABedThatWouldNotFitBeforeAllocatingIt) {
    const SlopeProfile p({0, 1e9}, {1000, 0});
    try {
        SoilBed::fromProfile(p, params(200));
        FAIL() << "a 1e9 m profile was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("1e+09 m long"), std::string::npos) << e.what();
    }
    // The full stand-in slope (630 m x 200 m, 2.8e5 spheres) is far below the cap.
    EXPECT_NO_THROW(SoilBed::fromProfile(SlopeProfile({0, 630}, {300, 0}), params(200)));
}

// On a straight 30 deg profile every centre lies R below the line along its normal, and rows
// follow each other at the curvilinear spacing d. Extra collinear vertices exercise the walk
// from segment to segment. Tolerance 1e-9 m: coordinates ~100 m, a few operations each.
TEST(SoilBed, SpheresOnAPlaneProfileSitOneRadiusUnderIt) {
    const double t = std::tan(kPi / 6), s = std::sin(kPi / 6), c = std::cos(kPi / 6);
    const std::vector<double> xs = {0, 37.3, 41, 150, 200};
    std::vector<double> zs;
    for (double x : xs) zs.push_back(100 - t * x);
    const SoilBed bed = SoilBed::fromProfile(SlopeProfile(xs, zs), params(20.0));
    const double R = bed.radius(), d = bed.spacing();
    ASSERT_EQ(bed.rows(), static_cast<std::size_t>(std::floor(200 / c / d)) + 1);
    for (std::uint32_t id = 0; id < bed.size(); ++id) {
        const Eigen::Vector3d p = bed.center(id);
        // signed distance to the line s x + c z = 100 c, positive above it
        ASSERT_NEAR(s * p.x() + c * p.z() - 100 * c, -R, 1e-9) << "sphere " << id;
    }
    EXPECT_NEAR(bed.center(0).x(), -R * s, 1e-9);  // the first row hangs under the top point
    for (std::size_t r = 1; r < bed.rows(); ++r) {
        const Eigen::Vector3d a = bed.center(static_cast<std::uint32_t>((r - 1) * bed.perRow()));
        const Eigen::Vector3d b = bed.center(static_cast<std::uint32_t>(r * bed.perRow()));
        EXPECT_NEAR(std::hypot(b.x() - a.x(), b.z() - a.z()), d, 1e-9) << "row " << r;
    }
}

// Only concave breaks (each segment flatter than the last): no sphere can reach above the other
// segments, so each centre is exactly R from the polyline: every top touches the profile.
TEST(SoilBed, SpheresUnderAConcaveProfileTouchItFromBelow) {
    const SlopeProfile profile({0, 50, 100, 150, 200}, {100, 60, 40, 35, 34});
    const SoilBed bed = SoilBed::fromProfile(profile, params(5.0));
    for (std::size_t r = 0; r < bed.rows(); ++r) {
        const Eigen::Vector3d p = bed.center(static_cast<std::uint32_t>(r * bed.perRow()));
        EXPECT_NEAR(distanceToProfile(profile, p.x(), p.z()), bed.radius(), 1e-9) << "row " << r;
        EXPECT_LT(p.z(), profile.height(p.x())) << "row " << r;
    }
}

TEST(SoilBed, RowsCoverTheWidthAtSpacingD) {
    const double width = 12.0;
    const SoilBed bed = SoilBed::fromProfile(SlopeProfile({0, 40}, {30, 0}), params(width));
    const double d = bed.spacing();
    ASSERT_GT(bed.rows(), 50u);
    for (std::size_t r = 0; r < bed.rows(); ++r) {
        const auto first = static_cast<std::uint32_t>(r * bed.perRow());
        const auto last = first + bed.perRow() - 1;
        EXPECT_LE(bed.center(first).y(), 0.0) << "row " << r;
        EXPECT_GT(bed.center(first).y(), -d) << "row " << r;
        EXPECT_GE(bed.center(last).y(), width) << "row " << r;
        for (std::uint32_t id = first + 1; id <= last; ++id)
            EXPECT_NEAR(bed.center(id).y() - bed.center(id - 1).y(), d, 1e-12);  // values ~10 m
        EXPECT_EQ(bed.center(last).x(), bed.center(first).x());
        EXPECT_EQ(bed.center(last).z(), bed.center(first).z());
    }
}

// Fig. 7: each row is shifted by an offset uniform in [0, 2 R]. The spheres of a row sit at
// offset + k d, so u = y(column 0) + d is the offset modulo d, in (0, d]. With 2R < 2d, u < a for
// a = 2R - d when the offset lies in [0, a) or in [d, 2R): probability 2a / 2R = 0.970, where an
// offset uniform in [0, d) would give a / d = 0.941. Bound: 4 standard errors of a proportion.
TEST(SoilBed, RowOffsetsAreUniformOverTwoRadiiAndSeeded) {
    const SlopeProfile profile({0, 2000}, {0, -10});
    const SoilBed bed = SoilBed::fromProfile(profile, params(1.0, 7));
    const double R = bed.radius(), d = bed.spacing(), a = 2 * R - d;
    const std::size_t n = bed.rows();
    std::size_t below = 0;
    for (std::size_t r = 0; r < n; ++r) below += bed.center(static_cast<std::uint32_t>(r * bed.perRow())).y() + d < a;
    const double p = 2 * a / (2 * R), se = std::sqrt(p * (1 - p) / n);
    EXPECT_NEAR(static_cast<double>(below) / n, p, 4 * se) << n << " rows";

    const SoilBed same = SoilBed::fromProfile(profile, params(1.0, 7));
    const SoilBed other = SoilBed::fromProfile(profile, params(1.0, 8));
    std::size_t equalToOther = 0;
    for (std::uint32_t id = 0; id < bed.size(); id += bed.perRow()) {
        EXPECT_EQ(bed.center(id), same.center(id));
        equalToOther += bed.center(id) == other.center(id);
    }
    EXPECT_LT(equalToOther, n / 100) << "another seed must give other offsets";
}

// A convex break (flat, then 60 deg) makes the row centres step back upslope; rows must still
// come out sorted in x for the binary search.
TEST(SoilBedNear, MatchesBruteForceOnAProfileWithBreaks) {
    const SlopeProfile profile({0, 40, 60, 100, 130, 160}, {120, 90, 90, 20.7, 10, 12});
    const SoilBed bed = SoilBed::fromProfile(profile, params(30.0, 3));
    for (std::size_t r = 1; r < bed.rows(); ++r)
        ASSERT_LE(bed.center(static_cast<std::uint32_t>((r - 1) * bed.perRow())).x(),
                  bed.center(static_cast<std::uint32_t>(r * bed.perRow())).x());
    expectNearMatchesBruteForce(bed, 11);
}

TEST(SoilBedNear, MatchesBruteForceOnTheExampleDtm) {
    const SoilBed bed = SoilBed::fromGrid(ElevationGrid::readAsc(kSlopes + "example-dtm.asc"), params(0.0, 4));
    expectNearMatchesBruteForce(bed, 12);
}

TEST(SoilBedNear, FindsNothingFarFromTheSurfaceOrWithANegativeReach) {
    const SoilBed bed = SoilBed::fromProfile(SlopeProfile({0, 50}, {50, 0}), params(10.0));
    std::vector<std::uint32_t> out;
    bed.near({25, 5, 25 + 3.0}, 2.0, out);  // 3 m above the surface: centres are 0.7 m below it
    bed.near({25, 5, 25}, -1.0, out);
    bed.near({500, 5, 25}, 2.0, out);
    bed.near({25, NAN, 25}, 2.0, out);
    EXPECT_TRUE(out.empty());
    bed.near({25, 5, 25}, 2.0, out);
    EXPECT_FALSE(out.empty());
}

// The 630 m x 200 m scene: about 270 k spheres, measured on the heap (glibc's mallinfo2) well
// under the 200 MB budget. A sphere costs 8 bytes plus its row's share; 20 MB leaves room.
TEST(SoilBed, FullSizeStandinSlopeFitsInMemory) {
    const SlopeProfile profile = SlopeProfile::readCsv(kSlopes + "standin-s1.0.csv");
    // in use = small blocks (uordblks) + blocks glibc gave their own mmap (hblkhd)
    const auto inUse = [] {
        const struct mallinfo2 m = mallinfo2();
        return m.uordblks + m.hblkhd;
    };
    const std::size_t before = inUse();
    const SoilBed bed = SoilBed::fromProfile(profile, params(200.0));
    const std::size_t after = inUse();
    const double d = bed.spacing();
    EXPECT_EQ(bed.rows(), static_cast<std::size_t>(std::floor(profile.length() / d)) + 1);
    EXPECT_GE(bed.perRow() * d, 200.0 + d);  // column 0 may start up to d below y = 0
    EXPECT_GT(bed.size(), 250000u);
    EXPECT_LT(bed.size(), 300000u);
    if (after == before) GTEST_SKIP() << "mallinfo2 does not see this allocator (a sanitizer build?)";
    const double mb = (after - before) / 1e6;
    EXPECT_GE(after - before, bed.size() * sizeof(double)) << "the measure must at least see the heights";
    EXPECT_LT(mb, 20.0);
    std::printf("stand-in slope s1.0: %zu rows x %u = %zu spheres, %.1f MB on the heap\n", bed.rows(),
                bed.perRow(), bed.size(), mb);
}

// grid_plane.asc is z = 50 - 0.5 x + 0.25 y: each centre is R under the plane along its normal.
// The last columns of a row reach up to d beyond the grid's y edges, where the height is clamped
// (z = 50 - 0.5 x + 0.25 y_edge, flat across): those spheres are R under that surface.
TEST(SoilBed, SpheresOnAPlaneDtmAreTangentToIt) {
    const ElevationGrid grid = ElevationGrid::readAsc(kDir + "grid_plane.asc");
    const SoilBed bed = SoilBed::fromGrid(grid, params(0.0, 2));
    const double d = bed.spacing();
    EXPECT_EQ(bed.rows(), static_cast<std::size_t>(std::floor((grid.xmax() - grid.xmin()) / d)) + 1);
    EXPECT_EQ(bed.xmin(), grid.xmin());
    EXPECT_EQ(bed.ymax(), grid.ymax());
    std::size_t outside = 0;
    for (std::uint32_t id = 0; id < bed.size(); ++id) {
        const Eigen::Vector3d c = bed.center(id);
        const bool inside = c.y() >= grid.ymin() && c.y() <= grid.ymax();
        outside += !inside;
        const double yEdge = std::clamp(c.y(), grid.ymin(), grid.ymax());
        const Eigen::Vector3d surface(c.x(), c.y(), 50 - 0.5 * c.x() + 0.25 * yEdge);
        const Eigen::Vector3d n = Eigen::Vector3d(0.5, inside ? -0.25 : 0.0, 1.0).normalized();  // upward
        // tolerance: values ~50 m, a dozen operations
        ASSERT_NEAR(n.dot(c - surface), -bed.radius(), 1e-9) << "sphere " << id;
    }
    EXPECT_GT(outside, 0u);
    for (std::size_t r = 0; r < bed.rows(); ++r) {
        const auto first = static_cast<std::uint32_t>(r * bed.perRow());
        EXPECT_NEAR(bed.center(first).x(), grid.xmin() + r * d, 1e-12);
        EXPECT_LE(bed.center(first).y(), grid.ymin());
        EXPECT_GE(bed.center(first + bed.perRow() - 1).y(), grid.ymax());
    }
}

TEST(SoilBed, NodataUnderTheBedIsAnInputError) {
    const ElevationGrid grid = ElevationGrid::readAsc(kDir + "grid_nodata.asc");
    try {
        SoilBed::fromGrid(grid, params(0.0));
        ADD_FAILURE() << "a bed was laid over a NODATA cell";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), kDir + "grid_nodata.asc");
        EXPECT_EQ(e.line(), 8);
    }
}

TEST(SoilBed, SurfaceAndAlongSlopeDistanceOfAProfile) {
    // profile_ok.csv: (0,10) (3,6) (6,6) (10,9), segments of 5, 3 and 5 m
    const SlopeProfile profile = SlopeProfile::readCsv(kDir + "profile_ok.csv");
    const SoilBed bed = SoilBed::fromProfile(profile, params(4.0));
    for (const double y : {0.0, 2.5, 40.0}) {
        EXPECT_NEAR(bed.alongSlope(0, 10, y), 13.0, 1e-12);
        EXPECT_NEAR(bed.alongSlope(1.5, 8, y), 5.5 + 2.5, 1e-12);
        EXPECT_NEAR(bed.alongSlope(8, 1.5, y), -8.0, 1e-12);
        EXPECT_EQ(bed.surfaceHeight(1.5, y), profile.height(1.5));
    }
    EXPECT_EQ(bed.xmin(), 0.0);
    EXPECT_EQ(bed.xmax(), 10.0);
    EXPECT_EQ(bed.ymin(), 0.0);
    EXPECT_EQ(bed.ymax(), 4.0);
}

// The example DTM is straight along every line y = const (30 deg): length dx / cos 30; the file's
// millimetre rounding telescopes to under 1e-3 m (see test_elevation_grid_reader.cpp).
TEST(SoilBed, SurfaceAndAlongSlopeDistanceOfADtm) {
    const ElevationGrid grid = ElevationGrid::readAsc(kSlopes + "example-dtm.asc");
    const SoilBed bed = SoilBed::fromGrid(grid, params(0.0));
    for (const double y : {10.0, 59.0, 60.0}) {
        EXPECT_NEAR(bed.alongSlope(20, 120, y), 100 / std::cos(kPi / 6), 1e-3);
        EXPECT_EQ(bed.surfaceHeight(33.3, y), grid.height(33.3, y));
    }
}

// Values are printed with 6 decimals: rounding <= 5e-7 m, tolerance 1e-6 m.
TEST(SoilBed, WriteCsvListsEverySphere) {
    const SoilBed bed = SoilBed::fromProfile(SlopeProfile({0, 5, 9}, {6, 3, 2}), params(3.0));
    const std::string path = ::testing::TempDir() + "soil_bed.csv";
    bed.writeCsv(path);
    const sylva::CsvTable t = sylva::CsvTable::read(path);
    EXPECT_EQ(t.header(), (std::vector<std::string>{"x", "y", "z", "r"}));
    ASSERT_EQ(t.rows(), bed.size());
    for (std::uint32_t id = 0; id < bed.size(); ++id) {
        const Eigen::Vector3d c = bed.center(id);
        EXPECT_NEAR(t.number(id, 0), c.x(), 1e-6);
        EXPECT_NEAR(t.number(id, 1), c.y(), 1e-6);
        EXPECT_NEAR(t.number(id, 2), c.z(), 1e-6);
        EXPECT_NEAR(t.number(id, 3), 0.7, 1e-6);
    }
    std::remove(path.c_str());
}

TEST(SoilBed, WriteCsvToAMissingDirectoryIsAnInputError) {
    const SoilBed bed = SoilBed::fromProfile(SlopeProfile({0, 5}, {6, 3}), params(3.0));
    EXPECT_THROW(bed.writeCsv("/nonexistent-directory/soil.csv"), InputError);
}

// What steepestRise promises (a height known at p bounds the surface at q by the rise times the
// horizontal distance; detectStemSoil skips on it), on random pairs over a profile with breaks and a
// bumpy DTM, and that it is not loose: on the profile it is its steepest segment, on the DTM within
// sqrt(2) of the steepest slope sampled (the bilinear cell's bound takes its two axes' worst edges).
TEST(SoilBed, SteepestRiseBoundsTheSurfaceAroundAnyKnownHeight) {
    const SlopeProfile profile({0, 40, 60, 100, 130, 160}, {120, 90, 90, 20.7, 10, 12});
    const SoilBed onProfile = SoilBed::fromProfile(profile, params(30.0, 3));
    EXPECT_DOUBLE_EQ(onProfile.steepestRise(), (90 - 20.7) / 40);

    std::mt19937 rng(5);
    std::uniform_real_distribution<double> bump(-1.5, 1.5);
    std::vector<double> z;
    for (int r = 0; r < 12; ++r)
        for (int c = 0; c < 15; ++c) z.push_back(0.4 * c * 2 + bump(rng));
    const SoilBed onDtm = SoilBed::fromGrid(ElevationGrid::fromValues(15, 12, 0, 0, 2, z, "bumps"), params(0.0));

    for (const SoilBed* bed : {&onProfile, &onDtm}) {
        std::uniform_real_distribution<double> ux(bed->xmin() - 2, bed->xmax() + 2), uy(bed->ymin(), bed->ymax());
        double tightest = 0;  // the largest rise per metre found over a few centimetres
        for (const double far : {3.0, 0.03}) {
            std::uniform_real_distribution<double> step(-far, far);
            for (int i = 0; i < 20000; ++i) {
                const double px = ux(rng), py = uy(rng), qx = px + step(rng), qy = std::clamp(py + step(rng), bed->ymin(), bed->ymax());
                const double distance = std::hypot(qx - px, qy - py);
                const double rise = bed->surfaceHeight(qx, qy) - bed->surfaceHeight(px, py);
                // 1e-12 m: the heights' rounding (a few ulps of hundreds of metres), far below any rise tested.
                ASSERT_LE(rise, bed->steepestRise() * distance + 1e-12) << "from (" << px << ", " << py << ") to (" << qx << ", " << qy << ")";
                if (distance > 1e-3) tightest = std::max(tightest, rise / distance);
            }
        }
        EXPECT_GT(tightest, bed->steepestRise() / std::sqrt(2.0));
    }
}

// Clark-Evans index against spatstat's clarkevans() (R 4.2, spatstat 3.0) on two real stands, and
// against analytic values on a lattice.
#include <gtest/gtest.h>

#include <cmath>

#include "libstand/ClarkEvans.hpp"
#include "libstand/NearestNeighbours.hpp"
#include "test_stand_statistics_data.hpp"

using namespace sylva::stand;
namespace td = sylva::stand::testdata;

namespace {

// The requirement. The arithmetic is the same as spatstat's, so the actual agreement is
// at rounding level (~1e-15); 1e-6 is what the summary.csv's 15 digits easily support.
constexpr double kSpatstatRel = 1e-6;

void expectRel(double got, double want, double rel, const std::string& what) {
    EXPECT_NEAR(got, want, rel * std::abs(want)) << what;
}

class ClarkEvansSpatstat : public ::testing::TestWithParam<std::string> {};

TEST_P(ClarkEvansSpatstat, AllCorrectionsAgreeWithClarkevans) {
    const std::string name = GetParam();
    const Window w = td::spatstatWindow(name);
    const auto pts = td::spatstatPoints(name);
    const ClarkEvansIndex ce = clarkEvans(pts, w);
    ASSERT_TRUE(ce.naive && ce.donnelly && ce.guard && ce.cdf);
    expectRel(ce.meanNearestNeighbour, td::spatstatSummary(name, "mean_nn"), kSpatstatRel, name + " mean nn");
    expectRel(*ce.naive, td::spatstatSummary(name, "ce_naive"), kSpatstatRel, name + " naive");
    expectRel(*ce.donnelly, td::spatstatSummary(name, "ce_donnelly"), kSpatstatRel, name + " Donnelly");
    expectRel(*ce.guard, td::spatstatSummary(name, "ce_guard"), kSpatstatRel, name + " guard");
    expectRel(*ce.cdf, td::spatstatSummary(name, "ce_cdf"), kSpatstatRel, name + " cdf");
}

INSTANTIATE_TEST_SUITE_P(Stands, ClarkEvansSpatstat, ::testing::Values("longleaf", "spruces"));

TEST(ClarkEvans, RectangleGivenAsPolygonGivesSameGuardAndNoDonnelly) {
    const auto pts = td::spatstatPoints("spruces");
    const Window rect = td::spatstatWindow("spruces");
    const Window poly = Window::fromWkt("POLYGON((0 0, 56 0, 56 38, 0 38, 0 0))");
    const ClarkEvansIndex a = clarkEvans(pts, rect), b = clarkEvans(pts, poly);
    EXPECT_FALSE(b.donnelly.has_value());  // spatstat: Donnelly only for rectangles
    ASSERT_TRUE(b.guard && b.naive && b.cdf);
    // Same points, same distances to the boundary (computed along edges instead of per side): identical
    // up to rounding.
    EXPECT_NEAR(*b.guard, *a.guard, 1e-12);
    EXPECT_NEAR(*b.naive, *a.naive, 1e-12);
    EXPECT_NEAR(*b.cdf, *a.cdf, 1e-12);
    EXPECT_EQ(a.nInGuard, b.nInGuard);
}

TEST(ClarkEvans, SquareLatticeIsTwiceThePoissonExpectation) {
    // k x k lattice of spacing s centred in [0, k s]²: every nearest-neighbour distance is s and
    // E = 0.5 sqrt(A/n) = s/2, so R = 2 exactly (the most regular pattern has R = 2.149 for a
    // hexagonal lattice; the square one 2).
    const int k = 20;
    const double s = 2.5;
    std::vector<Eigen::Vector2d> pts;
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) pts.emplace_back((i + 0.5) * s, (j + 0.5) * s);
    const ClarkEvansIndex ce = clarkEvans(pts, Window::rectangle(0, 0, k * s, k * s));
    EXPECT_NEAR(*ce.naive, 2.0, 1e-12);
    // Donnelly: d_obs / (s/2 + (0.0514 + 0.0412/k) 4 k s / k²), by hand
    EXPECT_NEAR(*ce.donnelly, s / (s / 2 + (0.0514 + 0.0412 / k) * 4 * k * s / (k * k)), 1e-12);
    EXPECT_NEAR(*ce.guard, 2.0, 1e-12);
}

TEST(ClarkEvans, CoincidentPointsHaveZeroNearestNeighbourDistance) {
    const std::vector<Eigen::Vector2d> pts{{1, 1}, {1, 1}, {4, 5}};
    const auto nnd = nearestNeighbourDistances(pts);
    EXPECT_EQ(nnd[0], 0.0);
    EXPECT_EQ(nnd[1], 0.0);
    EXPECT_NEAR(nnd[2], 5.0, 1e-15);
    const ClarkEvansIndex ce = clarkEvans(pts, Window::rectangle(0, 0, 10, 10));
    EXPECT_NEAR(ce.meanNearestNeighbour, 5.0 / 3, 1e-15);
}

TEST(ClarkEvans, UndefinedBelowTwoPoints) {
    const ClarkEvansIndex one = clarkEvans({{1, 1}}, Window::rectangle(0, 0, 10, 10));
    EXPECT_FALSE(one.naive || one.donnelly || one.guard || one.cdf);
    const ClarkEvansIndex none = clarkEvans({}, Window::rectangle(0, 0, 10, 10));
    EXPECT_FALSE(none.naive.has_value());
}

TEST(ClarkEvans, NearestNeighboursMatchBruteForce) {
    // CGAL k-d tree against an O(n²) scan on the longleaf pines.
    const auto pts = td::spatstatPoints("longleaf");
    const auto nnd = nearestNeighbourDistances(pts);
    for (std::size_t i = 0; i < pts.size(); ++i) {
        double best = INFINITY;
        for (std::size_t j = 0; j < pts.size(); ++j)
            if (j != i) best = std::min(best, (pts[i] - pts[j]).norm());
        ASSERT_EQ(nnd[i], best) << i;
    }
}

}  // namespace

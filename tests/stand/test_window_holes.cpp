// Windows with holes (issue 13: real plots leave out rocks, roads and gaps): geometry against closed
// forms, and the edge corrections, Clark-Evans and g(r) against spatstat on its `gordon` pattern
// (an outer ring and two holes; tests/data/spatstat/gordon_ref.R wrote the values).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <utility>
#include <vector>

#include "libstand/ClarkEvans.hpp"
#include "libstand/EdgeCorrection.hpp"
#include "libcommon/InputError.hpp"
#include "libstand/PairCorrelation.hpp"
#include "libstand/Window.hpp"
#include "test_stand_statistics_data.hpp"

using namespace sylva::stand;
namespace td = sylva::stand::testdata;
using Vec = Eigen::Vector2d;

namespace {

std::string errorOf(const std::string& wkt) {
    try {
        Window::fromWkt(wkt);
    } catch (const sylva::InputError& e) {
        return e.what();
    }
    return "(no error)";
}

// A 10 m square with a 2 m square hole in its middle.
const char* const kSquareWithHole = "POLYGON((0 0, 10 0, 10 10, 0 10, 0 0), (4 4, 4 6, 6 6, 6 4, 4 4))";

// |A ∩ (B + v)| of two axis-aligned rectangles given as (xmin, ymin, xmax, ymax).
double rectangleOverlap(const Eigen::Vector4d& a, const Eigen::Vector4d& b, const Vec& v) {
    const double w = std::min(a[2], b[2] + v.x()) - std::max(a[0], b[0] + v.x());
    const double h = std::min(a[3], b[3] + v.y()) - std::max(a[1], b[1] + v.y());
    return std::max(0.0, w) * std::max(0.0, h);
}

TEST(WindowWithHoles, GeometryOfASquareWithAHole) {
    const Window w = Window::fromWkt(kSquareWithHole);
    EXPECT_DOUBLE_EQ(w.area(), 96);       // 100 - 4
    EXPECT_DOUBLE_EQ(w.perimeter(), 48);  // 40 + 8
    EXPECT_EQ(w.describe(), "polygon of 4 vertices with 1 hole");
    EXPECT_FALSE(w.contains({5, 5}));    // in the hole
    EXPECT_TRUE(w.contains({4, 5}));     // on the hole's edge: the window is closed
    EXPECT_TRUE(w.contains({3, 5}));
    EXPECT_FALSE(w.contains({11, 5}));
    EXPECT_DOUBLE_EQ(w.distanceToBoundary({3, 5}), 1);  // nearer the hole than the outer edge
    EXPECT_DOUBLE_EQ(w.distanceToBoundary({1, 5}), 1);
    ASSERT_EQ(w.rings().size(), 2u);
    EXPECT_GT(signedArea(w.rings()[1]), 0);  // the hole given clockwise, stored counter-clockwise
}

TEST(WindowWithHoles, SetCovarianceIsTheRectanglesInclusionExclusion) {
    // Independent of the code's convex pieces and clipping: 1_W = 1_O - 1_H for rectangles O and H.
    const Window w = Window::fromWkt(kSquareWithHole);
    const Eigen::Vector4d O(0, 0, 10, 10), H(4, 4, 6, 6);
    const TranslationCorrection t(w);
    for (const Vec& v : {Vec(0, 0), Vec(1, 0), Vec(0.5, -1.5), Vec(2, 2), Vec(-3, 1), Vec(5, 7), Vec(9.5, 0.2), Vec(12, 0)}) {
        const double want = rectangleOverlap(O, O, v) - rectangleOverlap(O, H, v) - rectangleOverlap(H, O, v) +
                            rectangleOverlap(H, H, v);
        EXPECT_NEAR(t.setCovariance(v), want, 1e-9) << v.transpose();
    }
}

TEST(WindowWithHoles, CircleAroundAHoleLosesTheArcInside) {
    // Centre (2, 5), r = 2.5: the arc beyond x = 0 spans 2 acos(2/2.5); the arc in the hole [4,6]^2
    // runs between its edges y = 4 and y = 6, met at x = 2 + sqrt(2.5^2 - 1), so 2 atan(1/sqrt(5.25)).
    const Window w = Window::fromWkt(kSquareWithHole);
    const double outside = 2 * std::acos(2 / 2.5) + 2 * std::atan(1 / std::sqrt(5.25));
    EXPECT_NEAR(circleFractionInside(w, {2, 5}, 2.5), 1 - outside / (2 * M_PI), 1e-12);
    // A circle enclosing the hole, not touching the outer ring, loses nothing.
    EXPECT_DOUBLE_EQ(circleFractionInside(w, {5, 3.5}, 3), 1.0);
}

// Circles that touch an edge or pass through a vertex without crossing the boundary: the polygon's
// arcs must agree with the rectangle's formula (spatstat's ripleybox), an independent computation, on
// the same square. Such ties come with coordinates in whole metres. Tolerance: both are exact up to
// rounding in atan2 and acos.
TEST(WindowWithHoles, CirclesTouchingEdgesOrThroughVerticesKeepTheirArcs) {
    const Window square = Window::rectangle(0, 0, 20, 20);
    const Window polygon = Window::polygon({Vec(0, 0), Vec(20, 0), Vec(20, 20), Vec(0, 20)});
    ASSERT_FALSE(polygon.isRectangle());
    // Tangent to y = 0, crossing x = 20 at 3 m from the centre: the arc beyond it, 2 acos(3/5), is lost.
    EXPECT_NEAR(circleFractionInside(polygon, {17, 5}, 5), 1 - 2 * std::acos(0.6) / (2 * M_PI), 1e-12);
    // Through the corners (0, 0) and (20, 0), crossing the sides at y = 4: inside only the arc over the
    // top, between the directions atan2(2, +-10).
    EXPECT_NEAR(circleFractionInside(polygon, {10, 2}, std::sqrt(104.0)), (M_PI - 2 * std::atan2(2, 10)) / (2 * M_PI), 1e-12);
    // Tangent to all four sides from inside: all of it.
    EXPECT_NEAR(circleFractionInside(polygon, {10, 10}, 10), 1.0, 1e-12);
    for (const auto& [c, r] : std::vector<std::pair<Vec, double>>{{{17, 5}, 5}, {{10, 2}, std::sqrt(104.0)}, {{10, 10}, 10},
                                                                   {{3, 4}, 5}, {{5, 5}, std::sqrt(50.0)}, {{15, 15}, 5}})
        EXPECT_NEAR(circleFractionInside(polygon, c, r), circleFractionInside(square, c, r), 1e-12) << c.transpose() << " r " << r;
}

// Plots in projected coordinates (UTM: x ~ 6e5, y ~ 5e6 m) are checked as the same plots in a local
// frame: the validity tests' tolerance follows the rings' extent, not the coordinates' size alone.
TEST(WindowWithHoles, PlotsInProjectedCoordinatesAreCheckedAsLocalOnes) {
    const Vec o(600000, 5100000);
    const auto square = [&](double x, double y, double side) {
        return std::vector<Vec>{o + Vec(x, y), o + Vec(x + side, y), o + Vec(x + side, y + side), o + Vec(x, y + side)};
    };
    EXPECT_NEAR(Window::polygon(square(0, 0, 4)).area(), 16, 1e-6);
    EXPECT_NEAR(Window::polygon(square(0, 0, 50), {square(20, 20, 3)}).area(), 2500 - 9, 1e-6);
    // Still refused there: a ring on one line, and a hole touching the outer ring.
    EXPECT_THROW(Window::polygon({o, o + Vec(10, 10), o + Vec(20, 20)}), sylva::InputError);
    EXPECT_THROW(Window::polygon(square(0, 0, 50), {square(0, 20, 3)}), sylva::InputError);
}

TEST(WindowWithHoles, BadHolesAreInputErrorsNamingTheHole) {
    EXPECT_NE(errorOf("POLYGON((0 0, 10 0, 10 10, 0 10), (8 8, 12 8, 12 12, 8 12))").find("hole 1 of the polygon window is "
                                                                                        "not strictly inside"),
              std::string::npos);
    EXPECT_NE(errorOf("POLYGON((0 0, 10 0, 10 10, 0 10), (20 20, 21 20, 21 21))").find("not strictly inside"), std::string::npos);
    EXPECT_NE(errorOf("POLYGON((0 0, 10 0, 10 10, 0 10), (1 1, 4 1, 4 4, 1 4), (3 3, 6 3, 6 6, 3 6))")
                  .find("hole 2 of the polygon window overlaps or touches hole 1"),
              std::string::npos);
    EXPECT_NE(errorOf("POLYGON((0 0, 10 0, 10 10, 0 10), (1 1, 8 1, 8 8, 1 8), (3 3, 4 3, 4 4, 3 4))").find("overlaps"),
              std::string::npos);  // a hole inside another
    EXPECT_NE(errorOf("POLYGON((0 0, 10 0, 10 10, 0 10), (1 1, 2 2, 1 2, 2 1))").find("hole 1 of the polygon window intersects itself"),
              std::string::npos);
    EXPECT_NE(errorOf("POLYGON((0 0, 10 0, 10 10, 0 10), 1 1, 2 1, 2 2)").find("own parentheses"), std::string::npos);
}

// spatstat's gordon: 99 points in a polygon of 84 vertices with two holes. The window's area,
// perimeter, set covariance (overlap.owin) and Ripley weights (edge.Ripley) are exact in both codes:
// they agree to rounding, 1e-9 relative.
TEST(GordonSpatstat, WindowAndEdgeCorrectionsAgreeWithSpatstat) {
    const Window w = td::spatstatWindow("gordon");
    ASSERT_EQ(w.rings().size(), 3u);
    EXPECT_NEAR(w.area(), td::spatstatColumn("gordon", "summary", "area_m2")[0], 1e-9 * w.area());
    EXPECT_NEAR(w.perimeter(), td::spatstatColumn("gordon", "summary", "perimeter_m")[0], 1e-9 * w.perimeter());

    const TranslationCorrection t(w);
    const auto vx = td::spatstatColumn("gordon", "setcov", "vx"), vy = td::spatstatColumn("gordon", "setcov", "vy");
    const auto overlap = td::spatstatColumn("gordon", "setcov", "overlap");
    for (std::size_t k = 0; k < vx.size(); ++k)
        EXPECT_NEAR(t.setCovariance({vx[k], vy[k]}), overlap[k], 1e-9 * w.area()) << vx[k] << "," << vy[k];

    const auto pts = td::spatstatPoints("gordon");
    const auto point = td::spatstatColumn("gordon", "ripley", "point"), r = td::spatstatColumn("gordon", "ripley", "r");
    const auto weight = td::spatstatColumn("gordon", "ripley", "weight");
    int corrected = 0;
    for (std::size_t k = 0; k < point.size(); ++k) {
        EXPECT_NEAR(isotropicWeight(w, pts[static_cast<std::size_t>(point[k])], r[k]), weight[k], 1e-9 * weight[k])
            << "point " << point[k] << " r " << r[k];
        corrected += weight[k] > 1;
    }
    EXPECT_GT(corrected, 50);  // many circles cross the outer ring or a hole: the comparison has content
}

TEST(GordonSpatstat, ClarkEvansAgreesWithClarkevans) {
    const Window w = td::spatstatWindow("gordon");
    const ClarkEvansIndex ce = clarkEvans(td::spatstatPoints("gordon"), w);
    const auto ref = [](const char* column) { return td::spatstatColumn("gordon", "summary", column)[0]; };
    ASSERT_TRUE(ce.naive && ce.cdf && ce.guard);
    EXPECT_FALSE(ce.donnelly.has_value());  // rectangles only, as in spatstat
    // Same arithmetic as spatstat's (summary.csv carries 15 digits).
    EXPECT_NEAR(ce.meanNearestNeighbour, ref("mean_nn"), 1e-9 * ref("mean_nn"));
    EXPECT_NEAR(*ce.naive, ref("ce_naive"), 1e-9);  // uses the area with the holes taken out
    EXPECT_NEAR(*ce.cdf, ref("ce_cdf"), 1e-9);      // uses the distances to every ring
    // spatstat erodes the polygon with polyclip (arcs approximated at the corners); the same points
    // lie in both clip regions, so the index is the same.
    EXPECT_EQ(ce.nInGuard, static_cast<std::size_t>(ref("n_in_guard")));
    EXPECT_NEAR(*ce.guard, ref("ce_guard"), 1e-9);
}

TEST(GordonSpatstat, PairCorrelationAgreesWithPcf) {
    const td::ReferencePcf ref = td::spatstatPcf("gordon");
    const auto pts = td::spatstatPoints("gordon");
    const Window w = td::spatstatWindow("gordon");
    const PairCorrelation g = pairCorrelation(pts, w, ref.r.back(), ref.r.size() + 1);
    double worstIso = 0, worstTrans = 0;
    int compared = 0;
    for (std::size_t k = 0; k < ref.r.size(); ++k) {
        if (ref.iso[k] <= 0.1) continue;  // as for the other stands: relative differences of a tiny g mean nothing
        worstIso = std::max(worstIso, std::abs(g.iso[k + 1] / ref.iso[k] - 1));
        worstTrans = std::max(worstTrans, std::abs(g.trans[k + 1] / ref.trans[k] - 1));
        ++compared;
    }
    std::cout << "gordon: pcf vs spatstat over " << compared << " r values, max rel. diff iso " << worstIso << ", trans "
              << worstTrans << "\n";
    ASSERT_GT(compared, 30);
    // Ripley's weights are exact in both codes and the kernel sum emulates R's density: the 1e-3.
    EXPECT_LT(worstIso, 1e-3);
    // spatstat's translation weights on a polygon come from a pixel image of the set covariance
    // (edge.Trans without exact = TRUE), ours from exact overlaps (checked above against
    // overlap.owin): the pixels' error sets the difference (0.32 % measured on this 2 200 m2 window).
    EXPECT_LT(worstTrans, 1e-2);
}

}  // namespace

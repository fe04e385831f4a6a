// Observation windows: rectangles, polygons and their WKT text.
#include <gtest/gtest.h>

#include <cmath>

#include "libcommon/InputError.hpp"
#include "libstand/Window.hpp"

using sylva::InputError;
using sylva::stand::Window;

namespace {

template <class F>
std::string errorOf(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(Window, RectangleGeometry) {
    const Window w = Window::rectangle(2, 1, 12, 6);
    EXPECT_TRUE(w.isRectangle());
    EXPECT_DOUBLE_EQ(w.area(), 50);
    EXPECT_DOUBLE_EQ(w.perimeter(), 30);
    EXPECT_TRUE(w.contains({2, 1}));  // closed: corners and edges are inside
    EXPECT_TRUE(w.contains({12, 3}));
    EXPECT_FALSE(w.contains({12.0001, 3}));
    EXPECT_DOUBLE_EQ(w.distanceToBoundary({4, 5}), 1);
    EXPECT_EQ(w.describe(), "rectangle [2,12]x[1,6]");
}

TEST(Window, DegenerateRectangleIsAnInputError) {
    EXPECT_THROW(Window::rectangle(0, 0, 0, 5), InputError);
    EXPECT_THROW(Window::rectangle(0, 5, 3, 1), InputError);
    EXPECT_NE(errorOf([] { Window::rectangle(0, 0, 10, 0); }).find("degenerate"), std::string::npos);
}

TEST(Window, LShapedPolygonGeometry) {
    // Given clockwise and closed: normalised to counter-clockwise, closing vertex dropped.
    const Window w = Window::polygon({{0, 0}, {0, 10}, {4, 10}, {4, 4}, {10, 4}, {10, 0}, {0, 0}});
    EXPECT_FALSE(w.isRectangle());
    EXPECT_EQ(w.vertices().size(), 6u);
    EXPECT_DOUBLE_EQ(w.area(), 64);       // 10x4 + 4x6
    EXPECT_DOUBLE_EQ(w.perimeter(), 40);  // same as its 10x10 bounding square
    EXPECT_EQ(w.lower(), Eigen::Vector2d(0, 0));
    EXPECT_EQ(w.upper(), Eigen::Vector2d(10, 10));
    EXPECT_TRUE(w.contains({2, 8}));
    EXPECT_TRUE(w.contains({4, 7}));  // on the inner edge
    EXPECT_FALSE(w.contains({7, 7}));  // the missing corner
    EXPECT_DOUBLE_EQ(w.distanceToBoundary({3, 3}), std::sqrt(2.0));  // to the re-entrant vertex (4, 4)
    EXPECT_DOUBLE_EQ(w.distanceToBoundary({5, 3}), 1);
    double twice = 0;  // counter-clockwise: positive signed area
    const auto& v = w.vertices();
    for (std::size_t i = 0; i < v.size(); ++i)
        twice += v[i].x() * v[(i + 1) % v.size()].y() - v[i].y() * v[(i + 1) % v.size()].x();
    EXPECT_DOUBLE_EQ(twice, 128);
}

TEST(Window, BadPolygonsAreInputErrors) {
    EXPECT_NE(errorOf([] { Window::polygon({{0, 0}, {1, 1}}); }).find("at least 3"), std::string::npos);
    EXPECT_NE(errorOf([] { Window::polygon({{0, 0}, {1, 1}, {2, 2}}); }).find("area is zero"), std::string::npos);
    // A bow tie crosses itself.
    EXPECT_NE(errorOf([] { Window::polygon({{0, 0}, {2, 0}, {0, 2}, {2, 2}}); }).find("intersects itself"),
              std::string::npos);
    // An edge folding back onto the previous one.
    EXPECT_NE(errorOf([] { Window::polygon({{0, 0}, {4, 0}, {2, 0}, {2, 3}}); }).find("intersects itself"),
              std::string::npos);
}

TEST(Window, WktPolygon) {
    const Window w = Window::fromWkt("  polygon ((0 0, 10 0, 10 4, 4 4, 4 10, 0 10, 0 0)) ");
    EXPECT_DOUBLE_EQ(w.area(), 64);
    EXPECT_EQ(w.describe(), "polygon of 6 vertices");
    const Window r = Window::fromWkt("POLYGON((0 0,56 0,56 38,0 38,0 0))");
    EXPECT_DOUBLE_EQ(r.area(), 56 * 38);
    EXPECT_FALSE(r.isRectangle());  // as in spatstat, a polygon stays a polygon
}

TEST(Window, BadWktIsAnInputErrorNamingTheProblem) {
    // A hole with a vertex on the outer ring (the triangle's diagonal y = x).
    EXPECT_NE(errorOf([] { Window::fromWkt("POLYGON((0 0, 1 0, 1 1, 0 0), (0.2 0.2, 0.4 0.2, 0.3 0.3, 0.2 0.2))"); })
                  .find("hole 1 of the polygon window is not strictly inside"),
              std::string::npos);
    EXPECT_NE(errorOf([] { Window::fromWkt("LINESTRING(0 0, 1 1)"); }).find("POLYGON"), std::string::npos);
    EXPECT_NE(errorOf([] { Window::fromWkt("POLYGON((0 0, 1 x, 1 1, 0 0))"); }).find("'x y' pair"), std::string::npos);
    EXPECT_NE(errorOf([] { Window::fromWkt("POLYGON((0 0, 1 0, 1 1, 0 0)"); }).find("missing"), std::string::npos);
    EXPECT_NE(errorOf([] { Window::fromWkt("POLYGON((0 0, 1 0, 1 1, 0 0)) x"); }).find("trailing"), std::string::npos);
    EXPECT_NE(errorOf([] { Window::fromWkt("POLYGON(0 0, 1 0, 1 1, 0 0)"); }).find("own parentheses"),
              std::string::npos);
    EXPECT_NE(errorOf([] { Window::fromWkt("POLYGON((0 0, 1 1, 2 2, 0 0))"); }).find("area is zero"), std::string::npos);
}

}  // namespace

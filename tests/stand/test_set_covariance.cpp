// The set covariance |W ∩ (W + v)| of polygon windows (libstand/src/PolygonSetCovariance, through
// TranslationCorrection) against independent computations: sums over a decomposition of W into
// rectangles or triangles, each pair clipped directly. Exact in both: agreement to rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

#include "libstand/EdgeCorrection.hpp"

using namespace sylva::stand;
using Vec = Eigen::Vector2d;

namespace {

// Area of the intersection of two convex counter-clockwise polygons (Sutherland-Hodgman).
double convexOverlap(std::vector<Vec> poly, const std::vector<Vec>& clip) {
    for (std::size_t e = 0; e < clip.size() && !poly.empty(); ++e) {
        const Vec a = clip[e], edge = clip[(e + 1) % clip.size()] - a;
        std::vector<Vec> next;
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const Vec& p = poly[i];
            const Vec& q = poly[(i + 1) % poly.size()];
            const double sp = cross2(edge, p - a), sq = cross2(edge, q - a);
            if (sp >= 0) next.push_back(p);
            if ((sp >= 0) != (sq >= 0)) next.push_back(p + (q - p) * (sp / (sp - sq)));
        }
        poly = next;
    }
    return poly.size() < 3 ? 0.0 : signedArea(poly);
}

// |W ∩ (W + v)| for W the union of convex pieces with disjoint interiors.
double piecewise(const std::vector<std::vector<Vec>>& pieces, const Vec& v) {
    double sum = 0;
    for (const auto& a : pieces)
        for (auto b : pieces) {
            for (Vec& p : b) p += v;
            sum += convexOverlap(a, b);
        }
    return sum;
}

std::string wkt(const std::vector<Vec>& ring) {
    std::ostringstream s;
    s.precision(17);
    s << "POLYGON((";
    for (const Vec& p : ring) s << p.x() << " " << p.y() << ", ";
    s << ring.front().x() << " " << ring.front().y() << "))";
    return s.str();
}

}  // namespace

// A star of 40 spikes (radii 10 and 4 alternating), the union of the triangles of its fan from the
// centre: shifts of every direction and length, where spikes cross many spikes.
TEST(SetCovariance, SpikyStarEqualsItsTrianglesPairwise) {
    std::vector<Vec> ring;
    for (int k = 0; k < 80; ++k) {
        const double a = 2 * M_PI * k / 80, r = k % 2 ? 4 : 10;
        ring.emplace_back(20 + r * std::cos(a), 20 + r * std::sin(a));
    }
    std::vector<std::vector<Vec>> triangles;
    for (std::size_t k = 0; k < ring.size(); ++k) triangles.push_back({Vec(20, 20), ring[k], ring[(k + 1) % ring.size()]});
    const TranslationCorrection t(Window::fromWkt(wkt(ring)));
    for (const Vec& v : {Vec(0.3, 0.1), Vec(-2.5, 1.7), Vec(4, -3), Vec(7.7, 7.7), Vec(-12, 0.5), Vec(0, 5), Vec(15, -9)}) {
        const double want = piecewise(triangles, v);
        EXPECT_NEAR(t.setCovariance(v), want, 1e-9 * 400) << v.transpose();
    }
}

// A comb of 6 teeth on a base, with integer shifts: edges overlap edges, vertices fall on vertices and
// edges, exactly (the cases the simulation of simplicity decides). Against its rectangles.
TEST(SetCovariance, CombWithCoincidentEdgesEqualsItsRectangles) {
    std::vector<Vec> ring{{0, 0}, {12, 0}, {12, 2}};
    std::vector<std::vector<Vec>> rectangles{{{0, 0}, {12, 0}, {12, 2}, {0, 2}}};
    for (int k = 5; k >= 0; --k) {  // teeth [2k, 2k+1] x [2, 6], walked right to left
        ring.insert(ring.end(), {Vec(2 * k + 1, 2), Vec(2 * k + 1, 6), Vec(2 * k, 6), Vec(2 * k, 2)});
        rectangles.push_back({Vec(2 * k, 2), Vec(2 * k + 1, 2), Vec(2 * k + 1, 6), Vec(2 * k, 6)});
    }
    ring.pop_back();  // (0, 2) closes the ring
    ring.emplace_back(0, 2);
    const TranslationCorrection t(Window::fromWkt(wkt(ring)));
    for (int dx = -13; dx <= 13; ++dx)
        for (int dy = -7; dy <= 7; ++dy) {
            const Vec v(dx, dy);
            EXPECT_NEAR(t.setCovariance(v), piecewise(rectangles, v), 1e-9) << v.transpose();
        }
}

#include "libstand/NearestNeighbours.hpp"

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_2.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <boost/iterator/counting_iterator.hpp>
#include <algorithm>
#include <cmath>
#include <limits>

namespace sylva::stand {
namespace {

// Distances are computed from the input doubles; no construction needs exact arithmetic.
using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_2;

// The tree stores indices into the point vector, so that searches report which point was found.
using PointMap = CGAL::Pointer_property_map<Point>::type;
using Traits = CGAL::Search_traits_adapter<std::size_t, PointMap, CGAL::Search_traits_2<Kernel>>;
using KNeighbourSearch = CGAL::Orthogonal_k_neighbor_search<Traits>;
using Tree = KNeighbourSearch::Tree;
using Distance = KNeighbourSearch::Distance;
using Sphere = CGAL::Fuzzy_sphere<Traits>;

std::vector<Point> toCgal(const std::vector<Eigen::Vector2d>& points) {
    std::vector<Point> out;
    out.reserve(points.size());
    for (const auto& p : points) out.emplace_back(p.x(), p.y());
    return out;
}

}  // namespace

std::vector<double> nearestNeighbourDistances(const std::vector<Eigen::Vector2d>& points) {
    const std::size_t n = points.size();
    std::vector<double> nnd(n, std::numeric_limits<double>::infinity());
    if (n < 2) return nnd;
    std::vector<Point> pts = toCgal(points);
    PointMap map = CGAL::make_property_map(pts);
    Tree tree(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(n),
              Tree::Splitter(), Traits(map));
    Distance distance(map);
    for (std::size_t i = 0; i < n; ++i) {
        // The two nearest entries are the point itself and its neighbour; with a coincident point both
        // are at distance 0, which is then the answer whichever of them is "self".
        KNeighbourSearch search(tree, pts[i], 2, 0, true, distance);
        for (auto it = search.begin(); it != search.end(); ++it)
            if (it->first != i || it->second > 0) nnd[i] = std::min(nnd[i], std::sqrt(it->second));
    }
    return nnd;
}

std::vector<ClosePair> closePairs(const std::vector<Eigen::Vector2d>& points, double rmax) {
    const std::size_t n = points.size();
    std::vector<ClosePair> pairs;
    if (n < 2) return pairs;
    std::vector<Point> pts = toCgal(points);
    PointMap map = CGAL::make_property_map(pts);
    Tree tree(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(n),
              Tree::Splitter(), Traits(map));
    tree.build();
    // Room for a Poisson pattern's expected number of pairs (plus a margin), so that the vector is
    // not copied over and over while it grows to millions of pairs.
    Eigen::Vector2d boxLo = points.front(), boxHi = points.front();
    for (const auto& p : points) {
        boxLo = boxLo.cwiseMin(p);
        boxHi = boxHi.cwiseMax(p);
    }
    const double boxArea = std::max((boxHi - boxLo).prod(), 1e-12);
    const double perPoint = std::min(static_cast<double>(n - 1), static_cast<double>(n) * M_PI * rmax * rmax / boxArea);
    pairs.reserve(static_cast<std::size_t>(1.2 * static_cast<double>(n) * perPoint) + 16);
    std::vector<std::size_t> found;
    const double r2 = rmax * rmax;
    for (std::size_t i = 0; i < n; ++i) {
        found.clear();
        // A slightly larger sphere, then the exact test: the fuzzy boundary decides nothing.
        tree.search(std::back_inserter(found), Sphere(pts[i], rmax * (1 + 1e-9) + 1e-12, 0, Traits(map)));
        for (std::size_t j : found) {
            if (j == i) continue;
            const double d2 = (points[j] - points[i]).squaredNorm();
            if (d2 <= r2) pairs.push_back({i, j, std::sqrt(d2)});
        }
    }
    return pairs;
}

}  // namespace sylva::stand

#include "libstand/EdgeCorrection.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/partition_2.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <list>

namespace sylva::stand {
namespace {

using Vec = Eigen::Vector2d;

double cross(const Vec& a, const Vec& b) { return cross2(a, b); }

// Area of the intersection of two convex counter-clockwise polygons, the second shifted by v
// (Sutherland-Hodgman: clip the first by each edge of the second).
double convexOverlap(const std::vector<Vec>& subject, const std::vector<Vec>& clip, const Vec& v) {
    thread_local std::vector<Vec> poly, next;  // called millions of times: no allocation per call
    poly.assign(subject.begin(), subject.end());
    for (std::size_t e = 0; e < clip.size() && !poly.empty(); ++e) {
        const Vec a = clip[e] + v, b = clip[(e + 1) % clip.size()] + v;
        const Vec edge = b - a;
        next.clear();
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const Vec& p = poly[i];
            const Vec& q = poly[(i + 1) % poly.size()];
            const double sp = cross(edge, p - a), sq = cross(edge, q - a);
            if (sp >= 0) next.push_back(p);
            if ((sp >= 0) != (sq >= 0)) next.push_back(p + (q - p) * (sp / (sp - sq)));
        }
        poly.swap(next);
    }
    return poly.size() < 3 ? 0.0 : signedArea(poly);
}

// Convex pieces of a simple polygon (Hertel-Mehlhorn via CGAL): the overlap of two polygons is then a
// sum of convex-convex overlaps, which clipping computes exactly.
std::vector<std::vector<Vec>> convexPartition(const std::vector<Vec>& vertices) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Traits = CGAL::Partition_traits_2<K>;
    using Polygon = Traits::Polygon_2;
    Polygon polygon;
    for (const auto& v : vertices) polygon.push_back(Traits::Point_2(v.x(), v.y()));
    std::list<Polygon> parts;
    CGAL::approx_convex_partition_2(polygon.vertices_begin(), polygon.vertices_end(), std::back_inserter(parts));
    std::vector<std::vector<Vec>> out;
    for (const auto& part : parts) {
        std::vector<Vec> piece;
        for (auto it = part.vertices_begin(); it != part.vertices_end(); ++it) piece.emplace_back(it->x(), it->y());
        out.push_back(std::move(piece));
    }
    return out;
}

}  // namespace

TranslationCorrection::TranslationCorrection(const Window& window) : window_(window) {
    if (window.isRectangle()) return;
    // With holes H_k in the outer ring O, 1_W = 1_O - sum_k 1_{H_k}, so |W ∩ (W + v)| is the signed
    // sum of the pieces' overlaps: outer pieces count +1, hole pieces -1.
    for (std::size_t r = 0; r < window.rings().size(); ++r)
        for (auto& part : convexPartition(window.rings()[r])) {
            Eigen::AlignedBox2d box;
            for (const Vec& p : part) box.extend(p);
            partBoxes_.push_back(box);
            partSigns_.push_back(r == 0 ? 1.0 : -1.0);
            convexParts_.push_back(std::move(part));
        }
}

double TranslationCorrection::setCovariance(const Eigen::Vector2d& v) const {
    if (window_.isRectangle()) {
        const Vec size = window_.upper() - window_.lower();
        return std::max(0.0, size.x() - std::abs(v.x())) * std::max(0.0, size.y() - std::abs(v.y()));
    }
    // A polygon of many vertices has many pieces, most of which are far apart once shifted: their
    // boxes tell them apart (issue 13: 1 000 vertices took 80 s for 60 points). Clipping costs the
    // clip's edges times the subject's vertices: the smaller piece is the subject, by
    // |A ∩ (B + v)| = |B ∩ (A - v)|.
    double overlap = 0;
    for (std::size_t a = 0; a < convexParts_.size(); ++a)
        for (std::size_t b = 0; b < convexParts_.size(); ++b) {
            const Eigen::AlignedBox2d shifted(partBoxes_[b].min() + v, partBoxes_[b].max() + v);
            if (!partBoxes_[a].intersects(shifted)) continue;
            const auto& A = convexParts_[a];
            const auto& B = convexParts_[b];
            overlap += partSigns_[a] * partSigns_[b] * (A.size() <= B.size() ? convexOverlap(A, B, v) : convexOverlap(B, A, -v));
        }
    return std::max(0.0, overlap);  // the signed sum can round below zero where W and W + v barely meet
}

double TranslationCorrection::weight(const Eigen::Vector2d& v) const {
    const double cov = setCovariance(v);
    return cov > 0 ? std::min(maxEdgeWeight, window_.area() / cov) : maxEdgeWeight;
}

double circleFractionInside(const Window& window, const Eigen::Vector2d& c, double r) {
    if (r <= 0 || window.distanceToBoundary(c) >= r) return 1.0;
    if (window.isRectangle()) {
        // spatstat's ripleybox: the arc outside each (prolonged) edge is 2 acos(d/r), but not beyond
        // the directions of the rectangle's corners, which exactly removes the double counting.
        const Vec lo = window.lower(), hi = window.upper();
        const double dL = c.x() - lo.x(), dR = hi.x() - c.x(), dD = c.y() - lo.y(), dU = hi.y() - c.y();
        const auto half = [r](double d) { return d < r ? std::acos(d / r) : 0.0; };
        // Arc beyond the edge at distance d, clipped at the corner directions atan2(side1, d), atan2(side2, d).
        const auto beyond = [&](double d, double side1, double side2) {
            const double a = half(d);
            return a > 0 ? std::min(a, std::atan2(side1, d)) + std::min(a, std::atan2(side2, d)) : 0.0;
        };
        const double outside = beyond(dL, dU, dD) + beyond(dR, dU, dD) + beyond(dU, dL, dR) + beyond(dD, dL, dR);
        // A centre at a corner sees a quarter of the circle, which the arc sums alone do not give.
        const auto atEdge = [](double d) { return std::abs(d) < std::numeric_limits<double>::epsilon() ? 1 : 0; };
        const bool corner = atEdge(dL) + atEdge(dR) + atEdge(dD) + atEdge(dU) >= 2;
        return 1 - outside / (2 * M_PI) - (corner ? 0.25 : 0.0);
    }
    // Polygon: cut the circle where it crosses the edges and keep the arcs whose midpoints are inside.
    std::vector<double> angles;
    for (const auto& v : window.rings()) {
        for (std::size_t k = 0; k < v.size(); ++k) {
            const Vec a = v[k] - c, d = v[(k + 1) % v.size()] - v[k];
            // |a + t d| = r:  (d.d) t² + 2 (a.d) t + (a.a - r²) = 0
            const double qa = d.squaredNorm(), qb = 2 * a.dot(d), qc = a.squaredNorm() - r * r;
            const double disc = qb * qb - 4 * qa * qc;
            if (disc < 0) continue;
            for (const double t : {(-qb - std::sqrt(disc)) / (2 * qa), (-qb + std::sqrt(disc)) / (2 * qa)})
                if (t >= 0 && t <= 1) {
                    const Vec p = a + t * d;
                    angles.push_back(std::atan2(p.y(), p.x()));
                }
        }
    }
    if (angles.empty()) return window.contains(c + Vec(r, 0)) ? 1.0 : 0.0;
    std::sort(angles.begin(), angles.end());
    double inside = 0;
    for (std::size_t k = 0; k < angles.size(); ++k) {
        const double from = angles[k];
        const double to = k + 1 < angles.size() ? angles[k + 1] : angles.front() + 2 * M_PI;
        const double mid = 0.5 * (from + to);
        if (to > from && window.contains(c + r * Vec(std::cos(mid), std::sin(mid)))) inside += to - from;
    }
    return inside / (2 * M_PI);
}

double isotropicWeight(const Window& window, const Eigen::Vector2d& c, double r) {
    const double fraction = circleFractionInside(window, c, r);
    return fraction > 0 ? std::clamp(1 / fraction, 1.0, maxEdgeWeight) : maxEdgeWeight;
}

}  // namespace sylva::stand

#include "libstand/EdgeCorrection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "PolygonSetCovariance.hpp"

namespace sylva::stand {
namespace {
using Vec = Eigen::Vector2d;
}  // namespace

TranslationCorrection::TranslationCorrection(const Window& window) : window_(window) {
    if (!window.isRectangle()) polygon_ = std::make_shared<const PolygonSetCovariance>(window);
}

double TranslationCorrection::setCovariance(const Eigen::Vector2d& v) const {
    if (polygon_) return (*polygon_)(v);
    const Vec size = window_.upper() - window_.lower();
    return std::max(0.0, size.x() - std::abs(v.x())) * std::max(0.0, size.y() - std::abs(v.y()));
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
                if (t >= 0 && t < 1) {  // half-open: a crossing at a vertex counts once
                    const Vec p = a + t * d;
                    angles.push_back(std::atan2(p.y(), p.x()));
                }
        }
    }
    if (angles.empty()) return window.contains(c + Vec(r, 0)) ? 1.0 : 0.0;
    std::sort(angles.begin(), angles.end());
    // Each arc between neighbouring crossings is classified by its own midpoint. Telling them by
    // alternation (one test, then in and out at each crossing) goes wrong where the circle only
    // touches an edge or passes through a vertex without crossing: ties that survey coordinates in
    // whole metres produce. An arc of (almost) no length adds (almost) nothing, whichever way its
    // midpoint falls.
    double inside = 0;
    for (std::size_t k = 0; k < angles.size(); ++k) {
        const double from = angles[k], to = k + 1 < angles.size() ? angles[k + 1] : angles.front() + 2 * M_PI;
        const double mid = 0.5 * (from + to);
        if (window.contains(c + r * Vec(std::cos(mid), std::sin(mid)))) inside += to - from;
    }
    return inside / (2 * M_PI);
}

double isotropicWeight(const Window& window, const Eigen::Vector2d& c, double r) {
    const double fraction = circleFractionInside(window, c, r);
    return fraction > 0 ? std::clamp(1 / fraction, 1.0, maxEdgeWeight) : maxEdgeWeight;
}

}  // namespace sylva::stand

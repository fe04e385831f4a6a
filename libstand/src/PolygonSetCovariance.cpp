#include "PolygonSetCovariance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace sylva::stand {

namespace {

using Vec = Eigen::Vector2d;

// A fixed direction with no rational slope, so it is parallel to no edge of real data.
const Vec kGeneric(0.7548776662466927, 0.5698402909980532);

// Sign of value, or of its derivative in ε where the value is exactly zero.
bool positive(double value, double derivative) { return value != 0 ? value > 0 : derivative > 0; }

}  // namespace

PolygonSetCovariance::PolygonSetCovariance(const Window& window) : window_(window), corner_(window.lower()), area_(window.area()) {
    const Vec size = window.upper() - window.lower();
    const double extent = std::max(size.x(), size.y());
    tolerance_ = 1e-9 * extent;
    for (std::size_t r = 0; r < window.rings().size(); ++r) {
        std::vector<Vec> ring = window.rings()[r];
        for (Vec& p : ring) p -= corner_;
        if (r > 0) std::reverse(ring.begin(), ring.end());  // holes clockwise: the window on the left
        ringStarts_.push_back(edges_.size());
        for (std::size_t i = 0; i < ring.size(); ++i) edges_.push_back({ring[i], ring[(i + 1) % ring.size()]});
    }
    ringStarts_.push_back(edges_.size());
    const int side = std::max(1, static_cast<int>(2 * std::sqrt(static_cast<double>(edges_.size()))));
    cell_ = extent / side;
    nx_ = std::max(1, static_cast<int>(std::ceil(size.x() / cell_)));
    ny_ = std::max(1, static_cast<int>(std::ceil(size.y() / cell_)));
    cells_.resize(static_cast<std::size_t>(nx_) * ny_);
    for (std::size_t e = 0; e < edges_.size(); ++e)
        forCellsAlong(edges_[e].a, edges_[e].b, [&](std::size_t cell) { cells_[cell].push_back(static_cast<int>(e)); });
    // Prefix sums of the cells' edge counts: whether a box meets any edge's cell in O(1).
    occupied_.assign(static_cast<std::size_t>(nx_ + 1) * (ny_ + 1), 0);
    for (int j = 0; j < ny_; ++j)
        for (int i = 0; i < nx_; ++i)
            occupied_[static_cast<std::size_t>(j + 1) * (nx_ + 1) + i + 1] =
                static_cast<long>(cells_[static_cast<std::size_t>(j) * nx_ + i].size()) +
                occupied_[static_cast<std::size_t>(j) * (nx_ + 1) + i + 1] + occupied_[static_cast<std::size_t>(j + 1) * (nx_ + 1) + i] -
                occupied_[static_cast<std::size_t>(j) * (nx_ + 1) + i];
    for (std::size_t r = 0; r + 1 < ringStarts_.size(); ++r) {
        chainStarts_.push_back(chains_.size());
        for (std::size_t k = ringStarts_[r]; k < ringStarts_[r + 1]; k += kChain) {
            Chain c;
            c.edges = std::min(kChain, ringStarts_[r + 1] - k);
            for (std::size_t e = k; e < k + c.edges; ++e) {
                c.box.extend(edges_[e].a);
                c.box.extend(edges_[e].b);
                c.sumCross += cross2(edges_[e].a, edges_[e].b);
                c.sumVector += edges_[e].b - edges_[e].a;
            }
            chains_.push_back(c);
        }
    }
}

// Calls f(cell) for each grid cell the segment passes through, column by column (a long slanted
// edge meets a few cells, where its bounding box would meet many). Widened by a hair so that a
// segment through a cell's corner is listed in all the cells it touches: two segments that cross are
// then always listed in a common cell.
template <class F>
void PolygonSetCovariance::forCellsAlong(const Vec& p, const Vec& q, F&& f) const {
    const double eps = 1e-9 * cell_, width = nx_ * cell_, height = ny_ * cell_;
    const double x0 = std::min(p.x(), q.x()), x1 = std::max(p.x(), q.x());
    if (x1 < -eps || x0 > width + eps || std::max(p.y(), q.y()) < -eps || std::min(p.y(), q.y()) > height + eps) return;
    const auto index = [&](double x, int n) { return std::clamp(static_cast<int>(std::floor(x / cell_)), 0, n - 1); };
    const double slope = x1 > x0 ? (q.y() - p.y()) / (q.x() - p.x()) : 0;
    for (int i = index(x0 - eps, nx_), last = index(x1 + eps, nx_); i <= last; ++i) {
        double lo = std::min(p.y(), q.y()), hi = std::max(p.y(), q.y());
        if (x1 - x0 > eps) {  // the segment's y over the column's share of its x range
            const double xa = std::max(x0, i * cell_), xb = std::min(x1, (i + 1) * cell_);
            const double ya = p.y() + (xa - p.x()) * slope, yb = p.y() + (xb - p.x()) * slope;
            lo = std::min(ya, yb);
            hi = std::max(ya, yb);
        }
        if (hi < -eps || lo > height + eps) continue;
        for (int j = index(lo - eps, ny_), top = index(hi + eps, ny_); j <= top; ++j) f(static_cast<std::size_t>(j) * nx_ + i);
    }
}

// Calls f(edge) once for each edge listed in the cells the segment passes through.
template <class F>
void PolygonSetCovariance::forEdgesNear(const Vec& p, const Vec& q, F&& f) const {
    thread_local std::vector<std::uint64_t> seen;  // an edge listed in several cells is met once
    thread_local std::uint64_t stamp = 0;
    if (seen.size() < edges_.size()) seen.resize(edges_.size(), 0);
    ++stamp;
    forCellsAlong(p, q, [&](std::size_t cell) {
        for (int e : cells_[cell]) {
            if (seen[e] == stamp) continue;
            seen[e] = stamp;
            f(e);
        }
    });
}

bool PolygonSetCovariance::inside(const Vec& p, bool& clear) const {
    const Vec at = p + corner_;  // back from W's frame
    clear = window_.distanceToBoundary(at) >= tolerance_;
    return window_.contains(at);
}

// ½∮ over the parts of one edge inside, given whether its start is inside; returns whether its end is.
bool PolygonSetCovariance::edgeInside(const Edge& edge, const Vec& shift, const Vec& origin, const Vec& moving, bool in,
                                      double& sum) const {
    thread_local std::vector<double> crossings;
    const Vec P = edge.a - shift, Q = edge.b - shift, d = Q - P;
    crossings.clear();
    forEdgesNear(P, Q, [&](int w) {
        const Vec& a = edges_[w].a;
        const Vec& b = edges_[w].b;
        const Vec ab = b - a;
        // Sides of the moving P, Q to the line ab, and of the fixed a, b to the moving line PQ.
        const bool sP = positive(cross2(ab, P - a), cross2(ab, moving));
        const bool sQ = positive(cross2(ab, Q - a), cross2(ab, moving));
        if (sP == sQ) return;
        const bool sa = positive(cross2(d, a - P), -cross2(d, moving));
        const bool sb = positive(cross2(d, b - P), -cross2(d, moving));
        if (sa == sb) return;
        const double denominator = cross2(d, ab);
        crossings.push_back(denominator != 0 ? std::clamp(cross2(a - P, ab) / denominator, 0.0, 1.0) : 0.5);
    });
    std::sort(crossings.begin(), crossings.end());
    crossings.push_back(1.0);
    double from = 0;
    for (double t : crossings) {
        if (in) sum += 0.5 * cross2(edge.a + from * (edge.b - edge.a) - origin, edge.a + t * (edge.b - edge.a) - origin);
        in = !in;
        from = t;
    }
    return !in;  // the final 1.0 is no crossing
}

double PolygonSetCovariance::boundaryInside(const Vec& shift, const Vec& origin, const Vec& moving) const {
    double sum = 0;
    for (std::size_t r = 0; r + 1 < ringStarts_.size(); ++r) {
        const std::size_t first = ringStarts_[r], n = ringStarts_[r + 1] - first;
        // Start the walk at a vertex clear of W's boundary, where the crossing number is unambiguous.
        std::size_t start = 0;
        bool clear = false, in = false;
        for (; start < n && !clear; ++start) in = inside(edges_[first + start].a - shift, clear);
        if (!clear) return std::nan("");  // the whole ring on W's boundary: v is ~0
        --start;
        for (std::size_t done = 0, k = start; done < n;) {
            // A chain of edges that, shifted, comes near no edge of W crosses nothing: it is inside or
            // outside as a whole, and its integral is known in closed form.
            if (k % kChain == 0) {
                const Chain& chain = chains_[chainStarts_[r] + k / kChain];
                const Eigen::AlignedBox2d box(chain.box.min() - shift, chain.box.max() - shift);
                if (chain.edges <= n - done && !nearEdges(box)) {
                    if (in) sum += 0.5 * (chain.sumCross - cross2(origin, chain.sumVector));
                    done += chain.edges;
                    k = (k + chain.edges) % n;
                    continue;
                }
            }
            in = edgeInside(edges_[first + k], shift, origin, moving, in, sum);
            ++done;
            k = (k + 1) % n;
        }
    }
    return sum;
}

bool PolygonSetCovariance::nearEdges(const Eigen::AlignedBox2d& box) const {
    const double eps = 1e-9 * cell_;
    if (box.max().x() < -eps || box.max().y() < -eps || box.min().x() > nx_ * cell_ + eps || box.min().y() > ny_ * cell_ + eps)
        return false;
    const auto index = [&](double x, int n) { return std::clamp(static_cast<int>(std::floor(x / cell_)), 0, n - 1); };
    const int i0 = index(box.min().x() - eps, nx_), i1 = index(box.max().x() + eps, nx_);
    const int j0 = index(box.min().y() - eps, ny_), j1 = index(box.max().y() + eps, ny_);
    const auto at = [&](int i, int j) { return occupied_[static_cast<std::size_t>(j) * (nx_ + 1) + i]; };
    return at(i1 + 1, j1 + 1) - at(i0, j1 + 1) - at(i1 + 1, j0) + at(i0, j0) > 0;
}

double PolygonSetCovariance::operator()(const Vec& v) const {
    // B = W + v + ε e: the parts of ∂W inside B (their points move by −ε e relative to B) and the parts
    // of ∂B inside W, computed as the parts of ∂W whose points x + v + ε e are in W, about W's frame.
    const double own = boundaryInside(v, Vec::Zero(), -kGeneric);
    const double shifted = boundaryInside(-v, -v, kGeneric);
    if (std::isnan(own) || std::isnan(shifted)) return area_;  // |v| within 1e-9 of W's size
    return std::clamp(own + shifted, 0.0, area_);
}

}  // namespace sylva::stand

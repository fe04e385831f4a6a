#include "libstand/Window.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include <Eigen/Geometry>

#include "libcommon/InputError.hpp"

namespace sylva::stand {

double signedArea(const std::vector<Eigen::Vector2d>& v) {
    double twice = 0;
    for (std::size_t i = 0; i < v.size(); ++i) twice += cross2(v[i], v[(i + 1) % v.size()]);
    return 0.5 * twice;
}

namespace {

using Vec = Eigen::Vector2d;

double cross(const Vec& a, const Vec& b) { return cross2(a, b); }

double segmentDistance(const Vec& p, const Vec& a, const Vec& b) {
    const Vec ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (a + t * ab - p).norm();
}

// Orientation sign of (a, b, c) with a tolerance relative to the coordinates' size, so that
// collinear vertices read from a file with rounded decimals count as collinear.
int orientation(const Vec& a, const Vec& b, const Vec& c, double tol) {
    const double o = cross(b - a, c - a);
    return o > tol ? 1 : (o < -tol ? -1 : 0);
}

bool onSegment(const Vec& p, const Vec& a, const Vec& b) {
    return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= p.y() &&
           p.y() <= std::max(a.y(), b.y());
}

bool segmentsIntersect(const Vec& a, const Vec& b, const Vec& c, const Vec& d, double tol) {
    const int o1 = orientation(a, b, c, tol), o2 = orientation(a, b, d, tol);
    const int o3 = orientation(c, d, a, tol), o4 = orientation(c, d, b, tol);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    return (o1 == 0 && onSegment(c, a, b)) || (o2 == 0 && onSegment(d, a, b)) || (o3 == 0 && onSegment(a, c, d)) ||
           (o4 == 0 && onSegment(b, c, d));
}

}  // namespace

Window Window::rectangle(double xmin, double ymin, double xmax, double ymax) {
    if (!(xmax > xmin) || !(ymax > ymin))
        throw InputError("degenerate window: xmin,ymin,xmax,ymax = " + readableNumber(xmin) + "," + readableNumber(ymin) +
                         "," + readableNumber(xmax) + "," + readableNumber(ymax) + " (need xmax > xmin and ymax > ymin)");
    Window w;
    w.rectangle_ = true;
    w.lo_ = {xmin, ymin};
    w.hi_ = {xmax, ymax};
    w.rings_ = {{{xmin, ymin}, {xmax, ymin}, {xmax, ymax}, {xmin, ymax}}};
    w.area_ = (xmax - xmin) * (ymax - ymin);
    w.perimeter_ = 2 * ((xmax - xmin) + (ymax - ymin));
    return w;
}

void Window::requirePlotSize() const {
    if (area_ >= 1 && area_ <= 1e10) return;
    throw InputError("window of " + readableNumber(area_) + " m2 is outside [1, 1e10] m2 (coordinates in km, or in degrees?)");
}

namespace {

// Tolerance of the orientation tests for these vertices. The cross product of two edge vectors of
// length up to the rings' extent L carries the rounding of their differences, each off by up to
// eps |x| for coordinates of size |x|: of order L |x| eps. Scaled by |x|^2 instead, the tolerance in
// projected coordinates (|x| ~ 5e6 m) reached 25 m^2 and a 4 m square plot read as degenerate.
double orientationTolerance(const std::vector<Vec>& v) {
    double scale = 0;
    Eigen::AlignedBox2d box;
    for (const auto& p : v) {
        scale = std::max(scale, p.cwiseAbs().maxCoeff());
        box.extend(p);
    }
    const double extent = box.sizes().maxCoeff();
    return 1e-12 * std::max(1.0, extent * std::max(extent, scale));
}

// A ring as a simple polygon, counter-clockwise, without its closing vertex or repeated vertices.
// Throws InputError naming `ring` ("polygon window", "hole 2 of the polygon window").
std::vector<Vec> simpleRing(std::vector<Vec> v, const std::string& ring) {
    for (const auto& p : v)
        if (!std::isfinite(p.x()) || !std::isfinite(p.y())) throw InputError(ring + " has a non-finite vertex");
    if (v.size() >= 2 && v.front() == v.back()) v.pop_back();
    // Repeated consecutive vertices add nothing and would make zero-length edges.
    v.erase(std::unique(v.begin(), v.end()), v.end());
    if (v.size() >= 2 && v.front() == v.back()) v.pop_back();
    if (v.size() < 3)
        throw InputError("degenerate " + ring + ": " + std::to_string(v.size()) + " distinct vertices (at least 3 are needed)");
    const double tol = orientationTolerance(v);
    const std::size_t n = v.size();
    if (std::all_of(v.begin() + 2, v.end(), [&](const Vec& p) { return orientation(v[0], v[1], p, tol) == 0; }))
        throw InputError("degenerate " + ring + ": its area is zero (all vertices on one line)");
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
            if (adjacent) {
                // Adjacent edges share a vertex; they only cross if one folds back onto the other.
                const Vec& shared = j == i + 1 ? v[j] : v[i];
                const Vec& p = j == i + 1 ? v[i] : v[(i + 1) % n];
                const Vec& q = j == i + 1 ? v[(j + 1) % n] : v[n - 1];
                if (orientation(p, shared, q, tol) == 0 && (p - shared).dot(q - shared) > 0)
                    throw InputError(ring + " intersects itself (edges " + std::to_string(i + 1) + " and " +
                                     std::to_string(j + 1) + " overlap)");
                continue;
            }
            if (segmentsIntersect(v[i], v[(i + 1) % n], v[j], v[(j + 1) % n], tol))
                throw InputError(ring + " intersects itself (edges " + std::to_string(i + 1) + " and " +
                                 std::to_string(j + 1) + " cross)");
        }
    const double a = signedArea(v);
    if (std::abs(a) <= tol) throw InputError("degenerate " + ring + ": its area is zero");
    if (a < 0) std::reverse(v.begin(), v.end());
    return v;
}

// Even-odd test of a ring; `onBoundary` tells whether p lies on one of its edges.
bool insideRing(const std::vector<Vec>& ring, const Vec& p, bool& onBoundary) {
    bool inside = false;
    onBoundary = false;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        const Vec& a = ring[i];
        const Vec& b = ring[j];
        if (segmentDistance(p, a, b) == 0.0) {
            onBoundary = true;
            return true;
        }
        if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
            inside = !inside;
    }
    return inside;
}

bool ringsTouch(const std::vector<Vec>& r, const std::vector<Vec>& s, double tol) {
    for (std::size_t i = 0; i < r.size(); ++i)
        for (std::size_t j = 0; j < s.size(); ++j)
            if (segmentsIntersect(r[i], r[(i + 1) % r.size()], s[j], s[(j + 1) % s.size()], tol)) return true;
    return false;
}

}  // namespace

Window Window::polygon(std::vector<Eigen::Vector2d> outer, std::vector<std::vector<Eigen::Vector2d>> holes) {
    Window w;
    w.rectangle_ = false;
    w.rings_.push_back(simpleRing(std::move(outer), "polygon window"));
    for (std::size_t h = 0; h < holes.size(); ++h)
        w.rings_.push_back(simpleRing(std::move(holes[h]), "hole " + std::to_string(h + 1) + " of the polygon window"));
    std::vector<Vec> all;
    for (const auto& r : w.rings_) all.insert(all.end(), r.begin(), r.end());
    const double tol = orientationTolerance(all);
    // A hole lies strictly inside the outer ring and apart from the other holes (a hole touching the
    // boundary would split or pinch the window; spatstat refuses such polygons too).
    for (std::size_t h = 1; h < w.rings_.size(); ++h) {
        const std::string hole = "hole " + std::to_string(h) + " of the polygon window";
        bool edge = false;
        if (ringsTouch(w.rings_[h], w.rings_[0], tol) || !insideRing(w.rings_[0], w.rings_[h][0], edge) || edge)
            throw InputError(hole + " is not strictly inside its outer ring");
        for (std::size_t k = 1; k < h; ++k)
            if (ringsTouch(w.rings_[h], w.rings_[k], tol) || insideRing(w.rings_[k], w.rings_[h][0], edge) ||
                insideRing(w.rings_[h], w.rings_[k][0], edge))
                throw InputError(hole + " overlaps or touches hole " + std::to_string(k));
    }
    w.area_ = signedArea(w.rings_[0]);
    for (std::size_t h = 1; h < w.rings_.size(); ++h) w.area_ -= signedArea(w.rings_[h]);
    w.lo_ = w.hi_ = w.rings_[0].front();
    for (const auto& ring : w.rings_)
        for (std::size_t i = 0; i < ring.size(); ++i) {
            w.lo_ = w.lo_.cwiseMin(ring[i]);
            w.hi_ = w.hi_.cwiseMax(ring[i]);
            w.perimeter_ += (ring[(i + 1) % ring.size()] - ring[i]).norm();
        }
    return w;
}

Window Window::fromWkt(const std::string& wkt) {
    std::string s;
    for (char c : wkt) s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const auto bad = [&](const std::string& why) {
        return InputError("bad WKT polygon '" + wkt + "': " + why +
                          " (expected POLYGON((x y, x y, ...)) or, with holes, POLYGON((outer ring), (hole), ...))");
    };
    const auto start = s.find_first_not_of(" \t");
    if (start == std::string::npos || s.compare(start, 7, "POLYGON") != 0) throw bad("it does not start with POLYGON");
    const auto open = s.find('(', start + 7);
    if (open == std::string::npos || s.find_first_not_of(" \t", start + 7) != open) throw bad("no '(' after POLYGON");
    std::vector<std::vector<Vec>> rings;
    std::size_t at = open + 1;
    for (;;) {
        const auto ringOpen = s.find_first_not_of(" \t\r\n", at);
        if (ringOpen == std::string::npos || s[ringOpen] != '(') throw bad("each ring must be in its own parentheses");
        const auto close = s.find(')', ringOpen + 1);
        if (close == std::string::npos) throw bad("missing ')'");
        std::vector<Vec> v;
        std::stringstream ring(wkt.substr(ringOpen + 1, close - ringOpen - 1));
        std::string pair;
        while (std::getline(ring, pair, ',')) {
            const char* p = pair.c_str();
            char* end = nullptr;
            errno = 0;
            const double x = std::strtod(p, &end);
            if (end == p) throw bad("'" + pair + "' is not an 'x y' pair");
            const char* q = end;
            const double y = std::strtod(q, &end);
            if (end == q || errno == ERANGE) throw bad("'" + pair + "' is not an 'x y' pair");
            while (*end == ' ' || *end == '\t') ++end;
            if (*end != '\0') throw bad("'" + pair + "' is not an 'x y' pair");
            v.emplace_back(x, y);
        }
        rings.push_back(std::move(v));
        const auto after = s.find_first_not_of(" \t\r\n", close + 1);
        if (after == std::string::npos) throw bad("missing the final ')'");
        if (s[after] == ',') {
            at = after + 1;
            continue;
        }
        if (s[after] != ')' || s.find_first_not_of(" \t\r\n", after + 1) != std::string::npos)
            throw bad("trailing text after the rings");
        break;
    }
    try {
        std::vector<Vec> outer = std::move(rings.front());
        rings.erase(rings.begin());
        return polygon(std::move(outer), std::move(rings));
    } catch (const InputError& e) {
        throw bad(e.what());
    }
}

bool Window::contains(const Eigen::Vector2d& p) const {
    if (rectangle_) return lo_.x() <= p.x() && p.x() <= hi_.x() && lo_.y() <= p.y() && p.y() <= hi_.y();
    if ((p.array() < lo_.array()).any() || (p.array() > hi_.array()).any()) return false;
    bool edge = false;
    if (!insideRing(rings_[0], p, edge)) return false;
    // Closed window: a hole's boundary belongs to the window.
    for (std::size_t h = 1; h < rings_.size(); ++h)
        if (insideRing(rings_[h], p, edge) && !edge) return false;
    return true;
}

double Window::distanceToBoundary(const Eigen::Vector2d& p) const {
    if (rectangle_)
        return std::min({p.x() - lo_.x(), hi_.x() - p.x(), p.y() - lo_.y(), hi_.y() - p.y()});
    double d = INFINITY;
    for (const auto& ring : rings_)
        for (std::size_t i = 0; i < ring.size(); ++i) d = std::min(d, segmentDistance(p, ring[i], ring[(i + 1) % ring.size()]));
    return d;
}

std::string Window::describe() const {
    if (rectangle_)
        return "rectangle [" + readableNumber(lo_.x()) + "," + readableNumber(hi_.x()) + "]x[" + readableNumber(lo_.y()) + "," + readableNumber(hi_.y()) + "]";
    std::string text = "polygon of " + std::to_string(rings_[0].size()) + " vertices";
    if (rings_.size() == 2) text += " with 1 hole";
    if (rings_.size() > 2) text += " with " + std::to_string(rings_.size() - 1) + " holes";
    return text;
}

}  // namespace sylva::stand

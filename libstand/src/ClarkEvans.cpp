#include "libstand/ClarkEvans.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "libstand/NearestNeighbours.hpp"

namespace sylva::stand {
namespace {

// spatstat's clarkevans(correction="cdf"): the mean of the nearest-neighbour distance distribution
// G as estimated by Gest() (Kaplan-Meier, border-censored, on spatstat's default histogram of r),
// integrated as stieltjes(function(x) x, G) / stieltjes(1, G). Reproduced step by step so that the
// result agrees with spatstat to rounding, not just to the discretisation error.
std::optional<double> meanOfKaplanMeierG(const std::vector<double>& nnd, const std::vector<Eigen::Vector2d>& points,
                                         const Window& window) {
    const std::size_t n = points.size();
    const double lambda = static_cast<double>(n) / window.area();
    // rmax.rule("G"): half the frame's diagonal, or where a Poisson process has G = 1 - 1e-5.
    const Eigen::Vector2d frame = window.upper() - window.lower();
    const double rmax = std::min(std::sqrt(std::log(1e5) / (M_PI * lambda)), frame.norm() / 2);
    // handle.r.b.args -> make.even.breaks(rmax, bstep = rmax/512): breaks -step, 0, step, ..., npos*step.
    const double step = rmax / 128 / 4;
    const auto npos = static_cast<std::size_t>(std::ceil(rmax / step));
    const double right = step * static_cast<double>(npos);
    std::vector<double> breaks{-step};
    for (std::size_t k = 0; k <= npos; ++k)
        breaks.push_back(k == npos ? right : static_cast<double>(k) * (right / static_cast<double>(npos)));
    const std::size_t cells = breaks.size() - 1;
    // whist(): findInterval(x, breaks, rightmost.closed=TRUE) -> cell [b_k, b_k+1), the last one closed.
    const auto cellOf = [&](double x) -> std::ptrdiff_t {
        if (x < breaks.front()) return -1;
        if (x > breaks.back()) return static_cast<std::ptrdiff_t>(cells);
        if (x == breaks.back()) return static_cast<std::ptrdiff_t>(cells) - 1;
        return std::upper_bound(breaks.begin(), breaks.end(), x) - breaks.begin() - 1;
    };
    std::vector<double> observed(cells, 0.0), uncensored(cells, 0.0);
    double beyond = 0;  // observations above the last break
    for (std::size_t i = 0; i < n; ++i) {
        const double boundary = window.distanceToBoundary(points[i]);
        const double o = std::min(nnd[i], boundary);
        const auto c = cellOf(o);
        if (c == static_cast<std::ptrdiff_t>(cells)) {
            beyond += 1;
        } else if (c >= 0) {
            observed[c] += 1;
            if (nnd[i] <= boundary) uncensored[c] += 1;
        }
    }
    // kaplan.meier(): km[k] = 1 - prod_{j<=k} (1 - nco_j / #{o >= b_j}).
    std::vector<double> atRisk(cells);
    double cum = beyond;
    for (std::size_t k = cells; k-- > 0;) atRisk[k] = (cum += observed[k]);
    std::vector<double> km(cells);
    double survival = 1;
    for (std::size_t k = 0; k < cells; ++k) {
        survival *= atRisk[k] > 0 ? 1 - uncensored[k] / atRisk[k] : 1;
        km[k] = 1 - survival;
    }
    // km[k] estimates G at r_k = breaks[k+1]; stieltjes() weights each increment with its left r.
    double numer = 0;
    for (std::size_t k = 0; k + 1 < cells; ++k) numer += breaks[k + 1] * (km[k + 1] - km[k]);
    const double denom = km.back() - km.front();
    if (!(denom > 0)) return std::nullopt;
    return numer / denom;
}

}  // namespace

ClarkEvansIndex clarkEvans(const std::vector<Eigen::Vector2d>& points, const Window& window, double guardFraction) {
    ClarkEvansIndex out;
    const std::size_t n = points.size();
    out.guardDistance = guardFraction * std::sqrt(window.area());
    if (n < 2) return out;
    const std::vector<double> nnd = nearestNeighbourDistances(points);
    const double nd = static_cast<double>(n);
    out.meanNearestNeighbour = std::accumulate(nnd.begin(), nnd.end(), 0.0) / nd;
    const double expected = 1 / (2 * std::sqrt(nd / window.area()));  // Eq. 25
    out.naive = out.meanNearestNeighbour / expected;                    // Eq. 24
    if (window.isRectangle()) {
        // Donnelly (1978): E_d = 0.5 sqrt(A/n) + (0.0514 + 0.0412/sqrt(n)) P/n (model-notes.md)
        const double eDonnelly = expected + (0.0514 + 0.0412 / std::sqrt(nd)) * window.perimeter() / nd;
        out.donnelly = out.meanNearestNeighbour / eDonnelly;
    }
    double guardSum = 0;
    for (std::size_t i = 0; i < n; ++i)
        if (window.distanceToBoundary(points[i]) >= out.guardDistance) {
            guardSum += nnd[i];
            ++out.nInGuard;
        }
    if (out.nInGuard > 0) out.guard = guardSum / static_cast<double>(out.nInGuard) / expected;
    if (const auto dCdf = meanOfKaplanMeierG(nnd, points, window)) out.cdf = *dCdf / expected;
    return out;
}

}  // namespace sylva::stand

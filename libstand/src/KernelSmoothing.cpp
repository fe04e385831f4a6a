#include "libstand/KernelSmoothing.hpp"

#include <algorithm>
#include <cmath>

namespace sylva::stand {
namespace {

double epanechnikov(double u, double a) {
    const double t = u / a;
    return std::abs(u) < a ? 0.75 * (1 - t * t) / a : 0.0;
}

double gridPoint(double from, double to, std::size_t i, std::size_t n) {
    return i + 1 == n ? to : from + static_cast<double>(i) * ((to - from) / static_cast<double>(n - 1));
}

std::vector<double> exactSum(const std::vector<double>& d, const std::vector<double>& w, double a, double from,
                             double to, std::size_t nOut) {
    std::vector<double> f(nOut, 0.0);
    const double dx = (to - from) / static_cast<double>(nOut - 1);
    for (std::size_t k = 0; k < d.size(); ++k) {
        // Only the grid points within the kernel's support.
        const double first = std::max(0.0, std::ceil((d[k] - a - from) / dx));
        const double last = std::min(static_cast<double>(nOut - 1), std::floor((d[k] + a - from) / dx));
        if (last < first) continue;
        for (auto i = static_cast<std::size_t>(first); i <= static_cast<std::size_t>(last); ++i)
            f[i] += w[k] * epanechnikov(gridPoint(from, to, i, nOut) - d[k], a);
    }
    return f;
}

// R 4.2's density.default(x, weights, bw = sd, kernel = "epanechnikov", n = nOut, from, to) times
// sum(w), step by step (src/library/stats/R/density.R and BinDist in massdist.c).
std::vector<double> asRDensity(const std::vector<double>& d, const std::vector<double>& w, double sd, double a,
                               double from, double to, std::size_t nOut) {
    std::size_t n = std::max<std::size_t>(nOut, 512);
    if (n > 512) n = std::size_t{1} << static_cast<int>(std::ceil(std::log2(static_cast<double>(n))));
    const double lo = from - 4 * sd, up = to + 4 * sd;
    // BinDist: linear binning of the weights onto lo + j (up - lo)/(n - 1).
    std::vector<double> y(n, 0.0);
    const double xdelta = (up - lo) / static_cast<double>(n - 1);
    const long ixmax = static_cast<long>(n) - 2;
    for (std::size_t k = 0; k < d.size(); ++k) {
        const double xpos = (d[k] - lo) / xdelta;
        const double fl = std::floor(xpos);
        if (fl < -1 || fl > static_cast<double>(ixmax + 1)) continue;
        const long ix = static_cast<long>(fl);
        const double fx = xpos - fl;
        if (ix >= 0 && ix <= ixmax) {
            y[ix] += (1 - fx) * w[k];
            y[ix + 1] += fx * w[k];
        } else if (ix == -1) {
            y[0] += fx * w[k];
        } else {
            y[ix] += (1 - fx) * w[k];
        }
    }
    // The FFT convolution pairs bin j with grid point m at kernel abscissa |j - m| * 2 (up - lo)/(2n - 1)
    // (R's kords, a slightly different spacing from the bins'); evaluated here as the same finite sum.
    const double kstep = 2 * (up - lo) / static_cast<double>(2 * n - 1);
    const auto reach = static_cast<long>(std::ceil(a / kstep));
    std::vector<double> kernel(static_cast<std::size_t>(reach) + 1);
    for (long s = 0; s <= reach; ++s) kernel[s] = epanechnikov(static_cast<double>(s) * kstep, a);
    std::vector<double> smooth(n, 0.0);
    for (long m = 0; m < static_cast<long>(n); ++m) {
        double sum = 0;
        for (long j = std::max(0L, m - reach); j <= std::min(static_cast<long>(n) - 1, m + reach); ++j)
            sum += y[j] * kernel[std::abs(j - m)];
        smooth[m] = std::max(0.0, sum);
    }
    // approx(xords, smooth, x): linear interpolation to the output grid.
    std::vector<double> f(nOut);
    for (std::size_t i = 0; i < nOut; ++i) {
        const double x = gridPoint(from, to, i, nOut);
        const double pos = (x - lo) / xdelta;
        const auto j = std::min(static_cast<std::size_t>(std::max(0.0, std::floor(pos))), n - 2);
        const double t = pos - static_cast<double>(j);
        f[i] = smooth[j] + t * (smooth[j + 1] - smooth[j]);
    }
    return f;
}

}  // namespace

std::vector<double> epanechnikovSum(const std::vector<double>& d, const std::vector<double>& w, double sd,
                                    double from, double to, std::size_t nOut, KernelSum method) {
    const double a = sd * std::sqrt(5.0);
    return method == KernelSum::Exact ? exactSum(d, w, a, from, to, nOut) : asRDensity(d, w, sd, a, from, to, nOut);
}

}  // namespace sylva::stand

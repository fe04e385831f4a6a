#include "libassess/Correlation.hpp"

#include <gsl/gsl_cdf.h>

#include <cmath>
#include <stdexcept>

namespace sylva::assess {

double pearson(const std::vector<double>& x, const std::vector<double>& y) {
    if (x.size() != y.size()) throw std::invalid_argument("pearson: samples of different sizes");
    const std::size_t n = x.size();
    if (n < 2) return std::nan("");
    double mx = 0, my = 0;
    for (std::size_t i = 0; i < n; ++i) {
        mx += x[i];
        my += y[i];
    }
    mx /= n;
    my /= n;
    double sxy = 0, sxx = 0, syy = 0;
    for (std::size_t i = 0; i < n; ++i) {
        sxy += (x[i] - mx) * (y[i] - my);
        sxx += (x[i] - mx) * (x[i] - mx);
        syy += (y[i] - my) * (y[i] - my);
    }
    if (sxx <= 0 || syy <= 0) return std::nan("");
    return sxy / std::sqrt(sxx * syy);
}

double pearsonPValue(double r, std::size_t n) {
    if (!std::isfinite(r) || n < 3) return std::nan("");
    if (std::fabs(r) >= 1) return 0;
    const double dof = static_cast<double>(n) - 2;
    const double t = std::fabs(r) * std::sqrt(dof / (1 - r * r));
    return 2 * gsl_cdf_tdist_Q(t, dof);
}

std::vector<int> ascendingRanks(const std::vector<double>& values) {
    std::vector<int> ranks(values.size(), 1);
    for (std::size_t i = 0; i < values.size(); ++i)
        for (double other : values)
            if (other < values[i]) ++ranks[i];
    return ranks;
}

}  // namespace sylva::assess

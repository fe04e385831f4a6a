#pragma once
// Weighted Epanechnikov kernel sums f(x) = sum_k w_k K(x - d_k) on an evenly spaced grid, the
// smoothing step of the pair correlation function. K has standard deviation sd (half-width
// a = sqrt(5) sd): K(u) = 3/(4a) (1 - (u/a)²) for |u| < a.
#include <cstddef>
#include <vector>

namespace sylva::stand {

enum class KernelSum {
    // As R's density.default(), through which spatstat's pcf() goes: linear binning of the d_k on
    // max(512, nOut) points spanning [from - 4 sd, to + 4 sd], discrete convolution with the kernel
    // (R's grid of kernel abscissae included), then linear interpolation to the output grid.
    AsRDensity,
    // The sum evaluated at each output point directly.
    Exact,
};

// Values at x_i = from + i (to - from)/(nOut - 1), i = 0..nOut-1 (nOut >= 2, to > from).
std::vector<double> epanechnikovSum(const std::vector<double>& d, const std::vector<double>& w, double sd,
                                    double from, double to, std::size_t nOut, KernelSum method);

}  // namespace sylva::stand

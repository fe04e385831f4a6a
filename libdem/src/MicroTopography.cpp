#include "libdem/MicroTopography.hpp"

#include <cmath>
#include <vector>

#include "libcommon/InputError.hpp"
#include "libcommon/SeededRandom.hpp"

namespace sylva::dem {

ElevationGrid withMicroTopography(const ElevationGrid& dtm, const MicroTopographyParams& p) {
    if (!(p.sigma >= 0)) throw InputError("terrain.microtopography_m = " + readableNumber(p.sigma) + ": a standard deviation is >= 0");
    if (!(p.lengthM > 0)) throw InputError("terrain.microtopography_length_m = " + readableNumber(p.lengthM) + ": a correlation length is > 0");
    if (p.sigma == 0) return dtm;
    const int nc = dtm.columns(), nr = dtm.rows();
    const double rho = std::exp(-dtm.cellSize() / p.lengthM), innovation = std::sqrt(1 - rho * rho);
    SeededRandom rng(p.seed);
    // White noise, then AR(1) along x and along y: each pass keeps unit variance (its first value is
    // drawn from the stationary law, no spin-up) and gives the exponential correlation in its direction.
    std::vector<double> f(static_cast<std::size_t>(nc) * nr);
    for (auto& v : f) v = rng.gaussian(1.0);
    for (int r = 0; r < nr; ++r)
        for (int c = 1; c < nc; ++c) {
            const std::size_t i = static_cast<std::size_t>(r) * nc + c;
            f[i] = rho * f[i - 1] + innovation * f[i];
        }
    for (int c = 0; c < nc; ++c)
        for (int r = 1; r < nr; ++r) {
            const std::size_t i = static_cast<std::size_t>(r) * nc + c;
            f[i] = rho * f[i - static_cast<std::size_t>(nc)] + innovation * f[i];
        }
    std::vector<double> z = dtm.values();
    for (std::size_t i = 0; i < z.size(); ++i) z[i] += p.sigma * f[i];  // NaN (NODATA) stays NaN
    return ElevationGrid::fromValues(nc, nr, dtm.xmin(), dtm.ymin(), dtm.cellSize(), std::move(z),
                                     dtm.source() + " with a micro-topography of " + readableNumber(p.sigma) + " m");
}

}  // namespace sylva::dem

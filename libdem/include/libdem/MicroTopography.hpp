#pragma once
// Relief finer than a DTM's cells, added to it: a seeded Gaussian field at the DTM's own cells with a
// standard deviation and a correlation length. A coarse or smoothed DTM has lost the kinks that take
// normal velocity off a rolling block at each concave break (model-notes.md, "Micro-topography does
// it"): on a smooth surface the paper's contact law (Table 2) lets blocks run on. The stand-in slope
// carries the same field along its profile (data/slopes/make_standin.py: AR(1), 6 m, sigma 0.4 m).
#include <cstdint>

#include "libdem/ElevationGrid.hpp"

namespace sylva::dem {

struct MicroTopographyParams {
    double sigma = 0;          // m; 0: the DTM as it is (a fine survey DTM has its own relief)
    double lengthM = 6;        // correlation length, m (the stand-in's)
    std::uint64_t seed = 1;
};

// z + sigma * f(x, y), f of unit variance with correlation exp(-|dx| / L) exp(-|dy| / L) between cell
// centres (a separable AR(1): along each row, then along each column), drawn from `seed` alone. NODATA
// cells stay NODATA. The grid itself when sigma is 0. InputError for sigma < 0 or L <= 0.
ElevationGrid withMicroTopography(const ElevationGrid& dtm, const MicroTopographyParams& params);

}  // namespace sylva::dem

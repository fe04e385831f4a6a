#pragma once
// The hazard map for people (OUT/map.svg, and OUT/map.png for reports): the DTM's hillshade, the reach probability over it and
// the trees, drawn by gnuplot from data written beside it (OUT/map/), which a user can restyle.
#include <string>
#include <vector>

#include "libassess/Figures.hpp"
#include "libassess/GeoRaster.hpp"
#include "libstand/Forest.hpp"

namespace sylva::assess {

// Hillshade of the DTM at each cell centre, in [0, 1]: the cosine between the surface's normal and
// light from the north-west (azimuth 315 deg), 45 deg above the horizon (Lambertian hill shading,
// Horn 1981, Proc. IEEE 69: 14-47; azimuth and altitude as GIS tools default to them).
std::vector<float> hillshade(const Dtm& dtm);

// `reach`: the reach probability per cell (HazardMap::reachProbability). Without gnuplot the data
// and the script are still written and the warning says so.
FigureSet drawHazardMap(const std::string& outDir, const Dtm& dtm, const std::vector<float>& reach, const stand::Forest& forest);

}  // namespace sylva::assess

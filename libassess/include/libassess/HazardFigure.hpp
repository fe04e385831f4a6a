#pragma once
// The hazard map for people (OUT/map.svg, and OUT/map.png for reports): the DTM's hillshade, the reach probability over it and
// the trees, drawn by gnuplot from data written beside it (OUT/map/), which a user can restyle.
#include <string>
#include <vector>

#include "libassess/CheckLines.hpp"
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

// The rasters side by side for people (OUT/rasters.png, data and script in OUT/rasters/): each one
// over the DTM's extent, its values coloured (light yellow to dark red; blue to red around 0 for a
// signed raster such as the protection), cells without a value left white.
struct RasterPanel {
    std::string title;          // with its unit
    std::vector<float> values;  // on the DTM's grid, row 0 north
    float noData = -9999;
    bool signedScale = false;   // centred on 0
};
FigureSet drawRasterPanels(const std::string& outDir, const Dtm& dtm, const std::vector<RasterPanel>& panels);

// What a barrier on each check line would meet (OUT/check_lines.svg and .png, data and script in
// OUT/check_lines/): for each line and pass, the probability that a released block crosses the line
// with more than a given energy (left) or passing height (right), an exceedance curve per line and
// pass on a log scale, so that a line few blocks reach shows as a low curve rather than vanishing.
FigureSet drawCheckLines(const std::string& outDir, const std::vector<CheckLineTally::LineSample>& samples);

}  // namespace sylva::assess

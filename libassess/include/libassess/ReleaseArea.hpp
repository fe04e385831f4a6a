#pragma once
// Where blocks start on a DTM: the polygons of a vector layer (GeoJSON, GeoPackage, Shapefile, any
// format GDAL/OGR reads), turned into the DTM's cells whose centre lies inside one of them; or a
// raster (any grid in the DTM's CRS) whose cells other than 0 and NODATA release the DTM cells whose
// centre falls on them.
#include <string>
#include <vector>

#include "libassess/GeoRaster.hpp"

namespace sylva::assess {

struct ReleaseCell {
    int column = 0, row = 0;  // on the DTM's grid, row 0 the northernmost
};

// The release cells, in row-major order. InputError naming the file for: a file GDAL opens neither as
// vector data nor as a raster, no polygon in any layer, a CRS other than the DTM's, a release that
// covers no DTM cell centre (outside the DTM, smaller than a cell, a raster of zeros), and a release
// cell whose height is NODATA. `beyondDtm`, if given, is set when a polygon reaches past the DTM's
// edges (its part there releases nothing, which the caller may mention).
std::vector<ReleaseCell> readReleaseCells(const std::string& path, const Dtm& dtm, bool* beyondDtm = nullptr);

}  // namespace sylva::assess

#pragma once
// Where blocks start on a DTM: the polygons of a vector layer (GeoJSON, GeoPackage, Shapefile, any
// format GDAL/OGR reads), turned into the DTM's cells whose centre lies inside one of them.
#include <string>
#include <vector>

#include "libassess/GeoRaster.hpp"

namespace sylva::assess {

struct ReleaseCell {
    int column = 0, row = 0;  // on the DTM's grid, row 0 the northernmost
};

// The release cells, in row-major order. InputError naming the file for: a file OGR cannot open,
// no polygon in any layer, a CRS other than the DTM's, polygons that cover no DTM cell centre
// (outside the DTM, or smaller than a cell), and a release cell whose height is NODATA.
std::vector<ReleaseCell> readReleaseCells(const std::string& path, const Dtm& dtm);

}  // namespace sylva::assess

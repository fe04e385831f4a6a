#pragma once
// What libassess's GDAL readers share: a CRS as WKT, opening a vector file with OGR, and refusing a
// layer (release polygons, tree points) whose CRS is not the DTM's.
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <string>

#include "libassess/GeoRaster.hpp"

namespace sylva::assess {

// The CRS as WKT ("" for none).
std::string wktOf(const OGRSpatialReference* crs);

// Why GDAL could not open a file as `what` ("a raster", "vector data"), for an InputError.
std::string unreadable(const std::string& what);

// InputError naming the file if OGR cannot open it as vector data.
GDALDatasetUniquePtr openVectorFile(const std::string& path);

// InputError naming the file and the layer when the layer's CRS is not the DTM's. A GeoJSON without a
// "crs" member is WGS 84 by its standard (RFC 7946) and GDAL says so; when its coordinates cannot be
// degrees, it was written in a projected CRS without saying which, and is taken to be in the DTM's.
void requireDtmCrs(OGRLayer& layer, const std::string& path, const Dtm& dtm);

}  // namespace sylva::assess

#pragma once
// What libassess's GDAL readers share: a CRS as WKT, opening a vector file with OGR, and refusing a
// layer (release polygons, tree points) whose CRS is not the DTM's.
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "libassess/GeoRaster.hpp"

namespace sylva::assess {

// The CRS as WKT ("" for none).
std::string wktOf(const OGRSpatialReference* crs);

// Why GDAL could not open a file as `what` ("a raster", "vector data"), for an InputError.
std::string unreadable(const std::string& what);

// The files GDAL reads for the dataset at `path`, that file first: a Shapefile's .shx, .dbf and .prj,
// a raster's .aux.xml (which may scale its values) or .prj, a VRT's sources. Just `path` if GDAL
// cannot open it.
std::vector<std::string> datasetFiles(const std::string& path);

// InputError naming the file if OGR cannot open it as vector data.
GDALDatasetUniquePtr openVectorFile(const std::string& path);

// For inputs that may be polygons or a raster (release areas, soil maps): the file as vector data if
// GDAL opens it so (with a layer), else null when it is a raster; InputError naming the file if it is neither.
GDALDatasetUniquePtr openVectorUnlessRaster(const std::string& path);

// InputError naming the file and the layer when the layer's CRS is not the DTM's. A GeoJSON without a
// "crs" member is WGS 84 by its standard (RFC 7946) and GDAL says so; when its coordinates cannot be
// degrees, it was written in a projected CRS without saying which, and is taken to be in the DTM's.
void requireDtmCrs(OGRLayer& layer, const std::string& path, const Dtm& dtm);

// Whether the raster or vector file at `path` names no CRS (a Shapefile without its .prj, an ESRI ASCII
// grid without its .prj): its coordinates are then taken in the DTM's CRS, unchecked. False for a file
// GDAL cannot open (its reader says why) and for a layer-less one.
bool namesNoCrs(const std::string& path);

// What a vector file holds, for an error saying the file holds none of what was asked: "it holds 3
// Point and 1 Geometry Collection features" (a collection's parts: ogr2ogr -explodecollections), or
// "it holds no feature with a geometry". Reads every layer from its start.
std::string geometriesHeld(GDALDataset& ds);

// InputError naming the file and `where` (its layer and feature) for a polygon that GEOS finds
// invalid, such as a ring crossing itself: which cells lie inside it is then undefined (GEOS's
// Contains fails on it and says no for every cell).
void requireValidPolygon(const OGRGeometry& polygon, const std::string& path, const std::string& where);

// Calls visit(column, row) for each cell of the grid whose centre lies inside the polygon.
template <class Visit>
void forEachCellCentreInside(const OGRGeometry& polygon, const RasterGrid& grid, Visit visit) {
    OGREnvelope e;
    polygon.getEnvelope(&e);
    const double cell = grid.cellSize(), x0 = grid.geoTransform[0], y0 = grid.geoTransform[3];
    const int c0 = std::max(0, static_cast<int>(std::floor((e.MinX - x0) / cell))),
              c1 = std::min(grid.columns - 1, static_cast<int>(std::floor((e.MaxX - x0) / cell)));
    const int r0 = std::max(0, static_cast<int>(std::floor((y0 - e.MaxY) / cell))),
              r1 = std::min(grid.rows - 1, static_cast<int>(std::floor((y0 - e.MinY) / cell)));
    for (int r = r0; r <= r1; ++r)
        for (int c = c0; c <= c1; ++c) {
            const Eigen::Vector2d p = grid.centre(c, r);
            OGRPoint point(p.x(), p.y());
            if (polygon.Contains(&point)) visit(c, r);
        }
}

}  // namespace sylva::assess

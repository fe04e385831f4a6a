#pragma once
// Rasters on the ground through GDAL: a DTM read from any raster format GDAL opens (GeoTIFF, ESRI
// ASCII, ...), keeping its grid and CRS, and GeoTIFF rasters written on that same grid (the hazard
// maps), so that a GIS lays them exactly over the DTM.
#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

#include "libdem/ElevationGrid.hpp"

namespace sylva::assess {

// Where a raster lies: GDAL's geotransform (north-up, square cells: x = gt[0] + col gt[1],
// y = gt[3] + row gt[5] at a cell's north-west corner, gt[5] = -gt[1]) and its CRS.
struct RasterGrid {
    int columns = 0, rows = 0;
    std::array<double, 6> geoTransform{};
    std::string crsWkt;  // empty: the file names no CRS
    double cellSize() const { return geoTransform[1]; }
    // Centre of cell (col, row), row 0 the northernmost.
    Eigen::Vector2d centre(int col, int row) const;
    // The cell holding (x, y); false outside the raster.
    bool cellOf(double x, double y, int& col, int& row) const;
    std::size_t index(int col, int row) const { return static_cast<std::size_t>(row) * columns + col; }
};

struct Dtm {
    RasterGrid grid;
    dem::ElevationGrid elevation;  // the same heights for the simulator (NODATA as NaN)
    std::string path;
};

// Band 1 of any raster, north up with square cells.
struct GeoRaster {
    RasterGrid grid;
    std::vector<double> values;  // row-major, row 0 the northernmost; NaN where the band has no value (NODATA, mask)
};
// InputError naming the file: cannot be opened, no georeferencing, rotated or non-square cells,
// more than one band of values (an alpha band is a mask); `values` names what the band holds
// ("a DTM's heights") for that message.
GeoRaster readRaster(const std::string& path, const std::string& values);

// Band 1 of the raster as a terrain. InputError naming the file: readRaster's, fewer than 2 x 2 cells,
// a CRS in degrees or not in metres, cells outside 0.01-1000 m.
Dtm readDtm(const std::string& path);

// A single-band Float32 GeoTIFF on `grid` (values row-major, row 0 the northernmost), `noData`
// marking the cells without a value. InputError if it cannot be written.
void writeGeoTiff(const std::string& path, const RasterGrid& grid, const std::vector<float>& values, double noData,
                  const std::string& description);

// Whether two CRS (WKT) place points alike: their horizontal parts are the same (a compound CRS's
// vertical part says what its heights are in, not where its points are); true when either is empty.
bool sameCrs(const std::string& a, const std::string& b);
// A CRS's name for messages ("WGS 84", "RGF93 v1 / Lambert-93"), or "no CRS".
std::string crsName(const std::string& wkt);

// Registers GDAL's drivers once and silences its own error printing: sylvarock reports GDAL's
// errors itself, with the file concerned.
void initGdal();
// GDAL's last error message ("" if none).
std::string gdalLastError();

}  // namespace sylva::assess

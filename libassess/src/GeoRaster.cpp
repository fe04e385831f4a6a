#include "libassess/GeoRaster.hpp"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <mutex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "GdalSupport.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::assess {

namespace {
// 2.5e8 cells: 2 GB as doubles (a 15 km x 15 km DTM at 1 m).
constexpr double kMostRasterCells = 2.5e8;
}  // namespace

void initGdal() {
    static std::once_flag once;
    std::call_once(once, [] {
        GDALAllRegister();
        CPLSetErrorHandler(CPLQuietErrorHandler);
    });
}

namespace {

// GDAL's ESRI ASCII reader (AAIGrid) takes the grid's values as one stream of words and reads what it
// can of each without a word: a typo ('x', '5..2') in a DTM read as 0 or 5, a pit or a step in the
// slope; a 'nan' in a grid of whole numbers (which GDAL reads as integers) read as 0; one value too
// many on a line shifted every cell after it by one. The text is checked before GDAL's values are
// used: after the header's keywords, every word a number (a whole one in an integer grid), as many
// as the grid's cells, and when the grid is laid out one row per line (as every writer does),
// `columns` on each line.
void requireWellFormedAsciiGrid(const std::string& path, int columns, int rows, bool integers) {
    VSILFILE* f = VSIFOpenL(path.c_str(), "rb");
    if (!f) throw InputError(path, 0, "cannot open file");
    struct Closer {
        VSILFILE* f;
        ~Closer() { VSIFCloseL(f); }
    } closer{f};
    const auto number = [integers](const std::string& word) {
        if (integers) {
            char* end = nullptr;
            std::strtol(word.c_str(), &end, 10);
            return end != word.c_str() && *end == '\0';
        }
        // GDAL reads a decimal point or a decimal comma; anything else left over is not its number.
        for (const char point : {'.', ','}) {
            char* end = nullptr;
            CPLStrtodDelim(word.c_str(), &end, point);
            if (end != word.c_str() && *end == '\0') return true;
        }
        return false;
    };
    const auto headerKey = [](std::string word) {
        std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        for (const char* key : {"ncols", "nrows", "xllcorner", "yllcorner", "xllcenter", "yllcenter", "cellsize", "dx", "dy", "nodata_value"})
            if (word == key) return true;
        return false;
    };
    long lineNo = 0, values = 0;
    bool inHeader = true;
    std::vector<std::pair<long, long>> lineCounts;  // line, values on it
    while (const char* text = CPLReadLineL(f)) {
        ++lineNo;
        std::istringstream words(lineNo == 1 && std::string(text).rfind("\xEF\xBB\xBF", 0) == 0 ? text + 3 : text);
        std::string word;
        long onLine = 0;
        for (int i = 0; words >> word; ++i) {
            if (inHeader && i == 0 && headerKey(word)) break;  // "ncols 126"
            inHeader = false;
            if (!number(word))
                throw InputError(path, lineNo, "value " + std::to_string(onLine + 1) + " of the line, '" + word + "', is not " +
                                                   (integers ? "a whole number (this grid's values are whole numbers, read as integers)" : "a number"));
            ++onLine;
        }
        if (onLine > 0) lineCounts.emplace_back(lineNo, onLine), values += onLine;
    }
    const long cells = static_cast<long>(columns) * rows;
    // A stream wrapped at a fixed width (each line but the last as long) may by chance have nrows lines.
    bool wrapped = lineCounts.size() > 1 && lineCounts.front().second != columns;
    for (std::size_t r = 1; wrapped && r + 1 < lineCounts.size(); ++r) wrapped = lineCounts[r].second == lineCounts.front().second;
    if (static_cast<long>(lineCounts.size()) == rows && !wrapped)
        for (std::size_t r = 0; r < lineCounts.size(); ++r)
            if (lineCounts[r].second != columns)
                throw InputError(path, lineCounts[r].first,
                                 "row " + std::to_string(r + 1) + " has " + std::to_string(lineCounts[r].second) +
                                     " values, ncols = " + std::to_string(columns) + " (the rows after it would be shifted)");
    if (values != cells)
        throw InputError(path, lineNo, std::to_string(values) + " values for a grid of ncols x nrows = " + std::to_string(columns) +
                                           " x " + std::to_string(rows) + " = " + std::to_string(cells) + " cells");
}

}  // namespace

std::string gdalLastError() {
    const char* m = CPLGetLastErrorMsg();
    return m ? m : "";
}

Eigen::Vector2d RasterGrid::centre(int col, int row) const {
    const auto& g = geoTransform;
    return {g[0] + (col + 0.5) * g[1], g[3] + (row + 0.5) * g[5]};
}

bool RasterGrid::cellOf(double x, double y, int& col, int& row) const {
    const auto& g = geoTransform;
    const double c = (x - g[0]) / g[1], r = (y - g[3]) / g[5];
    if (!(c >= 0 && r >= 0 && c < columns && r < rows)) return false;
    col = static_cast<int>(c);
    row = static_cast<int>(r);
    return true;
}

GeoRaster readRaster(const std::string& path, const std::string& values) {
    initGdal();
    CPLErrorReset();
    GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
    if (!ds) throw InputError(path, 0, unreadable("a raster"));
    if (ds->GetRasterCount() < 1) throw InputError(path, 0, "the raster has no band");
    GeoRaster raster;
    RasterGrid& g = raster.grid;
    g.columns = ds->GetRasterXSize();
    g.rows = ds->GetRasterYSize();
    // Read whole, as doubles: refused before anything is allocated beyond what this machine holds.
    if (static_cast<double>(g.columns) * g.rows > kMostRasterCells)
        throw InputError(path, 0, "a raster of " + std::to_string(g.columns) + " x " + std::to_string(g.rows) + " cells, more than the " +
                                      readableNumber(kMostRasterCells) + " sylvarock reads at once: crop or resample it (gdalwarp -te, -tr)");
    if (ds->GetGeoTransform(g.geoTransform.data()) != CE_None)
        throw InputError(path, 0, "the raster has no georeferencing (geotransform): sylvarock needs cell size and position");
    const auto& t = g.geoTransform;
    if (t[2] != 0 || t[4] != 0) throw InputError(path, 0, "a rotated or sheared raster: warp it north-up first (gdalwarp)");
    if (t[1] > 0 && std::fabs(t[5] - t[1]) <= 1e-9 * t[1])
        throw InputError(path, 0, "a south-up raster (its first row the southern one): warp it north-up first (gdalwarp -tr " +
                                      readableNumber(t[1]) + " " + readableNumber(t[1]) + ")");
    if (!(t[1] > 0) || std::fabs(t[5] + t[1]) > 1e-9 * t[1])
        throw InputError(path, 0, "cells of " + readableNumber(t[1]) + " x " + readableNumber(-t[5]) +
                                      " m: sylvarock needs square cells, north up (gdalwarp -tr D D)");
    g.crsWkt = wktOf(ds->GetSpatialRef());
    // Band 1 of an image (a coloured hillshade, an orthophoto) was read as values without a word.
    int valueBands = 0;
    for (int b = 1; b <= ds->GetRasterCount(); ++b) valueBands += ds->GetRasterBand(b)->GetColorInterpretation() != GCI_AlphaBand;
    if (valueBands > 1)
        throw InputError(path, 0, "the raster has " + std::to_string(valueBands) + " bands of values (an image? a coloured hillshade?): " +
                                      values + " are one band; give that band alone (gdal_translate -b N)");
    if (std::string(ds->GetDriver()->GetDescription()) == "AAIGrid")
        requireWellFormedAsciiGrid(path, g.columns, g.rows, GDALDataTypeIsInteger(ds->GetRasterBand(1)->GetRasterDataType()));
    GDALRasterBand* band = ds->GetRasterBand(1);
    std::vector<double>& z = raster.values;
    z.resize(static_cast<std::size_t>(g.columns) * g.rows);
    if (band->RasterIO(GF_Read, 0, 0, g.columns, g.rows, z.data(), g.columns, g.rows, GDT_Float64, 0, 0) != CE_None)
        throw InputError(path, 0, "cannot read its values (" + gdalLastError() + ")");
    // The mask band says which cells hold a value: it knows the NODATA value in the band's own type
    // (a Float32 -9999.9 is not the double -9999.9) and any mask or alpha band.
    std::vector<GByte> valid(z.size(), 255);
    if (!(band->GetMaskFlags() & GMF_ALL_VALID) &&
        band->GetMaskBand()->RasterIO(GF_Read, 0, 0, g.columns, g.rows, valid.data(), g.columns, g.rows, GDT_Byte, 0, 0) != CE_None)
        throw InputError(path, 0, "cannot read which cells hold a value (" + gdalLastError() + ")");
    // A band stored scaled (heights as integer centimetres, say) gives its values as scale x stored +
    // offset; read raw, a DTM of 0.01 m units was taken for heights a hundred times too large.
    int hasScale = 0, hasOffset = 0;
    const double scale = band->GetScale(&hasScale), offset = band->GetOffset(&hasOffset);
    const bool scaled = (hasScale && scale != 1) || (hasOffset && offset != 0);
    for (std::size_t i = 0; i < z.size(); ++i)
        if (valid[i] == 0 || !std::isfinite(z[i]))
            z[i] = std::nan("");
        else if (scaled)
            z[i] = (hasScale ? scale : 1.0) * z[i] + (hasOffset ? offset : 0.0);
    return raster;
}

Dtm readDtm(const std::string& path) {
    GeoRaster raster = readRaster(path, "a DTM's heights");
    Dtm d;
    d.path = path;
    d.grid = raster.grid;
    const RasterGrid& g = d.grid;
    const auto& t = g.geoTransform;
    if (g.columns < 2 || g.rows < 2)
        throw InputError(path, 0, "a DTM of " + std::to_string(g.columns) + " x " + std::to_string(g.rows) + " cells: at least 2 x 2 are needed");
    // The simulator works in metres: a DTM in degrees or feet would be run with cells of 1e-4 "m".
    OGRSpatialReference crs;
    if (!g.crsWkt.empty() && crs.importFromWkt(g.crsWkt.c_str()) == OGRERR_NONE) {
        if (crs.IsGeographic())
            throw InputError(path, 0, "the DTM is in " + crsName(g.crsWkt) + ", in degrees: project it to a metric CRS first (gdalwarp -t_srs)");
        const char* unit = nullptr;
        if (std::fabs(crs.GetLinearUnits(&unit) - 1) > 1e-9)
            throw InputError(path, 0, "the DTM's CRS counts in " + std::string(unit ? unit : "an unknown unit") +
                                          ", not metres: reproject it (gdalwarp -t_srs) to a metric CRS");
        // A compound CRS (a LiDAR DTM's, say) gives the heights' unit apart: heights in feet were read
        // as metres, the relief 3.28 times too steep.
        const char* heightUnit = nullptr;
        if ((crs.IsCompound() || crs.IsVertical()) && std::fabs(crs.GetTargetLinearUnits("VERT_CS", &heightUnit) - 1) > 1e-9)
            throw InputError(path, 0, "the DTM's heights are in " + std::string(heightUnit ? heightUnit : "an unknown unit") + " (" +
                                          crsName(g.crsWkt) + "), not metres: convert them (gdalwarp -t_srs with a vertical CRS in metres)");
    }
    if (!(t[1] >= 0.01 && t[1] <= 1000))
        throw InputError(path, 0, "cells of " + readableNumber(t[1]) + " m: sylvarock reads DTMs with cells of 0.01 to 1000 m");
    // GDAL's rows run north to south, the simulator's south to north.
    std::vector<double> south(raster.values.size());
    for (int r = 0; r < g.rows; ++r)
        for (int c = 0; c < g.columns; ++c) south[static_cast<std::size_t>(g.rows - 1 - r) * g.columns + c] = raster.values[g.index(c, r)];
    const Eigen::Vector2d sw = g.centre(0, g.rows - 1);
    d.elevation = dem::ElevationGrid::fromValues(g.columns, g.rows, sw.x(), sw.y(), t[1], std::move(south), path);
    d.elevation.refuseUndeclaredNoData();
    return d;
}

void writeGeoTiff(const std::string& path, const RasterGrid& grid, const std::vector<float>& values, double noData,
                  const std::string& description) {
    initGdal();
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
    if (!driver) throw InputError(path, 0, "GDAL has no GeoTIFF driver");
    char** options = nullptr;
    options = CSLSetNameValue(options, "COMPRESS", "DEFLATE");
    CPLErrorReset();
    GDALDatasetUniquePtr ds(driver->Create(path.c_str(), grid.columns, grid.rows, 1, GDT_Float32, options));
    CSLDestroy(options);
    if (!ds) throw InputError(path, 0, "cannot write (" + gdalLastError() + ")");
    auto gt = grid.geoTransform;
    ds->SetGeoTransform(gt.data());
    if (!grid.crsWkt.empty()) ds->SetProjection(grid.crsWkt.c_str());
    GDALRasterBand* band = ds->GetRasterBand(1);
    band->SetNoDataValue(noData);
    band->SetDescription(description.c_str());
    std::vector<float> data = values;
    if (band->RasterIO(GF_Write, 0, 0, grid.columns, grid.rows, data.data(), grid.columns, grid.rows, GDT_Float32, 0, 0) != CE_None)
        throw InputError(path, 0, "cannot write (" + gdalLastError() + ")");
    ds.reset();  // closes and flushes the file (GDAL 3.6 has no Close() returning an error)
    if (CPLGetLastErrorType() >= CE_Failure) throw InputError(path, 0, "cannot write (" + gdalLastError() + ")");
}

bool sameCrs(const std::string& a, const std::string& b) {
    if (a.empty() || b.empty()) return true;
    OGRSpatialReference ra, rb;
    if (ra.importFromWkt(a.c_str()) != OGRERR_NONE || rb.importFromWkt(b.c_str()) != OGRERR_NONE) return a == b;
    // A LiDAR DTM in Lambert-93 + NGF-IGN69 height and a release drawn in Lambert-93 are in one frame.
    ra.StripVertical();
    rb.StripVertical();
    const char* options[] = {"IGNORE_DATA_AXIS_TO_SRS_AXIS_MAPPING=YES", "CRITERION=EQUIVALENT_EXCEPT_AXIS_ORDER_GEOGCRS", nullptr};
    return ra.IsSame(&rb, options);
}

std::string crsName(const std::string& wkt) {
    if (wkt.empty()) return "no CRS";
    OGRSpatialReference r;
    if (r.importFromWkt(wkt.c_str()) != OGRERR_NONE) return "an unreadable CRS";
    const char* name = r.GetName();
    return name ? name : "an unnamed CRS";
}

}  // namespace sylva::assess

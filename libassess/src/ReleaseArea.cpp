#include "libassess/ReleaseArea.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "GdalSupport.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::assess {

namespace {

// The DTM cells whose centre lies inside one of the polygons of the vector file; `beyond` is set if a
// polygon reaches past the DTM's outer edges (a polygon's bounding box is spanned by its vertices, so
// the box past an edge means a vertex past it).
std::vector<char> cellsInPolygons(GDALDataset& ds, const std::string& path, const Dtm& dtm, bool& beyond) {
    const RasterGrid& grid = dtm.grid;
    std::vector<std::unique_ptr<OGRGeometry>> polygons;
    for (OGRLayer* layer : ds.GetLayers()) {
        const std::size_t before = polygons.size();
        long featureNumber = 0;
        for (auto& feature : *layer) {
            ++featureNumber;
            const OGRGeometry* g = feature->GetGeometryRef();
            if (!g) continue;
            const auto type = wkbFlatten(g->getGeometryType());
            if (type != wkbPolygon && type != wkbMultiPolygon) continue;
            requireValidPolygon(*g, path, "layer '" + std::string(layer->GetName()) + "', feature " + std::to_string(featureNumber));
            polygons.emplace_back(g->clone());
        }
        // After the reading, and only for a layer with polygons: an empty GeoJSON layer reads as WGS 84,
        // and its CRS is not what is wrong with it (the check reads the extent, which restarts the reading).
        if (polygons.size() > before) requireDtmCrs(*layer, path, dtm);
    }
    if (polygons.empty()) throw InputError(path, 0, "no polygon in the file (" + geometriesHeld(ds) + "): a release area is a polygon layer");
    const double west = grid.geoTransform[0], north = grid.geoTransform[3];
    const double east = west + grid.columns * grid.cellSize(), south = north + grid.rows * grid.geoTransform[5];
    for (const auto& polygon : polygons) {
        OGREnvelope box;
        polygon->getEnvelope(&box);
        beyond = beyond || box.MinX < west || box.MaxX > east || box.MinY < south || box.MaxY > north;
    }
    std::vector<char> inside(static_cast<std::size_t>(grid.columns) * grid.rows, 0);
    for (const auto& polygon : polygons) forEachCellCentreInside(*polygon, grid, [&](int c, int r) { inside[grid.index(c, r)] = 1; });
    return inside;
}

// The DTM cells whose centre falls on a release raster's cell holding a value other than 0 (and not
// NODATA): a Rockyfor3D-style release raster, on the DTM's grid or any other in its CRS.
std::vector<char> cellsOnRaster(const std::string& path, const Dtm& dtm) {
    const GeoRaster release = readRaster(path, "a release raster's marks");
    if (!sameCrs(release.grid.crsWkt, dtm.grid.crsWkt))
        throw InputError(path, 0, "the release raster is in " + crsName(release.grid.crsWkt) + ", the DTM (" + dtm.path + ") in " +
                                      crsName(dtm.grid.crsWkt) + ": reproject it (gdalwarp -t_srs) to the DTM's CRS");
    const RasterGrid& grid = dtm.grid;
    std::vector<char> inside(static_cast<std::size_t>(grid.columns) * grid.rows, 0);
    for (int r = 0; r < grid.rows; ++r)
        for (int c = 0; c < grid.columns; ++c) {
            const Eigen::Vector2d p = grid.centre(c, r);
            int rc = 0, rr = 0;
            if (!release.grid.cellOf(p.x(), p.y(), rc, rr)) continue;
            const double v = release.values[release.grid.index(rc, rr)];
            inside[grid.index(c, r)] = std::isfinite(v) && v != 0;
        }
    return inside;
}

}  // namespace

std::vector<ReleaseCell> readReleaseCells(const std::string& path, const Dtm& dtm, bool* beyondDtm) {
    GDALDatasetUniquePtr vector = openVectorUnlessRaster(path);
    bool beyond = false;
    const std::vector<char> inside = vector ? cellsInPolygons(*vector, path, dtm, beyond) : cellsOnRaster(path, dtm);
    if (beyondDtm) *beyondDtm = beyond;
    const RasterGrid& grid = dtm.grid;
    std::vector<ReleaseCell> cells;
    for (int r = 0; r < grid.rows; ++r)
        for (int c = 0; c < grid.columns; ++c)
            if (inside[grid.index(c, r)]) cells.push_back({c, r});
    if (cells.empty())
        throw InputError(path, 0, "it covers no cell centre of the DTM (" + dtm.path + "): is it outside it, smaller than a cell of " +
                                      readableNumber(grid.cellSize()) + " m, or a raster of zeros?");
    for (const auto& cell : cells) {
        const Eigen::Vector2d p = grid.centre(cell.column, cell.row);
        try {
            dtm.elevation.height(p.x(), p.y());
        } catch (const InputError& e) {
            throw InputError(path, 0, "a release cell lies on a NODATA hole of the DTM: " + std::string(e.what()));
        }
    }
    return cells;
}

}  // namespace sylva::assess

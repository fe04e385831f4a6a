#include "libassess/ReleaseArea.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "GdalSupport.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::assess {

std::vector<ReleaseCell> readReleaseCells(const std::string& path, const Dtm& dtm) {
    GDALDatasetUniquePtr ds = openVectorFile(path);
    const RasterGrid& grid = dtm.grid;
    std::vector<std::unique_ptr<OGRGeometry>> polygons;
    for (OGRLayer* layer : ds->GetLayers()) {
        requireDtmCrs(*layer, path, dtm);
        for (auto& feature : *layer) {
            const OGRGeometry* g = feature->GetGeometryRef();
            if (!g) continue;
            const auto type = wkbFlatten(g->getGeometryType());
            if (type == wkbPolygon || type == wkbMultiPolygon) polygons.emplace_back(g->clone());
        }
    }
    if (polygons.empty()) throw InputError(path, 0, "no polygon in the file: a release area is a polygon layer");
    std::vector<char> inside(static_cast<std::size_t>(grid.columns) * grid.rows, 0);
    for (const auto& polygon : polygons) {
        OGREnvelope e;
        polygon->getEnvelope(&e);
        const double cell = grid.cellSize(), x0 = grid.geoTransform[0], y0 = grid.geoTransform[3];
        const int c0 = std::max(0, static_cast<int>(std::floor((e.MinX - x0) / cell))),
                  c1 = std::min(grid.columns - 1, static_cast<int>(std::floor((e.MaxX - x0) / cell)));
        const int r0 = std::max(0, static_cast<int>(std::floor((y0 - e.MaxY) / cell))),
                  r1 = std::min(grid.rows - 1, static_cast<int>(std::floor((y0 - e.MinY) / cell)));
        for (int r = r0; r <= r1; ++r)
            for (int c = c0; c <= c1; ++c) {
                const Eigen::Vector2d p = grid.centre(c, r);
                OGRPoint point(p.x(), p.y());
                if (!inside[grid.index(c, r)] && polygon->Contains(&point)) inside[grid.index(c, r)] = 1;
            }
    }
    std::vector<ReleaseCell> cells;
    for (int r = 0; r < grid.rows; ++r)
        for (int c = 0; c < grid.columns; ++c)
            if (inside[grid.index(c, r)]) cells.push_back({c, r});
    if (cells.empty())
        throw InputError(path, 0, "its polygons cover no cell centre of the DTM (" + dtm.path +
                                      "): are they outside it, or smaller than a cell of " + readableNumber(grid.cellSize()) + " m?");
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

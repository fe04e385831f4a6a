#include "GdalSupport.hpp"

#include <cpl_conv.h>

#include <map>

#include "libcommon/InputError.hpp"

namespace sylva::assess {

std::string wktOf(const OGRSpatialReference* crs) {
    if (!crs) return "";
    char* wkt = nullptr;
    crs->exportToWkt(&wkt);
    std::string s = wkt ? wkt : "";
    CPLFree(wkt);
    return s;
}

std::string unreadable(const std::string& what) {
    const std::string why = gdalLastError();
    return "cannot read it as " + what + (why.empty() ? " (no such file, or a format GDAL does not know)" : " (" + why + ")");
}

std::vector<std::string> datasetFiles(const std::string& path) {
    initGdal();
    CPLErrorReset();
    std::vector<std::string> files{path};
    const GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_VECTOR | GDAL_OF_READONLY));
    CPLErrorReset();
    if (!ds) return files;
    char** list = ds->GetFileList();
    for (int i = 0; list && list[i]; ++i)
        if (std::string(list[i]) != path) files.emplace_back(list[i]);
    CSLDestroy(list);
    return files;
}

GDALDatasetUniquePtr openVectorFile(const std::string& path) {
    initGdal();
    CPLErrorReset();
    GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
    if (!ds) throw InputError(path, 0, unreadable("vector data"));
    return ds;
}

GDALDatasetUniquePtr openVectorUnlessRaster(const std::string& path) {
    initGdal();
    CPLErrorReset();
    GDALDatasetUniquePtr vector(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
    if (vector && vector->GetLayerCount() > 0) return vector;
    CPLErrorReset();
    if (!GDALDatasetUniquePtr(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY)))
        throw InputError(path, 0, unreadable("polygons or a raster"));
    return nullptr;
}

void requireDtmCrs(OGRLayer& layer, const std::string& path, const Dtm& dtm) {
    const std::string crs = wktOf(layer.GetSpatialRef());
    OGREnvelope e;
    const bool notDegrees = layer.GetExtent(&e, TRUE) == OGRERR_NONE && (e.MinX < -180 || e.MaxX > 180 || e.MinY < -90 || e.MaxY > 90);
    if (notDegrees && crsName(crs) == "WGS 84") return;
    if (!sameCrs(crs, dtm.grid.crsWkt))
        throw InputError(path, 0, "layer '" + std::string(layer.GetName()) + "' is in " + crsName(crs) + ", the DTM (" + dtm.path + ") in " +
                                      crsName(dtm.grid.crsWkt) + ": reproject it (ogr2ogr -t_srs) to the DTM's CRS");
}

bool namesNoCrs(const std::string& path) {
    initGdal();
    CPLErrorReset();
    const GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_VECTOR | GDAL_OF_READONLY));
    CPLErrorReset();
    if (!ds) return false;
    if (ds->GetRasterCount() > 0) return ds->GetSpatialRef() == nullptr;
    bool layers = false;
    for (OGRLayer* layer : ds->GetLayers()) {
        if (layer->GetGeomType() == wkbNone) continue;
        if (layer->GetSpatialRef()) return false;
        layers = true;
    }
    return layers;
}

std::string geometriesHeld(GDALDataset& ds) {
    std::map<std::string, long> count;
    bool collection = false;
    for (OGRLayer* layer : ds.GetLayers()) {
        layer->ResetReading();
        for (auto& feature : *layer)
            if (const OGRGeometry* g = feature->GetGeometryRef()) {
                const OGRwkbGeometryType type = wkbFlatten(g->getGeometryType());
                ++count[OGRGeometryTypeToName(type)];
                collection = collection || type == wkbGeometryCollection;
            }
        layer->ResetReading();
    }
    if (count.empty()) return "it holds no feature with a geometry";
    std::string held;
    std::size_t k = 0;
    for (const auto& [name, n] : count)
        held += (k++ == 0 ? "" : k == count.size() ? " and " : ", ") + std::to_string(n) + " " + name;
    return "it holds " + held + (count.size() == 1 && count.begin()->second == 1 ? " feature" : " features") +
           (collection ? "; a geometry collection's parts become features of their own with ogr2ogr -explodecollections" : "");
}

void requireValidPolygon(const OGRGeometry& polygon, const std::string& path, const std::string& where) {
    if (!OGRGeometryFactory::haveGEOS() || polygon.IsValid()) return;
    throw InputError(path, 0, where + ": the polygon is not valid (a ring crosses itself or another, or is degenerate), so its inside "
                                      "is undefined: repair it (ogr2ogr -makevalid) or redraw it");
}

}  // namespace sylva::assess

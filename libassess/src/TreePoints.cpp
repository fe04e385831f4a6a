#include "libassess/TreePoints.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "GdalSupport.hpp"
#include "libcommon/InputError.hpp"
#include "libstand/Allometry.hpp"

namespace sylva::assess {

namespace {

bool endsWith(const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && std::equal(tail.rbegin(), tail.rend(), s.rbegin(),
                                                 [](char a, char b) { return std::tolower(a) == std::tolower(b); });
}

// Trees from the point layers of a file: each point a stem (each point of a multipoint too), its DBH
// in the field dbh_cm; allometry from the DBH (Eqs. 11-13), as for a CSV without it. Layers without
// points (a GeoPackage's style table, a polygon layer) are passed over.
stand::Forest readTreeLayer(const std::string& path, const Dtm& dtm) {
    GDALDatasetUniquePtr ds = openVectorFile(path);
    stand::Forest forest;
    forest.source = path;
    const auto add = [&](const OGRPoint& point, const OGRFeature& feature, int dbhField, const std::string& where) {
        stand::Tree t;
        t.id = static_cast<long>(forest.trees.size() + 1);
        t.x = point.getX();
        t.y = point.getY();
        t.dbhCm = feature.GetFieldAsDouble(dbhField);
        if (!feature.IsFieldSetAndNotNull(dbhField) || !(t.dbhCm > 0) || t.dbhCm > 200) {
            // A text field that is no number reads as 0: show what it holds.
            const bool text = feature.GetFieldDefnRef(dbhField)->GetType() == OFTString;
            const std::string given = !feature.IsFieldSetAndNotNull(dbhField) ? "missing"
                                      : text ? "'" + std::string(feature.GetFieldAsString(dbhField)) + "'"
                                             : readableNumber(t.dbhCm);
            throw InputError(path, 0, where + ": dbh_cm " + given + " is not a DBH in (0, 200] cm");
        }
        if (!std::isfinite(t.x) || !std::isfinite(t.y)) throw InputError(path, 0, where + ": a point without coordinates");
        t.heightM = stand::treeHeightM(t.dbhCm);
        t.crownLengthM = stand::crownLengthM(t.heightM);
        t.crownMassKg = stand::crownMassKg(t.dbhCm);
        forest.trees.push_back(t);
    };
    for (OGRLayer* layer : ds->GetLayers()) {
        if (layer->GetGeomType() == wkbNone) continue;
        const int dbhField = layer->GetLayerDefn()->GetFieldIndex("dbh_cm");
        const std::size_t before = forest.trees.size();
        // Features are counted from 1 in each layer's order, as the release and check-line readers
        // count them (GDAL's FID starts at 0 in GeoJSON and at 1 in a GeoPackage).
        long number = 0;
        for (auto& feature : *layer) {
            const OGRGeometry* g = feature->GetGeometryRef();
            const auto type = g ? wkbFlatten(g->getGeometryType()) : wkbNone;
            ++number;
            if (type != wkbPoint && type != wkbMultiPoint) continue;
            if (dbhField < 0)
                throw InputError(path, 0, "layer '" + std::string(layer->GetName()) + "' has points but no field dbh_cm (each tree's DBH in cm)");
            const std::string where = "layer '" + std::string(layer->GetName()) + "', feature " + std::to_string(number);
            if (type == wkbPoint)
                add(*g->toPoint(), *feature, dbhField, where);
            else
                for (const OGRPoint* point : *g->toMultiPoint()) add(*point, *feature, dbhField, where);
        }
        // After the loop: the CRS check reads the layer's extent, which restarts its reading.
        if (forest.trees.size() > before) requireDtmCrs(*layer, path, dtm);
    }
    if (forest.trees.empty()) throw InputError(path, 0, "no point in the file (" + geometriesHeld(*ds) + "): trees are a point layer with a dbh_cm field");
    return forest;
}

}  // namespace

stand::Forest readTreePoints(const std::string& path, const Dtm& dtm) {
    if (!endsWith(path, ".csv")) return readTreeLayer(path, dtm);
    stand::Forest forest = stand::readForestCsv(path);
    // A header alone: the map would come out bare, as if the trees had been left out on purpose.
    if (forest.trees.empty()) throw InputError(path, 0, "no tree in the file (to map without forest, leave out --trees)");
    return forest;
}


}  // namespace sylva::assess

#include "libassess/TreePoints.hpp"

#include <algorithm>
#include <cctype>

#include "GdalSupport.hpp"
#include "libcommon/InputError.hpp"
#include "libstand/Allometry.hpp"

namespace sylva::assess {

namespace {

bool endsWith(const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && std::equal(tail.rbegin(), tail.rend(), s.rbegin(),
                                                 [](char a, char b) { return std::tolower(a) == std::tolower(b); });
}

// Trees from a point layer: each point a stem, its DBH in the field dbh_cm; allometry from the DBH
// (Eqs. 11-13), as for a CSV without it.
stand::Forest readTreeLayer(const std::string& path, const Dtm& dtm) {
    GDALDatasetUniquePtr ds = openVectorFile(path);
    stand::Forest forest;
    forest.source = path;
    for (OGRLayer* layer : ds->GetLayers()) {
        requireDtmCrs(*layer, path, dtm);
        const int dbhField = layer->GetLayerDefn()->GetFieldIndex("dbh_cm");
        if (dbhField < 0) throw InputError(path, 0, "layer '" + std::string(layer->GetName()) + "' has no field dbh_cm (each tree's DBH in cm)");
        for (auto& feature : *layer) {
            const OGRGeometry* g = feature->GetGeometryRef();
            if (!g || wkbFlatten(g->getGeometryType()) != wkbPoint) continue;
            const auto* point = g->toPoint();
            stand::Tree t;
            t.id = static_cast<long>(forest.trees.size() + 1);
            t.x = point->getX();
            t.y = point->getY();
            t.dbhCm = feature->GetFieldAsDouble(dbhField);
            if (!feature->IsFieldSetAndNotNull(dbhField) || !(t.dbhCm > 0) || t.dbhCm > 200)
                throw InputError(path, 0, "feature " + std::to_string(feature->GetFID()) + ": dbh_cm " +
                                              (feature->IsFieldSetAndNotNull(dbhField) ? readableNumber(t.dbhCm) : "missing") +
                                              " is not a DBH in (0, 200] cm");
            t.heightM = stand::treeHeightM(t.dbhCm);
            t.crownLengthM = stand::crownLengthM(t.heightM);
            t.crownMassKg = stand::crownMassKg(t.dbhCm);
            forest.trees.push_back(t);
        }
    }
    if (forest.trees.empty()) throw InputError(path, 0, "no point in the file: trees are a point layer with a dbh_cm field");
    return forest;
}

}  // namespace

stand::Forest readTreePoints(const std::string& path, const Dtm& dtm) {
    return endsWith(path, ".csv") ? stand::readForestCsv(path) : readTreeLayer(path, dtm);
}


}  // namespace sylva::assess

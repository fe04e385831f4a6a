#include "libassess/SoilMap.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "GdalSupport.hpp"
#include "libcommon/CsvTable.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::assess {

namespace {

constexpr const char* kSceneSoil = "scene";

// Zone of each type: 1 + its place in the table (zone 0 is the scene's soil).
dem::SoilZones emptyZones(const std::vector<SoilType>& types, const Dtm& dtm, const dem::SoilContactParams& sceneSoil) {
    dem::SoilZones z;
    const RasterGrid& g = dtm.grid;
    const Eigen::Vector2d sw = g.centre(0, g.rows - 1);
    z.x0 = sw.x();
    z.y0 = sw.y();
    z.cell = g.cellSize();
    z.columns = g.columns;
    z.rows = g.rows;
    z.zone.assign(static_cast<std::size_t>(g.columns) * g.rows, 0);
    z.names.push_back(kSceneSoil);
    z.params.push_back(sceneSoil);
    for (const auto& t : types) {
        z.names.push_back(t.name);
        z.params.push_back(t.params);
    }
    return z;
}

// The zones' rows run south to north, the DTM's north to south.
std::size_t zoneIndex(const RasterGrid& g, int c, int r) { return static_cast<std::size_t>(g.rows - 1 - r) * g.columns + c; }

void zonesFromPolygons(GDALDataset& ds, const std::string& path, const std::vector<SoilType>& types, const Dtm& dtm, dem::SoilZones& z) {
    std::map<std::string, std::uint16_t> zoneOf;
    for (std::size_t k = 0; k < types.size(); ++k) zoneOf[types[k].name] = static_cast<std::uint16_t>(k + 1);
    std::vector<long> featureAt(z.zone.size(), 0);  // which feature set each cell, for the overlap message
    long feature = 0;
    for (OGRLayer* layer : ds.GetLayers()) {
        const int field = layer->GetLayerDefn()->GetFieldIndex("soil");
        bool any = false;
        for (auto& f : *layer) {
            const OGRGeometry* g = f->GetGeometryRef();
            const auto type = g ? wkbFlatten(g->getGeometryType()) : wkbNone;
            if (type != wkbPolygon && type != wkbMultiPolygon) continue;
            any = true;
            const std::string where = "layer '" + std::string(layer->GetName()) + "', feature " + std::to_string(++feature);
            if (field < 0) throw InputError(path, 0, "layer '" + std::string(layer->GetName()) + "' has polygons but no field `soil` (a soil type's name)");
            requireValidPolygon(*g, path, where);
            const std::string name = f->IsFieldSetAndNotNull(field) ? f->GetFieldAsString(field) : "";
            const auto it = zoneOf.find(name);
            if (it == zoneOf.end()) {
                std::string known;
                for (const auto& t : types) known += (known.empty() ? "" : ", ") + t.name;
                throw InputError(path, 0, where + ": soil '" + name + "' is not in the soil types' table (" + known + ")");
            }
            forEachCellCentreInside(*g, dtm.grid, [&](int c, int r) {
                const std::size_t i = zoneIndex(dtm.grid, c, r);
                if (featureAt[i] != 0 && z.zone[i] != it->second) {
                    const Eigen::Vector2d p = dtm.grid.centre(c, r);
                    throw InputError(path, 0, where + " (" + name + ") overlaps feature " + std::to_string(featureAt[i]) + " (" + z.names[z.zone[i]] +
                                                  ") at the DTM cell centred on " + readableNumber(p.x()) + ", " + readableNumber(p.y()) +
                                                  ": a cell has one soil");
                }
                z.zone[i] = it->second;
                featureAt[i] = feature;
            });
        }
        if (any) requireDtmCrs(*layer, path, dtm);
    }
    if (feature == 0) throw InputError(path, 0, "no polygon in the file (" + geometriesHeld(ds) + "): a soil map is polygons with a field `soil`, or a raster of codes");
}

void zonesFromRaster(const std::string& path, const std::vector<SoilType>& types, const Dtm& dtm, dem::SoilZones& z) {
    const GeoRaster map = readRaster(path, "a soil map's codes");
    if (!sameCrs(map.grid.crsWkt, dtm.grid.crsWkt))
        throw InputError(path, 0, "the soil raster is in " + crsName(map.grid.crsWkt) + ", the DTM (" + dtm.path + ") in " +
                                      crsName(dtm.grid.crsWkt) + ": reproject it (gdalwarp -t_srs) to the DTM's CRS");
    std::map<long, std::uint16_t> zoneOf;
    for (std::size_t k = 0; k < types.size(); ++k) zoneOf[types[k].code] = static_cast<std::uint16_t>(k + 1);
    const RasterGrid& g = dtm.grid;
    for (int r = 0; r < g.rows; ++r)
        for (int c = 0; c < g.columns; ++c) {
            const Eigen::Vector2d p = g.centre(c, r);
            int mc = 0, mr = 0;
            if (!map.grid.cellOf(p.x(), p.y(), mc, mr)) continue;
            const double v = map.values[map.grid.index(mc, mr)];
            if (!std::isfinite(v)) continue;
            const auto it = zoneOf.find(std::lround(v));
            if (it == zoneOf.end() || std::lround(v) != v)
                throw InputError(path, 0, "cell column " + std::to_string(mc + 1) + ", row " + std::to_string(mr + 1) + " holds " + readableNumber(v) +
                                              ", not the code of a soil type in the table");
            z.zone[zoneIndex(g, c, r)] = it->second;
        }
}

}  // namespace

std::vector<SoilType> readSoilTypes(const std::string& path, const dem::SoilContactParams& sceneSoil) {
    const CsvTable t = CsvTable::read(path);
    const std::size_t name = t.require("name"), code = t.require("code");
    // A misspelt column would leave that soil on the scene's value without a word.
    static const std::set<std::string> known{"name", "code", "kn_n_m", "kappa", "damping_ratio", "restitution", "friction_deg"};
    for (const std::string& column : t.header())
        if (!known.count(column))
            throw InputError(path, 1, "unknown column '" + column +
                                          "' (the columns are name, code and any of kn_n_m, kappa, damping_ratio or restitution, friction_deg)");
    if (t.has("damping_ratio") && t.has("restitution"))
        throw InputError(path, 1, "both damping_ratio and restitution: give one (Eq. 15 ties them)");
    std::vector<SoilType> types;
    for (std::size_t row = 0; row < t.rows(); ++row) {
        SoilType s;
        s.name = t.text(row, name);
        s.code = t.integer(row, code);
        s.params = sceneSoil;
        if (s.name.empty()) t.fail(row, name, "a soil type needs a name");
        if (s.name == kSceneSoil) t.fail(row, name, "'scene' names the scene's own soil, where the map says nothing: choose another name");
        for (const auto& o : types) {
            if (o.name == s.name) t.fail(row, name, "soil type '" + s.name + "' is named twice");
            if (o.code == s.code) t.fail(row, code, "code " + std::to_string(s.code) + " is used by '" + o.name + "' too");
        }
        const auto value = [&](const char* column, double lo, double hi, bool loOpen, bool hiOpen, double& into) {
            const auto c = t.index(column);
            if (!c || t.text(row, *c).empty()) return;
            const double v = t.number(row, *c);
            if ((loOpen ? !(v > lo) : !(v >= lo)) || (hiOpen ? !(v < hi) : !(v <= hi)))
                t.fail(row, *c, readableNumber(v) + " is outside " + (loOpen ? "(" : "[") + readableNumber(lo) + ", " + readableNumber(hi) + (hiOpen ? ")" : "]"));
            into = v;
        };
        value("kn_n_m", 0, 1e12, true, false, s.params.kn);
        value("kappa", 0, 10, true, false, s.params.kappa);
        value("damping_ratio", 0, 1, false, true, s.params.dampingRatio);
        double restitution = 0;
        value("restitution", 0, 1, true, false, restitution);
        if (restitution > 0) s.params.dampingRatio = dem::dampingRatioFromRestitution(restitution);
        value("friction_deg", 0, 90, false, true, s.params.frictionDeg);
        types.push_back(s);
    }
    if (types.empty()) throw InputError(path, 0, "no soil type in the table");
    if (types.size() >= 65535) throw InputError(path, 0, "more than 65 534 soil types");
    return types;
}

std::shared_ptr<dem::SoilZones> readSoilZones(const std::string& mapPath, const std::vector<SoilType>& types, const Dtm& dtm,
                                              const dem::SoilContactParams& sceneSoil) {
    auto zones = std::make_shared<dem::SoilZones>(emptyZones(types, dtm, sceneSoil));
    if (GDALDatasetUniquePtr vector = openVectorUnlessRaster(mapPath))
        zonesFromPolygons(*vector, mapPath, types, dtm, *zones);
    else
        zonesFromRaster(mapPath, types, dtm, *zones);
    // A map that reaches no cell would leave the scene's soil everywhere without a word.
    if (std::all_of(zones->zone.begin(), zones->zone.end(), [](std::uint16_t k) { return k == 0; }))
        throw InputError(mapPath, 0, "it places no soil type on any cell centre of the DTM (" + dtm.path +
                                         "): is it outside it, in other coordinates, or all NODATA?");
    return zones;
}

}  // namespace sylva::assess

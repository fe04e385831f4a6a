#include "libassess/StandPolygons.hpp"

#include <Eigen/Core>

#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <unordered_map>

#include "GdalSupport.hpp"
#include "libcommon/InputError.hpp"
#include "libdem/Campaign.hpp"
#include "libstand/Inventory.hpp"
#include "libstand/StandCatalogue.hpp"

namespace fs = std::filesystem;

namespace sylva::assess {

namespace {

// Any geometry's area (0 for points and lines), m2.
double areaOf(const OGRGeometry& g) { return OGR_G_Area(OGRGeometry::ToHandle(const_cast<OGRGeometry*>(&g))); }

// The polygons of a cut: a polygon touching the terrain's edge comes back as a collection with the
// lines it shares with the edge.
std::vector<const OGRPolygon*> polygonsOf(const OGRGeometry& g) {
    switch (wkbFlatten(g.getGeometryType())) {
        case wkbPolygon:
            return {g.toPolygon()};
        case wkbMultiPolygon:
        case wkbGeometryCollection: {
            std::vector<const OGRPolygon*> all;
            for (const OGRGeometry* part : *g.toGeometryCollection())
                for (const OGRPolygon* p : polygonsOf(*part)) all.push_back(p);
            return all;
        }
        default:
            return {};
    }
}

// Overlaps smaller than this are the slivers two digitised neighbours leave along a shared border.
constexpr double kOverlapToleranceM2 = 1.0;

// The inventory a polygon names: beside the vector file first (a project folder travels whole), then
// from the working folder.
std::string resolveInventory(const std::string& prefix, const std::string& vectorPath, const std::string& where) {
    std::vector<fs::path> tried;
    if (fs::path(prefix).is_relative()) tried.push_back(fs::path(vectorPath).parent_path() / prefix);
    tried.push_back(prefix);
    for (const auto& p : tried)
        if (fs::is_regular_file(p.string() + "_stems.csv") && fs::is_regular_file(p.string() + "_plots.csv")) return p.lexically_normal().string();
    std::string list;
    for (const auto& p : tried) list += (list.empty() ? "" : ", ") + p.string() + "_stems.csv";
    throw InputError(vectorPath, 0, where + ": stand '" + prefix + "' has no inventory (looked for " + list +
                                        " and its _plots.csv): `stand` is the prefix of PREFIX_stems.csv and PREFIX_plots.csv");
}

stand::Window windowOf(const OGRPolygon& polygon, const std::string& path, const std::string& where) {
    const auto ring = [](const OGRLinearRing& r) {
        std::vector<Eigen::Vector2d> points;
        for (const OGRPoint& p : r) points.emplace_back(p.getX(), p.getY());
        return points;
    };
    std::vector<std::vector<Eigen::Vector2d>> holes;
    for (int k = 0; k < polygon.getNumInteriorRings(); ++k) holes.push_back(ring(*polygon.getInteriorRing(k)));
    try {
        return stand::Window::polygon(ring(*polygon.getExteriorRing()), std::move(holes));
    } catch (const InputError& e) {
        throw InputError(path, 0, where + ": " + e.what());
    }
}

// Stems of different polygons may come closer than their radii where the polygons share a border:
// the later one is dropped (a tree stands in one stand). A polygon's own stems are not held to it:
// the generator spaces them, but a coppice stool's stems may stand closer than their radii, as
// inventories record them, and were dropped as if a neighbour's (a third of such a stand).
class StemOccupancy {
public:
    bool overlaps(const stand::Tree& t) const {
        const long cx = cellOf(t.x), cy = cellOf(t.y);
        for (long i = cx - 1; i <= cx + 1; ++i)
            for (long j = cy - 1; j <= cy + 1; ++j) {
                const auto it = cells_.find(key(i, j));
                if (it == cells_.end()) continue;
                for (const Eigen::Vector3d& o : it->second)
                    if (std::hypot(o.x() - t.x, o.y() - t.y) < o.z() + t.dbhCm / 200.0) return true;
            }
        return false;
    }
    void add(const stand::Tree& t) { cells_[key(cellOf(t.x), cellOf(t.y))].emplace_back(t.x, t.y, t.dbhCm / 200.0); }

private:
    // 2 m cells hold any two touching stems of DBH up to 200 cm in neighbouring cells.
    static long cellOf(double v) { return static_cast<long>(std::floor(v / 2.0)); }
    static long long key(long i, long j) { return (static_cast<long long>(i) << 32) ^ static_cast<unsigned long>(j); }
    std::unordered_map<long long, std::vector<Eigen::Vector3d>> cells_;  // x, y, radius
};

bool isPolygon(const OGRGeometry* g) {
    const auto type = g ? wkbFlatten(g->getGeometryType()) : wkbNone;
    return type == wkbPolygon || type == wkbMultiPolygon;
}

// "xmin..xmax x ymin..ymax", as the messages give a rectangle.
std::string extentText(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
    return readableNumber(lo.x()) + ".." + readableNumber(hi.x()) + " x " + readableNumber(lo.y()) + ".." + readableNumber(hi.y());
}

bool holdsPolygons(OGRLayer& layer) {
    for (auto& f : layer)
        if (isPolygon(f->GetGeometryRef())) return true;
    return false;
}

}  // namespace

StandForest readStandPolygons(const std::string& path, const Dtm& dtm, std::uint64_t seed, double tipDiameter) {
    GDALDatasetUniquePtr ds = openVectorFile(path);
    const Eigen::Vector2d lo = dtm.grid.centre(0, dtm.grid.rows - 1), hi = dtm.grid.centre(dtm.grid.columns - 1, 0);
    const Eigen::Vector2d halfCell(0.5 * std::abs(dtm.grid.geoTransform[1]), 0.5 * std::abs(dtm.grid.geoTransform[5]));
    const Eigen::Vector2d outerLo = lo - halfCell, outerHi = hi + halfCell;
    const auto rectangle = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
        OGRPolygon p;
        OGRLinearRing r;
        r.addPoint(a.x(), a.y());
        r.addPoint(b.x(), a.y());
        r.addPoint(b.x(), b.y());
        r.addPoint(a.x(), b.y());
        r.addPoint(a.x(), a.y());
        p.addRing(&r);
        return p;
    };
    const OGRPolygon terrain = rectangle(lo, hi), outline = rectangle(outerLo, outerHi);
    StandForest out;
    out.forest.source = path;
    std::map<std::string, std::unique_ptr<stand::StandCatalogue>> catalogues;
    std::vector<std::unique_ptr<OGRGeometry>> onTerrain;  // each feature's polygon(s) on the terrain, for the overlap check
    StemOccupancy occupied;
    long feature = 0, part = 0, stool = 0;
    bool defaultStructureSaid = false;
    for (OGRLayer* layer : ds->GetLayers()) {
        if (layer->GetGeomType() == wkbNone) continue;
        const int standField = layer->GetLayerDefn()->GetFieldIndex("stand");
        const int structureField = layer->GetLayerDefn()->GetFieldIndex("structure");
        // Its CRS first: polygons in degrees all lay "outside the terrain", which hid the cause.
        if (holdsPolygons(*layer)) requireDtmCrs(*layer, path, dtm);
        for (auto& f : *layer) {
            const OGRGeometry* g = f->GetGeometryRef();
            if (!isPolygon(g)) continue;
            const std::string where = "layer '" + std::string(layer->GetName()) + "', feature " + std::to_string(++feature);
            if (standField < 0)
                throw InputError(path, 0, "layer '" + std::string(layer->GetName()) +
                                              "' has polygons but no field `stand` (each stand's inventory prefix, e.g. data/stands/MO1)");
            if (!f->IsFieldSetAndNotNull(standField) || std::string(f->GetFieldAsString(standField)).empty())
                throw InputError(path, 0, where + ": `stand` is empty (the stand's inventory prefix, e.g. data/stands/MO1)");
            requireValidPolygon(*g, path, where);
            StandPolygon s;
            s.feature = feature;
            s.inventory = resolveInventory(f->GetFieldAsString(standField), path, where);
            if (structureField >= 0 && f->IsFieldSetAndNotNull(structureField)) {
                try {
                    s.structure = stand::parseForestStructure(f->GetFieldAsString(structureField));
                } catch (const InputError& e) {
                    throw InputError(path, 0, where + ": " + e.what());
                }
            } else if (!defaultStructureSaid) {
                out.notes.push_back(path + ": a stand without `structure` is aggregated (A); give structure NA for a random forest");
                defaultStructureSaid = true;
            }
            std::unique_ptr<OGRGeometry> cut(g->Intersection(&terrain));
            if (!cut || !(areaOf(*cut) > 0))
                throw InputError(path, 0, where + " (stand " + s.inventory + ") lies outside the terrain, which spans the DTM's cell centres " +
                                              extentText(lo, hi));
            // Cut silently, a stand drawn past the DTM's edge lost its forest there without a word. Past
            // its outer edge, not its cell centres: a stand drawn to the edge loses a half-cell strip, as
            // every forest on a DTM does.
            std::unique_ptr<OGRGeometry> onDtm(g->Intersection(&outline));
            const double beyond = areaOf(*g) - (onDtm ? areaOf(*onDtm) : 0.0);
            if (beyond > kOverlapToleranceM2)
                out.notes.push_back(path + ": " + where + " (stand " + s.inventory + "): " + readableNumber(std::round(beyond)) + " m2 of its " +
                                    readableNumber(std::round(areaOf(*g))) + " m2 lie beyond the DTM (" + extentText(outerLo, outerHi) +
                                    ") and are left without trees");
            for (std::size_t k = 0; k < onTerrain.size(); ++k) {
                std::unique_ptr<OGRGeometry> both(onTerrain[k]->Intersection(cut.get()));
                if (both && areaOf(*both) > kOverlapToleranceM2)
                    throw InputError(path, 0, where + " overlaps feature " + std::to_string(out.polygons[k].feature) + " by " +
                                                  readableNumber(areaOf(*both)) + " m2: a tree stands in one stand");
            }
            auto& catalogue = catalogues[s.inventory];
            if (!catalogue) {
                const stand::Inventory inventory = stand::readInventory(s.inventory + "_stems.csv", s.inventory + "_plots.csv");
                for (const auto& w : inventory.warnings) out.notes.push_back(w);
                dem::requireBuildableStems(inventory, s.inventory + "_stems.csv", tipDiameter);
                catalogue = std::make_unique<stand::StandCatalogue>(inventory, s.inventory + "_stems.csv");
            }
            for (const OGRPolygon* p : polygonsOf(*cut)) {
                const stand::Window window = windowOf(*p, path, where);
                stand::GenerationSettings settings;
                settings.structure = s.structure;
                // Part k of the file: its own stream, fixed by the run's seed (the hazard runs draw from runSeed(seed, i)).
                settings.seed = dem::splitmix64(dem::splitmix64(seed) + static_cast<std::uint64_t>(++part));
                if (s.seed == 0) s.seed = settings.seed;
                stand::GeneratedForest g;
                try {
                    g = stand::generateForest(*catalogue, window, settings);
                } catch (const InputError& e) {
                    throw InputError(path, 0, where + " (stand " + s.inventory + "): " + e.what());
                }
                for (const auto& w : g.warnings) out.notes.push_back(where + ": " + w);
                s.areaHa += window.area() / 1e4;
                long dropped = 0;
                const long stoolBase = stool;
                const std::size_t first = out.forest.trees.size();
                for (stand::Tree t : g.forest.trees) {
                    if (occupied.overlaps(t)) {
                        ++dropped;
                        continue;
                    }
                    t.id = static_cast<long>(out.forest.trees.size() + 1);
                    if (t.stool) {
                        t.stool = *t.stool + stoolBase;
                        stool = std::max(stool, *t.stool);
                    }
                    out.forest.trees.push_back(t);
                    ++s.stems;
                }
                for (std::size_t i = first; i < out.forest.trees.size(); ++i) occupied.add(out.forest.trees[i]);
                if (dropped)
                    out.notes.push_back(where + ": " + std::to_string(dropped) + " stem(s) dropped where they would overlap a neighbouring stand's");
            }
            onTerrain.push_back(std::move(cut));
            out.polygons.push_back(s);
        }
    }
    if (out.polygons.empty()) throw InputError(path, 0, "no polygon in the file (" + geometriesHeld(*ds) + "): stands are polygons with a field `stand` naming an inventory");
    return out;
}

}  // namespace sylva::assess

#include "libassess/BlockPaths.hpp"

#include <cpl_error.h>
#include <ogr_spatialref.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "GdalSupport.hpp"
#include "libcommon/InputError.hpp"

namespace fs = std::filesystem;

namespace sylva::assess {

namespace {

PathPoint pointOf(const dem::TrajectorySample& s) {
    PathPoint p;
    p.x = s.position.x();
    p.y = s.position.y();
    p.z = s.position.z();
    p.time = static_cast<float>(s.t);
    p.speedMs = static_cast<float>(s.velocity.norm());
    p.energyKj = static_cast<float>((s.translationalEnergy + s.rotationalEnergy) / 1000);
    return p;
}

// GDAL's last error as " (why)", "" if it said nothing.
std::string gdalWhy() {
    const std::string why = gdalLastError();
    return why.empty() ? why : " (" + why + ")";
}

[[noreturn]] void cannotWrite(const std::string& path) { throw InputError(path, 0, "cannot write the GeoPackage" + gdalWhy()); }

// GeoPackage commits each feature on its own outside a transaction: 10^4 paths would take minutes.
template <class Write>
void inTransaction(GDALDataset& ds, const std::string& path, Write write) {
    if (ds.StartTransaction() != OGRERR_NONE) cannotWrite(path);
    try {
        write();
    } catch (...) {
        ds.RollbackTransaction();
        throw;
    }
    if (ds.CommitTransaction() != OGRERR_NONE) cannotWrite(path);
}

OGRLayer& createLayer(GDALDataset& ds, const std::string& path, const std::string& name, OGRSpatialReference* crs,
                      OGRwkbGeometryType type) {
    if (ds.GetLayerByName(name.c_str()))
        throw InputError(path, 0, "already holds a layer '" + name + "': a pass is written once (another run goes into a new file)");
    OGRLayer* layer = ds.CreateLayer(name.c_str(), crs, type, nullptr);
    if (!layer) cannotWrite(path);
    return *layer;
}

void addField(OGRLayer& layer, const std::string& path, const char* name, OGRFieldType type, OGRFieldSubType subType = OFSTNone) {
    OGRFieldDefn field(name, type);
    field.SetSubType(subType);
    if (layer.CreateField(&field) != OGRERR_NONE) cannotWrite(path);
}

void addFeature(OGRLayer& layer, const std::string& path, OGRFeature& feature) {
    if (layer.CreateFeature(&feature) != OGRERR_NONE) cannotWrite(path);
}

void writePaths(OGRLayer& layer, const std::string& path, const std::vector<BlockPath>& paths) {
    addField(layer, path, "run", OFTInteger64);
    addField(layer, path, "seed", OFTString);
    addField(layer, path, "release_col", OFTInteger);
    addField(layer, path, "release_row", OFTInteger);
    addField(layer, path, "stop", OFTString);
    addField(layer, path, "path_m", OFTReal);
    addField(layer, path, "reach_m", OFTReal);
    for (const BlockPath& p : paths) {
        OGRFeature feature(layer.GetLayerDefn());
        feature.SetField("run", static_cast<GIntBig>(p.run));
        feature.SetField("seed", std::to_string(p.seed).c_str());
        feature.SetField("release_col", p.releaseColumn + 1);
        feature.SetField("release_row", p.releaseRow + 1);
        feature.SetField("stop", dem::toString(p.reason).c_str());
        feature.SetField("path_m", p.pathLengthM);
        feature.SetField("reach_m", p.reachM);
        // A one-point line is not a line to GIS readers (GEOS refuses it): the path keeps its fields.
        if (p.points.size() >= 2) {
            OGRLineString line;
            line.setNumPoints(static_cast<int>(p.points.size()));
            for (std::size_t i = 0; i < p.points.size(); ++i) line.setPoint(static_cast<int>(i), p.points[i].x, p.points[i].y, p.points[i].z);
            feature.SetGeometry(&line);
        }
        addFeature(layer, path, feature);
    }
}

void writeImpacts(OGRLayer& layer, const std::string& path, const std::vector<ImpactPoint>& impacts) {
    addField(layer, path, "run", OFTInteger64);
    addField(layer, path, "tree", OFTInteger64);
    addField(layer, path, "dbh_cm", OFTReal);
    addField(layer, path, "height_m", OFTReal);
    addField(layer, path, "energy_before_kj", OFTReal);
    addField(layer, path, "energy_after_kj", OFTReal);
    addField(layer, path, "speed_before_m_s", OFTReal);
    addField(layer, path, "stem_broken", OFTInteger, OFSTBoolean);
    addField(layer, path, "root_yielded", OFTInteger, OFSTBoolean);
    for (const ImpactPoint& i : impacts) {
        OGRFeature feature(layer.GetLayerDefn());
        feature.SetField("run", static_cast<GIntBig>(i.run));
        feature.SetField("tree", static_cast<GIntBig>(i.tree));
        feature.SetField("dbh_cm", i.dbhCm);
        feature.SetField("height_m", i.heightAboveFootM);
        feature.SetField("energy_before_kj", i.energyBeforeKj);
        feature.SetField("energy_after_kj", i.energyAfterKj);
        feature.SetField("speed_before_m_s", i.speedBeforeMs);
        feature.SetField("stem_broken", i.stemBroken ? 1 : 0);
        feature.SetField("root_yielded", i.rootYielded ? 1 : 0);
        OGRPoint foot(i.x, i.y, i.z);
        feature.SetGeometry(&foot);
        addFeature(layer, path, feature);
    }
}

GDALDatasetUniquePtr openOrCreateGeoPackage(const std::string& path) {
    initGdal();
    CPLErrorReset();
    std::error_code ec;
    if (fs::exists(path, ec)) {
        const char* const drivers[] = {"GPKG", nullptr};
        GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE, drivers));
        if (!ds) throw InputError(path, 0, "exists but is not a GeoPackage GDAL can add layers to" + gdalWhy());
        return ds;
    }
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GPKG");
    if (!driver) throw InputError(path, 0, "GDAL has no GeoPackage (GPKG) driver");
    GDALDatasetUniquePtr ds(driver->Create(path.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    if (!ds) cannotWrite(path);
    return ds;
}

// Written so: a title line (VTK reads 256 characters of it), ASCII, the dataset type.
std::ofstream createVtk(const std::string& path, const std::string& title, const std::string& dataset) {
    std::ofstream out(path, std::ios::trunc);
    if (!out) throw sylva::cannotWrite(path);
    // 12 digits: 0.01 mm on Lambert-93's seven-digit eastings, where a float would round to 0.5 m.
    out.precision(12);
    out << "# vtk DataFile Version 3.0\n" << title.substr(0, 255) << "\nASCII\nDATASET " << dataset << '\n';
    return out;
}

void closeVtk(std::ofstream& out, const std::string& path) {
    out.close();
    if (!out) throw sylva::cannotWrite(path);
}

std::string createDir(const std::string& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw InputError(dir, 0, "cannot create the folder (" + ec.message() + ")");
    return dir;
}

}  // namespace

std::vector<PathPoint> thinPath(const std::vector<dem::TrajectorySample>& samples, double spacingM, double maxGapS) {
    if (!(spacingM > 0) || !(maxGapS > 0))
        throw std::invalid_argument("thinPath: spacing " + readableNumber(spacingM) + " m and gap " + readableNumber(maxGapS) + " s must be > 0");
    std::vector<PathPoint> kept;
    if (samples.empty()) return kept;
    const dem::TrajectorySample* last = &samples.front();
    kept.push_back(pointOf(*last));
    for (std::size_t i = 1; i < samples.size(); ++i) {
        const dem::TrajectorySample& s = samples[i];
        if (i + 1 == samples.size() || (s.position - last->position).norm() >= spacingM || s.t - last->t >= maxGapS) {
            kept.push_back(pointOf(s));
            last = &s;
        }
    }
    return kept;
}

std::vector<ImpactPoint> impactPoints(long run, const std::vector<dem::TreeImpact>& impacts, const stand::Forest& forest, const Dtm& dtm) {
    std::vector<ImpactPoint> points;
    if (impacts.empty()) return points;
    std::unordered_map<long, const stand::Tree*> byId;
    for (const stand::Tree& t : forest.trees) byId.emplace(t.id, &t);
    for (const dem::TreeImpact& impact : impacts) {
        const auto found = byId.find(impact.tree);
        if (found == byId.end())
            throw std::logic_error("impactPoints: run " + std::to_string(run) + " hit tree " + std::to_string(impact.tree) + ", which the forest" +
                                   (forest.source.empty() ? std::string() : " of " + forest.source) + " does not have");
        const stand::Tree& tree = *found->second;
        ImpactPoint p;
        p.run = run;
        p.tree = tree.id;
        p.x = tree.x;
        p.y = tree.y;
        p.z = dtm.elevation.height(tree.x, tree.y);
        p.dbhCm = tree.dbhCm;
        p.heightAboveFootM = impact.height;
        p.energyBeforeKj = impact.energyBefore / 1000;
        p.energyAfterKj = impact.energyAfter / 1000;
        p.speedBeforeMs = impact.speedBefore;
        p.stemBroken = impact.stemBroken;
        p.rootYielded = impact.rootYielded;
        points.push_back(p);
    }
    return points;
}

void writePathLayers(const std::string& gpkgPath, const Dtm& dtm, const std::string& pass, const std::vector<BlockPath>& paths,
                     const std::vector<ImpactPoint>& impacts) {
    GDALDatasetUniquePtr ds = openOrCreateGeoPackage(gpkgPath);
    OGRSpatialReference crs;
    if (!dtm.grid.crsWkt.empty()) {
        if (crs.importFromWkt(dtm.grid.crsWkt.c_str()) != OGRERR_NONE)
            throw InputError(dtm.path, 0, "GDAL cannot read back the DTM's CRS to write " + gpkgPath);
        // Easting, northing: the order the paths' coordinates are in, whatever the CRS's definition says.
        crs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    }
    OGRSpatialReference* layerCrs = dtm.grid.crsWkt.empty() ? nullptr : &crs;
    OGRLayer& pathLayer = createLayer(*ds, gpkgPath, "paths_" + pass, layerCrs, wkbLineString25D);
    inTransaction(*ds, gpkgPath, [&] { writePaths(pathLayer, gpkgPath, paths); });
    OGRLayer& impactLayer = createLayer(*ds, gpkgPath, "impacts_" + pass, layerCrs, wkbPoint25D);
    inTransaction(*ds, gpkgPath, [&] { writeImpacts(impactLayer, gpkgPath, impacts); });
    ds.reset();  // closes and flushes the file (GDAL 3.6 has no Close() returning an error)
    if (CPLGetLastErrorType() >= CE_Failure) cannotWrite(gpkgPath);
}

void writeVtkScene(const std::string& dir, const Dtm& dtm, const stand::Forest& forest) {
    const RasterGrid& g = dtm.grid;
    const std::string terrainPath = createDir(dir) + "/terrain.vtk";
    std::ofstream terrain = createVtk(terrainPath, "sylvarock terrain: the DTM's cell centres, " + crsName(g.crsWkt), "STRUCTURED_GRID");
    const long n = static_cast<long>(g.columns) * g.rows;
    std::vector<double> heights;
    heights.reserve(static_cast<std::size_t>(n));
    terrain << "DIMENSIONS " << g.columns << ' ' << g.rows << " 1\nPOINTS " << n << " double\n";
    // From the south: east then north are VTK's i and j, so the surface's normals point up.
    for (int row = g.rows - 1; row >= 0; --row)
        for (int col = 0; col < g.columns; ++col) {
            const Eigen::Vector2d c = g.centre(col, row);
            heights.push_back(dtm.elevation.height(c.x(), c.y()));
            terrain << c.x() << ' ' << c.y() << ' ' << heights.back() << '\n';
        }
    terrain << "POINT_DATA " << n << "\nSCALARS elevation_m double 1\nLOOKUP_TABLE default\n";
    for (double z : heights) terrain << z << '\n';
    closeVtk(terrain, terrainPath);

    if (forest.trees.empty()) return;
    const std::string treesPath = dir + "/trees.vtk";
    std::ofstream trees = createVtk(treesPath, "sylvarock trees: stems from foot to top, " + crsName(g.crsWkt), "POLYDATA");
    const std::size_t m = forest.trees.size();
    trees << "POINTS " << 2 * m << " double\n";
    for (const stand::Tree& t : forest.trees) {
        const double foot = dtm.elevation.height(t.x, t.y);
        trees << t.x << ' ' << t.y << ' ' << foot << '\n' << t.x << ' ' << t.y << ' ' << foot + t.heightM << '\n';
    }
    trees << "LINES " << m << ' ' << 3 * m << '\n';
    for (std::size_t i = 0; i < m; ++i) trees << "2 " << 2 * i << ' ' << 2 * i + 1 << '\n';
    trees << "CELL_DATA " << m << "\nSCALARS dbh_cm double 1\nLOOKUP_TABLE default\n";
    for (const stand::Tree& t : forest.trees) trees << t.dbhCm << '\n';
    closeVtk(trees, treesPath);
}

void writeVtkPaths(const std::string& dir, const std::string& pass, const std::vector<BlockPath>& paths) {
    const std::string path = createDir(dir) + "/paths_" + pass + ".vtk";
    std::vector<const BlockPath*> lines;
    std::size_t points = 0;
    for (const BlockPath& p : paths)
        if (p.points.size() >= 2) {
            lines.push_back(&p);
            points += p.points.size();
        }
    std::ofstream out = createVtk(path, "sylvarock block paths, pass " + pass, "POLYDATA");
    out << "POINTS " << points << " double\n";
    for (const BlockPath* p : lines)
        for (const PathPoint& q : p->points) out << q.x << ' ' << q.y << ' ' << q.z << '\n';
    out << "LINES " << lines.size() << ' ' << lines.size() + points << '\n';
    std::size_t next = 0;
    for (const BlockPath* p : lines) {
        out << p->points.size();
        for (std::size_t i = 0; i < p->points.size(); ++i) out << ' ' << next++;
        out << '\n';
    }
    out << "POINT_DATA " << points << '\n';
    // A float's own digits: 12 would print 3.3f as 3.29999995232.
    out.precision(std::numeric_limits<float>::digits10);
    const auto scalars = [&](const char* name, float PathPoint::*value) {
        out << "SCALARS " << name << " float 1\nLOOKUP_TABLE default\n";
        for (const BlockPath* p : lines)
            for (const PathPoint& q : p->points) out << q.*value << '\n';
    };
    scalars("speed_m_s", &PathPoint::speedMs);
    scalars("energy_kj", &PathPoint::energyKj);
    scalars("time_s", &PathPoint::time);
    out << "CELL_DATA " << lines.size() << "\nSCALARS run long 1\nLOOKUP_TABLE default\n";
    for (const BlockPath* p : lines) out << p->run << '\n';
    closeVtk(out, path);
}

}  // namespace sylva::assess

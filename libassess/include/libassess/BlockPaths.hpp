#pragma once
// The block paths of a hazard run, for looking at them rather than at the rasters: as GeoPackage
// layers a GIS lays over the DTM (each block's line and the trees it hit), and as legacy VTK files
// ParaView shows in 3-D with the terrain and the stems. Both keep the DTM's own coordinates.
#include <cstdint>
#include <string>
#include <vector>

#include "libassess/GeoRaster.hpp"
#include "libdem/BlockRun.hpp"
#include "libstand/Forest.hpp"

namespace sylva::assess {

struct PathPoint {
    double x = 0, y = 0, z = 0;  // the block's centre, in the DTM's CRS
    float time = 0, speedMs = 0, energyKj = 0;  // s since release; translation + rotation, kJ
};

// A trajectory thinned for export: the first and last samples, and a sample whenever the block has
// moved >= spacingM (3-D distance) from the last kept one or maxGapS has passed since it (a bounce's
// apex survives at short spacing; a block at rest keeps a point every maxGapS). Empty for no sample.
// std::invalid_argument unless spacingM > 0 and maxGapS > 0.
std::vector<PathPoint> thinPath(const std::vector<dem::TrajectorySample>& samples, double spacingM, double maxGapS);

struct BlockPath {
    long run = 0;
    std::uint64_t seed = 0;
    int releaseColumn = 0, releaseRow = 0;  // 0-based DTM cell, row 0 the northernmost
    dem::StopReason reason = dem::StopReason::TimeLimit;
    double pathLengthM = 0, reachM = 0;
    std::vector<PathPoint> points;
};

struct ImpactPoint {  // a tree hit by a block
    long run = 0;
    long tree = 0;                 // stand::Tree::id
    double x = 0, y = 0, z = 0;    // the tree's foot (z: the DTM's height there)
    double dbhCm = 0, heightAboveFootM = 0;  // where the block hit the stem
    double energyBeforeKj = 0, energyAfterKj = 0, speedBeforeMs = 0;
    bool stemBroken = false, rootYielded = false;
};

// The impacts of one run on the trees of `forest` (TreeImpact::tree is stand::Tree::id), z from
// dtm.elevation.height. std::logic_error for an impact on a tree id the forest does not have: the run
// was simulated with another forest, a programming error, not something a user gave.
std::vector<ImpactPoint> impactPoints(long run, const std::vector<dem::TreeImpact>& impacts, const stand::Forest& forest, const Dtm& dtm);

// Two layers in a GeoPackage, in the DTM's CRS (none if the DTM has none):
//   "paths_<pass>": a LineString25D per path (the block's centre), fields run, seed (decimal text: a
//     seed uses all 64 bits, more than an Integer64 holds), release_col and release_row (counted from
//     1 at the north-west corner, as sylvarock's messages name cells), stop (dem::toString: "rest",
//     "left_domain", ...), path_m, reach_m. A path of fewer than 2 points has no geometry.
//   "impacts_<pass>": a Point25D per impact at the tree's foot, fields run, tree, dbh_cm, height_m
//     (above the foot), energy_before_kj, energy_after_kj, speed_before_m_s, stem_broken, root_yielded
//     (booleans). Written even when empty (a pass without trees).
// The first call creates the file, the next ones add their pass's layers to it. InputError naming the
// file if it cannot be created or opened as a GeoPackage for update, already holds the pass's layers,
// or cannot be written.
void writePathLayers(const std::string& gpkgPath, const Dtm& dtm, const std::string& pass, const std::vector<BlockPath>& paths,
                     const std::vector<ImpactPoint>& impacts);

// Legacy VTK (ASCII) files for ParaView in `dir` (created if missing), coordinates absolute in the
// DTM's CRS, as doubles with 12 significant digits, so that the files overlay each other:
//   terrain.vtk: STRUCTURED_GRID of the DTM's cell centres (columns x rows x 1, from the south-west
//     corner, east then north), POINT_DATA elevation_m;
//   trees.vtk (only for a forest with trees): POLYDATA, a LINE per stem from its foot (the DTM's
//     height) to foot + heightM, CELL_DATA dbh_cm.
// InputError naming the file if one cannot be written, or (from the DTM) a NODATA cell.
void writeVtkScene(const std::string& dir, const Dtm& dtm, const stand::Forest& forest);
// paths_<pass>.vtk in `dir` (created if missing): POLYDATA, a polyline per path of at least 2 points
// (shorter ones are left out: nothing to draw), POINT_DATA speed_m_s, energy_kj, time_s, CELL_DATA run.
void writeVtkPaths(const std::string& dir, const std::string& pass, const std::vector<BlockPath>& paths);

}  // namespace sylva::assess

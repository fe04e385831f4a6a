#pragma once
// `sylvarock hazard` as a library call: N blocks from each release cell of a DTM, through a forest or
// without it, and the hazard rasters on the DTM's own grid (docs/hazard.md).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "libassess/BlockVolumes.hpp"
#include "libassess/StandPolygons.hpp"
#include "libdem/Campaign.hpp"

namespace sylva::assess {

struct HazardOptions {
    std::string dtmPath;       // any raster GDAL reads
    std::string releasePath;   // polygons (GeoJSON, GeoPackage, Shapefile, ...)
    std::string treesPath;     // optional: CSV x,y,dbh_cm (or a forest file), or a point layer with a dbh_cm field
    std::string standsPath;    // optional, instead of treesPath: stand polygons generating their forests (StandPolygons.hpp)
    std::string sceneFile;     // optional: block, contact laws, stems; its terrain is replaced by the DTM
    std::vector<std::string> sceneOverrides;
    dem::Model model = dem::Model::Dem;
    int runsPerCell = 10;
    std::vector<BlockVolumeClass> blockVolumes;  // empty: every block is the scene's
    std::uint64_t seed = 1;
    int threads = 0;
    bool compareBare = false;  // also without the forest, and the forest's protection map
    std::string soilTypesPath, soilMapPath;  // optional, together: the ground's contact parameters by place (SoilMap.hpp)
    std::string checkLinesPath;     // optional: lines whose crossings are tallied (CheckLines.hpp)
    bool writeTrajectories = false; // trajectories.gpkg: each block's path and its tree impacts (BlockPaths.hpp)
    bool writeVtk = false;          // vtk/: the terrain, the stems and the paths for ParaView
    std::string outDir;
    bool resume = false;  // finish the interrupted map in outDir (its hazard.sqlite): the runs it lacks, then every output
    std::function<void(const std::string&)> onNote;
    std::function<void(const std::string& pass, int done, int total)> onRunDone;
};

struct HazardPass {
    std::string name;     // "forest" or "bare"
    long blocks = 0, failed = 0, rest = 0, leftDomain = 0, timeLimit = 0;
    // Of the bare pass: runs not made because their forest run failed, so that both passes count the
    // same blocks (the protection map compares paired runs).
    long leftOutForPairing = 0;
    double pathP50 = 0, pathP90 = 0, reachP50 = 0, reachP90 = 0, reachMax = 0;  // m
    long treeImpacts = 0;
    std::vector<long> blocksPerVolume;  // with HazardOptions::blockVolumes: blocks (not failed) of each class
};

struct HazardResults {
    long releaseCells = 0;
    long trees = 0;
    std::vector<StandPolygon> stands;  // with standsPath; their forest is written to outDir/forest.csv
    std::vector<HazardPass> passes;  // the forest (or the bare slope without trees), then bare with compareBare
    std::vector<std::string> rasters;  // written, relative to outDir
    std::vector<std::string> files;    // the other outputs asked for (check lines, trajectories, vtk/), relative to outDir
    std::string figureWarning;         // why map.svg is missing (no gnuplot), empty if drawn
};

// Writes the rasters, map.svg (HazardFigure.hpp) and summary.json into outDir (which must be new or empty,
// or with `resume` the interrupted map's), keeping every finished run in outDir/hazard.sqlite. InputError
// for unusable inputs (and a resume with other inputs), before any run.
HazardResults runHazard(const HazardOptions& options);

}  // namespace sylva::assess

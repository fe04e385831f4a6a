#include "libassess/HazardRun.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "FolderLock.hpp"
#include "GdalSupport.hpp"
#include "HazardStore.hpp"
#include "RunOutcome.hpp"
#include "libassess/BlockPaths.hpp"
#include "libassess/CheckLines.hpp"
#include "libassess/GeoRaster.hpp"
#include "libassess/Hashing.hpp"
#include "libassess/HazardFigure.hpp"
#include "libassess/HazardMap.hpp"
#include "libassess/ReleaseArea.hpp"
#include "libassess/SoilMap.hpp"
#include "libassess/TreePoints.hpp"
#include "libcommon/BuildId.hpp"
#include "libcommon/InputError.hpp"
#include "libcommon/SeededRandom.hpp"
#include "libcommon/ThreadTeam.hpp"
#include "libdem/BlockMotion.hpp"
#include "libdem/CampaignSummary.hpp"
#include "libdem/LumpedRun.hpp"
#include "libdem/ReleaseInsideStem.hpp"
#include "libdem/SimulationError.hpp"

namespace fs = std::filesystem;

namespace sylva::assess {

namespace {

constexpr float kNoData = -9999;
// A trajectory sample at least this often (a resolution: docs/hazard.md shows the rasters converging
// as it is halved; at 0.01 s the 95th-percentile energies are within 2.5 % of those at 0.005 s).
constexpr double kMaxSampleInterval = 0.01;
// Runs named on stderr when they are left out; the others are counted in summary.json.
constexpr int kMostNotes = 10;
// Every run's trace is kept until the pass ends (~1-5 kB each): a million runs is ~1-5 GB.
constexpr long kMostRuns = 1000000;
// Exported paths keep a point per metre the block moved (about its size) and at least every 0.5 s:
// ~40 B a point, a few hundred points a block, so at most 10^5 runs a pass when they are kept.
constexpr double kPathSpacingM = 1.0, kPathGapS = 0.5;
constexpr long kMostRunsWithPaths = 100000;

// Empty or new: a hazard run never mixes its rasters with someone else's files. Resumed: the map's own
// folder (its path and VTK files are written again whole, once the store accepts the inputs).
void prepareOutDir(const std::string& dir, bool resume) {
    if (dir.empty()) throw InputError("--out DIR is required");
    if (fs::exists(dir) && !fs::is_directory(dir)) throw InputError("--out " + dir + " is a file, not a folder");
    if (resume) {
        if (!fs::is_regular_file(fs::path(dir) / "hazard.sqlite"))
            throw InputError("--resume: " + dir + " holds no map to resume (no hazard.sqlite): give the --out of the interrupted map");
        return;
    }
    if (fs::exists(dir) && !fs::is_empty(dir))
        throw InputError("--out " + dir + " exists and is not an empty folder: use another --out (or --resume an interrupted map)");
    fs::create_directories(dir);
}

std::string hashOf(const std::string& path) { return path.empty() ? "none" : toHex(fileFingerprint(path), 16); }

// A GDAL dataset by what a map reads of it. A raster by its grid, CRS and values: QGIS and gdalinfo
// -stats write statistics into its .aux.xml, which change no value (a resumed map was refused for
// them), while a scale, an offset or a NODATA value given there changes the values read. Vector data
// by the contents of every file it is read from, not only the one named.
std::string datasetHashOf(const std::string& path) {
    if (path.empty()) return "none";
    if (!openVectorUnlessRaster(path)) {
        const GeoRaster raster = readRaster(path, "values");
        const RasterGrid& g = raster.grid;
        std::string bytes = std::to_string(g.columns) + ' ' + std::to_string(g.rows) + '\n' + g.crsWkt + '\n';
        for (const double t : g.geoTransform) bytes += exactText(t) + ' ';
        // Row by row, each value's bytes (every NaN one NaN): a whole DTM's text would take gigabytes
        // and minutes; the raster itself is read a second time, its largest (2.5e8 cells) for 2 GB more.
        std::string row(sizeof(double) * static_cast<std::size_t>(g.columns), '\0');
        for (int r = 0; r < g.rows; ++r) {
            for (int c = 0; c < g.columns; ++c) {
                const double v = raster.values[g.index(c, r)];
                const double canonical = std::isnan(v) ? std::numeric_limits<double>::quiet_NaN() : v;
                std::memcpy(&row[sizeof(double) * static_cast<std::size_t>(c)], &canonical, sizeof(double));
            }
            bytes += toHex(fnv1a64(row), 16);
        }
        return toHex(fnv1a64(bytes), 16);
    }
    std::string hashes;
    for (const std::string& file : datasetFiles(path)) hashes += toHex(fileFingerprint(file), 16);
    return toHex(fnv1a64(hashes), 16);
}

// Everything the maps depend on, a line each, as the store keeps it: a resumed map must be the same
// map. Files by their contents (a moved file is the same input), the forest by its stems: all that a
// run reads of them (a trees file may give heights and crowns instead of the allometry's).
std::vector<std::string> inputsOf(const HazardOptions& o, const stand::Forest& forest) {
    std::string stems;
    for (const auto& t : forest.trees)
        stems += exactText(t.x) + ' ' + exactText(t.y) + ' ' + exactText(t.dbhCm) + ' ' + std::to_string(t.stool.value_or(0)) + ' ' +
                 exactText(t.heightM) + ' ' + exactText(t.crownLengthM) + ' ' + exactText(t.crownMassKg) + '\n';
    std::string volumes;
    for (const auto& v : o.blockVolumes) volumes += exactText(v.volumeM3) + ':' + exactText(v.weight) + ' ';
    std::vector<std::string> lines{"sylvarock hazard store 4",
                                   "dtm " + datasetHashOf(o.dtmPath),
                                   "release " + datasetHashOf(o.releasePath),
                                   "forest " + std::to_string(forest.trees.size()) + " stems " + toHex(fnv1a64(stems), 16),
                                   "scene " + hashOf(o.sceneFile),
                                   "model " + dem::toString(o.model),
                                   "runs per cell " + std::to_string(o.runsPerCell),
                                   "seed " + std::to_string(o.seed),
                                   "block volumes " + volumes,
                                   "soil types " + hashOf(o.soilTypesPath),
                                   "soils " + datasetHashOf(o.soilMapPath),
                                   "check lines " + datasetHashOf(o.checkLinesPath),
                                   std::string("compare bare ") + (o.compareBare ? "yes" : "no"),
                                   std::string("trajectories ") + (o.writeTrajectories || o.writeVtk ? "kept" : "not kept")};
    for (const auto& set : o.sceneOverrides) lines.push_back("set " + set);
    lines.push_back(madeByLine());
    return lines;
}

// What a pass writes besides the rasters, when asked for, and where it keeps its finished runs.
struct PassOutputs {
    const std::vector<CheckLine>* lines = nullptr;  // with checkLines
    CheckLineTally* checkLines = nullptr;
    bool paths = false;           // keep each block's thinned path and its tree impacts
    HazardStore* store = nullptr;  // every finished run, for --resume
};

// `leaveOut`, if not empty, marks runs not to make; `failedRuns`, if given, is set to the runs that
// failed (both sized as the pass's runs).
HazardPass runPass(const std::string& name, const BlockVolumeScenes& blocks, const Dtm& dtm, const std::vector<ReleaseCell>& cells,
                   const HazardOptions& o, HazardMap& map, const PassOutputs& outputs, const std::vector<bool>& leaveOut = {},
                   std::vector<bool>* failedRuns = nullptr) {
    const dem::Scene& scene = blocks.scene(0);
    std::unordered_map<long, Eigen::Vector2d> treeAt;
    for (const auto& t : scene.forest().trees) treeAt[t.id] = {t.x, t.y};
    const long total = static_cast<long>(cells.size()) * o.runsPerCell;
    std::vector<RunOutcome> runs(static_cast<std::size_t>(total));
    // Runs a resumed map finished before: read back, not run again.
    std::vector<long> toRun;
    {
        std::map<long, HazardStore::Finished> done;
        if (outputs.store) done = outputs.store->finished(name);
        for (long i = 0; i < total; ++i) {
            if (!leaveOut.empty() && leaveOut[static_cast<std::size_t>(i)]) continue;
            const auto it = done.find(i);
            if (it == done.end()) {
                toRun.push_back(i);
                continue;
            }
            try {
                runs[i] = it->second.failed ? RunOutcome{} : decode(it->second.record);
            } catch (const std::exception& e) {
                throw InputError(o.outDir + "/hazard.sqlite", 0, name + " run " + std::to_string(i) + " is unreadable (" + e.what() +
                                                                     "): the store is damaged; start the map again in another --out");
            }
            runs[i].failed = it->second.failed;
        }
    }
    std::atomic<long> next{0};
    std::mutex progress;
    int done = 0, notes = 0;
    const double cell = dtm.grid.cellSize();
    const dem::SoilBed& soil = scene.soil();
    const auto note = [&](const std::string& text) {  // under `progress`; the first few only
        if (!o.onNote || ++notes > kMostNotes) return;
        o.onNote(text + (notes == kMostNotes ? " (further runs left out are counted in summary.json, not named)" : ""));
    };
    const long todo = static_cast<long>(toRun.size());
    runOnThreads(threadsFor(o.threads, todo), [&] {
        for (long k; (k = next++) < todo;) {
            const long i = toRun[static_cast<std::size_t>(k)];
            RunOutcome& out = runs[static_cast<std::size_t>(i)];
            const std::uint64_t seed = dem::runSeed(o.seed, static_cast<int>(i));
            // The release point: uniform in the cell, from the run's own stream (as the block's orientation).
            SeededRandom rng(dem::splitmix64(seed));
            const ReleaseCell& from = cells[static_cast<std::size_t>(i / o.runsPerCell)];
            const Eigen::Vector2d centre = dtm.grid.centre(from.column, from.row);
            dem::RunOptions run;
            run.recordTrajectory = true;
            // The terrain spans the DTM's cell centres: a point drawn in an edge cell's outer half is
            // moved onto that edge.
            const auto drawInCell = [&] {
                return Eigen::Vector2d(std::clamp(centre.x() + rng.uniform(-0.5, 0.5) * cell, soil.xmin(), soil.xmax()),
                                       std::clamp(centre.y() + rng.uniform(-0.5, 0.5) * cell, soil.ymin(), soil.ymax()));
            };
            run.releaseAt = drawInCell();
            // Drawn only with several classes: without them the runs are those of a single-volume map.
            if (blocks.classes() > 1) out.volumeClass = blocks.of(rng.uniform(0, 1));
            const dem::Scene& classScene = blocks.scene(out.volumeClass);
            const std::string which = name + " run " + std::to_string(i) + " (seed " + std::to_string(seed) + ", release cell column " +
                                      std::to_string(from.column + 1) + ", row " + std::to_string(from.row + 1) + ")";
            const auto simulate = [&] {
                // Blocks start where the release cell's trees leave room: a point inside a stem is drawn
                // again (left out, the runs starting in dense forest were missing from the map).
                constexpr int kDraws = 20;
                for (int draw = 1;; ++draw) {
                    try {
                        return o.model == dem::Model::Dem ? dem::simulateBlock(classScene, static_cast<int>(i), seed, run)
                                                          : dem::simulateLumped(classScene, static_cast<int>(i), seed, run);
                    } catch (const dem::ReleaseInsideStem&) {
                        if (draw == kDraws)
                            throw InputError(std::to_string(kDraws) + " release points drawn in its cell all start inside a stem: "
                                             "its trees fill the cell");
                        run.releaseAt = drawInCell();
                    }
                }
            };
            try {
                const dem::RunResult r = simulate();
                out.trace = traceRun(r, dtm, treeAt);
                if (outputs.checkLines) out.crossings = crossCheckLines(r.trajectory, dtm, *outputs.lines);
                if (outputs.paths) {
                    BlockPath& p = out.path;
                    p.run = i;
                    p.seed = seed;
                    p.releaseColumn = from.column;
                    p.releaseRow = from.row;
                    p.reason = r.reason;
                    p.pathLengthM = r.runoutAlongSlope;
                    p.reachM = r.runoutHorizontal;
                    p.points = thinPath(r.trajectory, kPathSpacingM, kPathGapS);
                    out.impacts = impactPoints(i, r.impacts, classScene.forest(), dtm);
                }
            } catch (const dem::SimulationError& e) {
                out.failed = true;
                std::lock_guard<std::mutex> lock(progress);
                note(which + " stopped on a numerical error and is left out: " + e.what());
            } catch (const InputError& e) {
                // A block that cannot start where it was drawn (inside a stem, or the ground under a
                // steep cell): that run is left out, not the map.
                out.failed = true;
                std::lock_guard<std::mutex> lock(progress);
                note(which + " could not start and is left out: " + e.what());
            }
            if (outputs.store) outputs.store->save(name, i, out.failed, out.failed ? std::string() : encode(out));
            std::lock_guard<std::mutex> lock(progress);
            ++done;
            if (o.onRunDone) o.onRunDone(name, done, static_cast<int>(todo));
        }
    });
    if (outputs.store) outputs.store->flush();
    HazardPass pass;
    pass.name = name;
    if (!o.blockVolumes.empty()) pass.blocksPerVolume.assign(blocks.classes(), 0);
    if (failedRuns) failedRuns->assign(runs.size(), false);
    std::vector<double> path, reach;
    std::vector<BlockPath> keptPaths;
    std::vector<ImpactPoint> keptImpacts;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        RunOutcome& r = runs[i];
        if (!leaveOut.empty() && leaveOut[i]) {
            ++pass.leftOutForPairing;
            continue;
        }
        if (r.failed) {
            ++pass.failed;
            if (failedRuns) (*failedRuns)[i] = true;
            continue;
        }
        const BlockTrace& t = r.trace;
        map.add(t);
        if (outputs.checkLines) outputs.checkLines->add(name, static_cast<long>(i), r.crossings);
        if (outputs.paths) {
            keptPaths.push_back(std::move(r.path));
            keptImpacts.insert(keptImpacts.end(), r.impacts.begin(), r.impacts.end());
        }
        ++pass.blocks;
        if (!pass.blocksPerVolume.empty()) ++pass.blocksPerVolume[r.volumeClass];
        pass.rest += t.reason == dem::StopReason::Rest;
        pass.leftDomain += t.reason == dem::StopReason::LeftDomain;
        pass.timeLimit += t.reason == dem::StopReason::TimeLimit;
        pass.treeImpacts += static_cast<long>(t.impactCells.size());
        path.push_back(t.pathLengthM);
        reach.push_back(t.reachM);
    }
    // Before any of the pass's outputs: a map made of no block would read as ground no block reaches.
    if (pass.blocks == 0)
        throw std::runtime_error("every one of the " + std::to_string(pass.failed) + " runs of the " + name +
                                 " pass failed (the notes above say why): no map is written");
    if (outputs.checkLines) outputs.checkLines->setBlocks(name, pass.blocks);
    if (outputs.paths) {
        if (o.writeTrajectories) writePathLayers(o.outDir + "/trajectories.gpkg", dtm, name, keptPaths, keptImpacts);
        if (o.writeVtk) writeVtkPaths(o.outDir + "/vtk", name, keptPaths);
    }
    if (!path.empty()) {
        pass.pathP50 = dem::quantile(path, 0.5);
        pass.pathP90 = dem::quantile(path, 0.9);
        pass.reachP50 = dem::quantile(reach, 0.5);
        pass.reachP90 = dem::quantile(reach, 0.9);
        pass.reachMax = *std::max_element(reach.begin(), reach.end());
    }
    return pass;
}

std::vector<std::string> writeRasters(const std::string& dir, const HazardMap& map, const Dtm& dtm, bool forested) {
    fs::create_directories(dir);
    std::vector<std::pair<std::string, std::vector<float>>> rasters{
        {"reach_probability.tif", map.reachProbability()},
        {"passing_count.tif", map.passingCount()},
        {"deposits.tif", map.deposits()},
        {"energy_p95_kj.tif", map.energyP95Kj(kNoData)},
        {"height_p95_m.tif", map.heightP95M(kNoData)}};
    if (forested) rasters.push_back({"tree_impacts.tif", map.treeImpacts()});
    std::vector<std::string> names;
    for (auto& [name, values] : rasters) {
        writeGeoTiff((fs::path(dir) / name).string(), dtm.grid, values, kNoData, name.substr(0, name.size() - 4));
        names.push_back(name);
    }
    return names;
}

nlohmann::ordered_json passJson(const HazardPass& p) {
    return {{"blocks", p.blocks},
            {"failed_runs", p.failed},
            {"left_out_for_pairing", p.leftOutForPairing},
            {"stop_reasons", {{"rest", p.rest}, {"left_domain", p.leftDomain}, {"time_limit", p.timeLimit}}},
            {"path_length_m", {{"p50", p.pathP50}, {"p90", p.pathP90}}},
            {"reach_horizontal_m", {{"p50", p.reachP50}, {"p90", p.reachP90}, {"max", p.reachMax}}},
            {"tree_impacts", p.treeImpacts}};
}

}  // namespace

HazardResults runHazard(const HazardOptions& o) {
    if (o.runsPerCell < 1) throw InputError("--runs-per-cell must be at least 1, got " + std::to_string(o.runsPerCell));
    const Dtm dtm = readDtm(o.dtmPath);
    if (const long holes = dtm.elevation.noDataCells())
        throw InputError(o.dtmPath, 0, "the DTM has " + std::to_string(holes) + " NODATA cell(s); sylvarock hazard builds its soil over the " +
                                           "whole DTM: fill them (gdal_fillnodata.py) or crop the DTM to where it has heights (gdalwarp -te)");
    if (dtm.grid.crsWkt.empty() && o.onNote)
        o.onNote(o.dtmPath + " names no CRS: the release, trees, stands and maps are taken in its coordinates as they are, unchecked");
    // A layer without a CRS beside a DTM with one is taken in the DTM's, as CSV trees are: unchecked.
    if (!dtm.grid.crsWkt.empty() && o.onNote)
        for (const std::string& layer : {o.releasePath, o.checkLinesPath, o.soilMapPath, o.standsPath, o.treesPath})
            if (!layer.empty() && namesNoCrs(layer))
                o.onNote(layer + " names no CRS: taken in the DTM's (" + crsName(dtm.grid.crsWkt) + "), unchecked");
    bool releaseBeyond = false;
    const std::vector<ReleaseCell> cells = readReleaseCells(o.releasePath, dtm, &releaseBeyond);
    if (releaseBeyond && o.onNote)
        o.onNote(o.releasePath + " reaches past the DTM's edges: only its part on the DTM releases blocks (" + std::to_string(cells.size()) +
                 " cells)");
    std::vector<CheckLine> lines;
    if (!o.checkLinesPath.empty()) {
        int others = 0;
        lines = readCheckLines(o.checkLinesPath, dtm, &others);
        if (others > 0 && o.onNote)
            o.onNote(o.checkLinesPath + ": " + std::to_string(others) + " feature(s) beside the lines are not lines (points, polygons) and are passed over");
    }
    const long total = static_cast<long>(cells.size()) * o.runsPerCell;
    if ((o.writeTrajectories || o.writeVtk) && total > kMostRunsWithPaths)
        throw InputError(std::to_string(total) + " runs a pass with " + (o.writeTrajectories ? "--trajectories" : "--vtk") + ": at most " +
                         std::to_string(kMostRunsWithPaths) + " keep their paths in memory: fewer runs per cell, or a smaller release area");
    if (total > kMostRuns)
        throw InputError("--runs-per-cell " + std::to_string(o.runsPerCell) + " on " + std::to_string(cells.size()) + " release cells is " +
                         std::to_string(total) + " runs, more than the " + std::to_string(kMostRuns) +
                         " a pass keeps in memory: fewer runs per cell, or split the release area");
    dem::SceneConfig config = o.sceneFile.empty() ? dem::sceneFromOverrides(o.sceneOverrides) : dem::loadScene(o.sceneFile, o.sceneOverrides);
    if (!config.terrain.profile.empty() || !config.terrain.dtm.empty()) {
        if (o.onNote) o.onNote("the scene's terrain (" + (config.terrain.profile.empty() ? config.terrain.dtm : config.terrain.profile + " and terrain.width_m") +
                               ") is replaced by the DTM " + o.dtmPath);
        config.terrain.profile.clear();
        config.terrain.dtm.clear();
    }
    // The blocks start in the release cells: a release point set in the scene would do nothing unsaid.
    const dem::ReleaseConfig unset;
    const dem::ReleaseConfig& r = config.release;
    if (o.onNote && (r.x != unset.x || r.y != unset.y || r.yRangeGiven || r.forestYMin != unset.forestYMin || r.forestYMax != unset.forestYMax))
        o.onNote("the scene's release point (release.x_m, release.y_m and their ranges) is replaced by the release cells of " + o.releasePath);
    if (!config.forestFile.empty()) throw InputError(o.sceneFile, 0, "the scene places a forest: give the trees with --trees");
    if (config.launch.enabled) throw InputError("a single-tree launch (block.speed_m_s) has no place in a hazard map");
    config.trajectoryInterval = std::min(config.trajectoryInterval, kMaxSampleInterval);
    std::shared_ptr<dem::SoilZones> soils;
    if (o.soilTypesPath.empty() != o.soilMapPath.empty())
        throw InputError(o.soilTypesPath.empty() ? "--soils needs --soil-types (the table of the types it names)"
                                                 : "--soil-types needs --soils (the map placing them)");
    if (!o.soilMapPath.empty()) {
        if (o.model != dem::Model::Dem)
            throw InputError("--soils sets the DEM's block/soil contacts; the lumped model's rebound is calibrated as a whole (docs/lumped.md): "
                             "use --model dem");
        soils = readSoilZones(o.soilMapPath, readSoilTypes(o.soilTypesPath, config.soilContact), dtm, config.soilContact);
    }
    if (!o.treesPath.empty() && !o.standsPath.empty())
        throw InputError("--trees and --stands both give the forest: give one (generate the stands' forest with --stands alone, its trees are "
                         "written to OUT/forest.csv)");
    HazardResults results;
    stand::Forest forest;
    if (!o.treesPath.empty()) forest = readTreePoints(o.treesPath, dtm);
    if (!o.standsPath.empty()) {
        StandForest stands = readStandPolygons(o.standsPath, dtm, o.seed, config.stem.tipDiameter);
        for (const auto& n : stands.notes)
            if (o.onNote) o.onNote(n);
        forest = std::move(stands.forest);
        results.stands = std::move(stands.polygons);
    }
    if (o.compareBare && forest.trees.empty()) throw InputError("--compare-bare compares with a forest: give --trees or --stands");
    // The ground is the same with and without the trees: both passes on the soil map.
    const auto onSoils = [&soils](dem::Scene s) { return soils ? s.withSoilZones(soils) : s; };
    const dem::Scene scene = onSoils(dem::Scene(config, dtm.elevation, std::move(forest)));
    const BlockVolumeScenes blocks(scene, o.blockVolumes);
    // A soil too soft for a block, or a lumped block larger than its fall height, would fail every run
    // of its volume alike: said once, before the output folder is touched.
    for (std::size_t k = 0; k < blocks.classes(); ++k) {
        if (o.model == dem::Model::Dem) dem::BlockMotion::refuseSoilTooSoft(blocks.scene(k));
        else dem::refuseReleaseInsideTheGround(blocks.scene(k));
    }
    prepareOutDir(o.outDir, o.resume);
    const FolderLock lock(o.outDir, "hazard");  // until the last output is written
    const std::string storePath = o.outDir + "/hazard.sqlite";
    const stand::Forest& trees = scene.forest();
    const std::unique_ptr<HazardStore> store =
        o.resume ? HazardStore::resume(storePath, inputsOf(o, trees)) : HazardStore::create(storePath, inputsOf(o, trees));
    if (!store->note().empty() && o.onNote) o.onNote(store->note());
    if (o.resume) {  // the same map: its paths are written again whole (a refused resume leaves them)
        fs::remove(fs::path(o.outDir) / "trajectories.gpkg");
        fs::remove_all(fs::path(o.outDir) / "vtk");
    }
    if (!o.standsPath.empty()) stand::writeForestCsv(o.outDir + "/forest.csv", trees);

    results.releaseCells = static_cast<long>(cells.size());
    results.trees = static_cast<long>(trees.trees.size());
    const bool forested = !trees.trees.empty();
    std::optional<CheckLineTally> tally;
    if (!lines.empty()) tally.emplace(lines);
    PassOutputs outputs;
    outputs.lines = &lines;
    outputs.checkLines = tally ? &*tally : nullptr;
    outputs.paths = o.writeTrajectories || o.writeVtk;
    outputs.store = store.get();
    if (o.writeVtk) writeVtkScene(o.outDir + "/vtk", dtm, scene.forest());
    HazardMap map(dtm.grid);
    std::vector<bool> failedInForest;
    results.passes.push_back(runPass(forested ? "forest" : "bare", blocks, dtm, cells, o, map, outputs, {}, &failedInForest));
    results.rasters = writeRasters(o.outDir, map, dtm, forested);
    const FigureSet figure = drawHazardMap(o.outDir, dtm, map.reachProbability(), scene.forest());
    results.figureWarning = figure.warning;
    for (const auto& f : figure.files) results.files.push_back(f);
    std::vector<float> protection;  // with compareBare
    if (o.compareBare) {
        const dem::Scene bare = onSoils(dem::Scene(config, dtm.elevation));
        HazardMap bareMap(dtm.grid);
        // The blocks whose forest run failed are left out here too: both maps count the same blocks.
        results.passes.push_back(runPass("bare", BlockVolumeScenes(bare, o.blockVolumes), dtm, cells, o, bareMap, outputs, failedInForest));
        for (const auto& name : writeRasters(o.outDir + "/bare", bareMap, dtm, false)) results.rasters.push_back("bare/" + name);
        // What the forest takes off the reach probability: bare minus forest, in [-1, 1].
        protection = bareMap.reachProbability();
        const std::vector<float> withForest = map.reachProbability();
        for (std::size_t i = 0; i < protection.size(); ++i) protection[i] -= withForest[i];
        writeGeoTiff(o.outDir + "/protection.tif", dtm.grid, protection, kNoData, "protection");
        results.rasters.push_back("protection.tif");
    }

    {
        std::vector<RasterPanel> panels{{"reach probability", map.reachProbability()},
                                        {"95th percentile of the energy (kJ)", map.energyP95Kj(kNoData)},
                                        {"95th percentile of the passing height (m)", map.heightP95M(kNoData)},
                                        {"blocks at rest", map.deposits()}};
        if (forested) panels.push_back({"tree impacts", map.treeImpacts()});
        if (!protection.empty()) panels.push_back({"protection: reach probability without minus with the forest", protection, kNoData, true});
        const FigureSet rasterFigure = drawRasterPanels(o.outDir, dtm, panels);
        for (const auto& f : rasterFigure.files) results.files.push_back(f);
        if (!rasterFigure.warning.empty()) results.figureWarning += (results.figureWarning.empty() ? "" : "; ") + rasterFigure.warning;
    }
    if (tally) {
        tally->write(o.outDir);
        results.files.push_back("check_lines.csv");
        results.files.push_back("check_lines_summary.csv");
        const FigureSet lineFigure = drawCheckLines(o.outDir, tally->samples());
        for (const auto& f : lineFigure.files) results.files.push_back(f);
        if (!lineFigure.warning.empty()) results.figureWarning += (results.figureWarning.empty() ? "" : "; ") + lineFigure.warning;
    }
    if (o.writeTrajectories) results.files.push_back("trajectories.gpkg");
    if (o.writeVtk) results.files.push_back("vtk/");

    nlohmann::ordered_json j;
    j["dtm"] = o.dtmPath;
    j["grid"] = {{"columns", dtm.grid.columns}, {"rows", dtm.grid.rows}, {"cell_size_m", dtm.grid.cellSize()}, {"crs", crsName(dtm.grid.crsWkt)}};
    j["release"] = o.releasePath;
    j["release_cells"] = results.releaseCells;
    j["runs_per_cell"] = o.runsPerCell;
    j["model"] = dem::toString(o.model);
    j["seed"] = o.seed;
    j["microtopography_m"] = {{"sd", config.terrain.micro.sigma}, {"correlation_length", config.terrain.micro.lengthM}};
    if (!o.blockVolumes.empty()) {
        j["block_volumes"] = nlohmann::ordered_json::array();
        for (std::size_t k = 0; k < o.blockVolumes.size(); ++k) {
            nlohmann::ordered_json c{{"volume_m3", o.blockVolumes[k].volumeM3}, {"weight", o.blockVolumes[k].weight}};
            for (const auto& p : results.passes) c["blocks"][p.name] = p.blocksPerVolume.at(k);
            j["block_volumes"].push_back(c);
        }
    }
    j["trees"] = results.trees;
    if (soils) {
        j["soil_types"] = o.soilTypesPath;
        j["soil_map"] = o.soilMapPath;
        std::vector<long> cells(soils->names.size(), 0);
        for (const auto z : soils->zone) ++cells[z];
        for (std::size_t k = 0; k < cells.size(); ++k)
            j["soils"].push_back({{"name", soils->names[k]}, {"dtm_cells", cells[k]}, {"kn_n_m", soils->params[k].kn},
                                  {"damping_ratio", soils->params[k].dampingRatio}, {"friction_deg", soils->params[k].frictionDeg}});
    }
    if (!o.standsPath.empty()) {
        j["stands_file"] = o.standsPath;
        j["stands"] = nlohmann::ordered_json::array();
        for (const auto& st : results.stands)
            j["stands"].push_back({{"feature", st.feature},
                                   {"inventory", st.inventory},
                                   {"structure", st.structure == stand::ForestStructure::Aggregated ? "A" : "NA"},
                                   {"area_ha", st.areaHa},
                                   {"stems", st.stems},
                                   {"stems_per_ha", st.areaHa > 0 ? st.stems / st.areaHa : 0.0},
                                   {"seed", std::to_string(st.seed)}});  // 64 bits: a string, as in the GeoPackage (jq and JavaScript round a number this long)
    }
    for (const auto& p : results.passes) j["passes"][p.name] = passJson(p);
    j["rasters"] = results.rasters;
    if (!lines.empty()) {
        j["check_lines_file"] = o.checkLinesPath;
        j["check_lines"] = nlohmann::ordered_json::array();
        for (const auto& l : lines) j["check_lines"].push_back(l.name);
    }
    j["other_files"] = results.files;
    std::ofstream out(o.outDir + "/summary.json");
    out << j.dump(2) << "\n";
    if (!out) throw InputError(o.outDir + "/summary.json", 0, "cannot write");
    return results;
}

}  // namespace sylva::assess

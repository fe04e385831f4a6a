#include "libassess/HazardRun.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>
#include <unordered_map>

#include "libassess/BlockPaths.hpp"
#include "libassess/CheckLines.hpp"
#include "libassess/GeoRaster.hpp"
#include "libassess/HazardFigure.hpp"
#include "libassess/HazardMap.hpp"
#include "libassess/ReleaseArea.hpp"
#include "libassess/SoilMap.hpp"
#include "libassess/TreePoints.hpp"
#include "libcommon/InputError.hpp"
#include "libcommon/SeededRandom.hpp"
#include "libcommon/ThreadTeam.hpp"
#include "libdem/CampaignSummary.hpp"
#include "libdem/LumpedRun.hpp"
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

// Empty or new: a hazard run never mixes its rasters with someone else's files.
void prepareOutDir(const std::string& dir) {
    if (dir.empty()) throw InputError("--out DIR is required");
    if (fs::exists(dir) && (!fs::is_directory(dir) || !fs::is_empty(dir)))
        throw InputError("--out " + dir + " exists and is not an empty folder: use another --out");
    fs::create_directories(dir);
}

// The scene of each block-volume class (the scene itself without classes) and where each class ends
// on [0, 1].
struct BlockClasses {
    std::vector<dem::Scene> resized;       // a scene per class, sharing the soil bed
    std::vector<const dem::Scene*> scenes;
    std::vector<double> upTo;
    BlockClasses(const dem::Scene& scene, const std::vector<BlockVolumeClass>& classes) {
        if (classes.empty()) {
            scenes.push_back(&scene);
            return;
        }
        double total = 0;
        for (const auto& c : classes) total += c.weight;
        double sum = 0;
        for (const auto& c : classes) {
            resized.push_back(scene.withBlockVolume(c.volumeM3));
            upTo.push_back((sum += c.weight) / total);
        }
        upTo.back() = 1;
        for (const auto& r : resized) scenes.push_back(&r);
    }
    // The class of a uniform draw u in [0, 1).
    std::size_t of(double u) const {
        std::size_t k = 0;
        while (k + 1 < upTo.size() && u >= upTo[k]) ++k;
        return k;
    }
};

// What a pass writes besides the rasters, when asked for.
struct PassOutputs {
    const std::vector<CheckLine>* lines = nullptr;  // with checkLines
    CheckLineTally* checkLines = nullptr;
    bool paths = false;  // keep each block's thinned path and its tree impacts
};

HazardPass runPass(const std::string& name, const BlockClasses& blocks, const Dtm& dtm, const std::vector<ReleaseCell>& cells,
                   const HazardOptions& o, HazardMap& map, const PassOutputs& outputs) {
    const dem::Scene& scene = *blocks.scenes.front();
    std::unordered_map<long, Eigen::Vector2d> treeAt;
    for (const auto& t : scene.forest().trees) treeAt[t.id] = {t.x, t.y};
    const long total = static_cast<long>(cells.size()) * o.runsPerCell;
    std::vector<BlockTrace> traces(static_cast<std::size_t>(total));
    std::vector<char> failed(traces.size(), 0);
    std::vector<std::size_t> volumeClass(traces.size(), 0);
    std::vector<std::vector<LineCrossing>> crossings(outputs.checkLines ? traces.size() : 0);
    std::vector<BlockPath> paths(outputs.paths ? traces.size() : 0);
    std::vector<std::vector<ImpactPoint>> impacts(paths.size());
    std::atomic<long> next{0};
    std::mutex progress;
    int done = 0, notes = 0;
    const double cell = dtm.grid.cellSize();
    const dem::SoilBed& soil = scene.soil();
    const auto note = [&](const std::string& text) {  // under `progress`; the first few only
        if (!o.onNote || ++notes > kMostNotes) return;
        o.onNote(text + (notes == kMostNotes ? " (further runs left out are counted in summary.json, not named)" : ""));
    };
    runOnThreads(threadsFor(o.threads, total), [&] {
        for (long i; (i = next++) < total;) {
            const std::uint64_t seed = dem::runSeed(o.seed, static_cast<int>(i));
            // The release point: uniform in the cell, from the run's own stream (as the block's orientation).
            SeededRandom rng(dem::splitmix64(seed));
            const Eigen::Vector2d centre = dtm.grid.centre(cells[i / o.runsPerCell].column, cells[i / o.runsPerCell].row);
            dem::RunOptions run;
            run.recordTrajectory = true;
            // The terrain spans the DTM's cell centres: a point drawn in an edge cell's outer half is
            // moved onto that edge.
            run.releaseAt = Eigen::Vector2d(std::clamp(centre.x() + rng.uniform(-0.5, 0.5) * cell, soil.xmin(), soil.xmax()),
                                            std::clamp(centre.y() + rng.uniform(-0.5, 0.5) * cell, soil.ymin(), soil.ymax()));
            // Drawn only with several classes: without them the runs are those of a single-volume map.
            if (blocks.scenes.size() > 1) volumeClass[i] = blocks.of(rng.uniform(0, 1));
            const dem::Scene& classScene = *blocks.scenes[volumeClass[i]];
            const std::string which = name + " run " + std::to_string(i) + " (seed " + std::to_string(seed) + ", release cell column " +
                                      std::to_string(cells[i / o.runsPerCell].column + 1) + ", row " +
                                      std::to_string(cells[i / o.runsPerCell].row + 1) + ")";
            try {
                const dem::RunResult r = o.model == dem::Model::Dem ? dem::simulateBlock(classScene, static_cast<int>(i), seed, run)
                                                                     : dem::simulateLumped(classScene, static_cast<int>(i), seed, run);
                traces[i] = traceRun(r, dtm, treeAt);
                if (outputs.checkLines) crossings[i] = crossCheckLines(r.trajectory, dtm, *outputs.lines);
                if (outputs.paths) {
                    BlockPath& p = paths[i];
                    p.run = i;
                    p.seed = seed;
                    p.releaseColumn = cells[i / o.runsPerCell].column;
                    p.releaseRow = cells[i / o.runsPerCell].row;
                    p.reason = r.reason;
                    p.pathLengthM = r.runoutAlongSlope;
                    p.reachM = r.runoutHorizontal;
                    p.points = thinPath(r.trajectory, kPathSpacingM, kPathGapS);
                    impacts[i] = impactPoints(i, r.impacts, classScene.forest(), dtm);
                }
            } catch (const dem::SimulationError& e) {
                failed[i] = 1;
                std::lock_guard<std::mutex> lock(progress);
                note(which + " stopped on a numerical error and is left out: " + e.what());
            } catch (const InputError& e) {
                // A block that cannot start where it was drawn (inside a stem, or the ground under a
                // steep cell): that run is left out, not the map.
                failed[i] = 1;
                std::lock_guard<std::mutex> lock(progress);
                note(which + " could not start and is left out: " + e.what());
            }
            std::lock_guard<std::mutex> lock(progress);
            ++done;
            if (o.onRunDone) o.onRunDone(name, done, static_cast<int>(total));
        }
    });
    HazardPass pass;
    pass.name = name;
    if (blocks.scenes.size() > 1) pass.blocksPerVolume.assign(blocks.scenes.size(), 0);
    std::vector<double> path, reach;
    std::vector<BlockPath> keptPaths;
    std::vector<ImpactPoint> keptImpacts;
    for (std::size_t i = 0; i < traces.size(); ++i) {
        if (failed[i]) {
            ++pass.failed;
            continue;
        }
        const BlockTrace& t = traces[i];
        map.add(t);
        if (outputs.checkLines) outputs.checkLines->add(name, static_cast<long>(i), crossings[i]);
        if (outputs.paths) {
            keptPaths.push_back(std::move(paths[i]));
            keptImpacts.insert(keptImpacts.end(), impacts[i].begin(), impacts[i].end());
        }
        ++pass.blocks;
        if (!pass.blocksPerVolume.empty()) ++pass.blocksPerVolume[volumeClass[i]];
        pass.rest += t.reason == dem::StopReason::Rest;
        pass.leftDomain += t.reason == dem::StopReason::LeftDomain;
        pass.timeLimit += t.reason == dem::StopReason::TimeLimit;
        pass.treeImpacts += static_cast<long>(t.impactCells.size());
        path.push_back(t.pathLengthM);
        reach.push_back(t.reachM);
    }
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
            {"stop_reasons", {{"rest", p.rest}, {"left_domain", p.leftDomain}, {"time_limit", p.timeLimit}}},
            {"path_length_m", {{"p50", p.pathP50}, {"p90", p.pathP90}}},
            {"reach_horizontal_m", {{"p50", p.reachP50}, {"p90", p.reachP90}, {"max", p.reachMax}}},
            {"tree_impacts", p.treeImpacts}};
}

}  // namespace

std::vector<BlockVolumeClass> parseBlockVolumes(const std::string& text) {
    std::vector<BlockVolumeClass> classes;
    std::stringstream list(text);
    for (std::string item; std::getline(list, item, ',');) {
        BlockVolumeClass c;
        const auto colon = item.find(':');
        const auto number = [&](const std::string& s, const char* what) {
            std::size_t used = 0;
            double v = std::nan("");
            try {
                v = std::stod(s, &used);
            } catch (const std::exception&) {
            }
            if (used != s.size() || !std::isfinite(v))
                throw InputError("--block-volumes '" + text + "': " + what + " '" + s + "' is not a number (expected V1,V2,... or V1:W1,V2:W2,...)");
            return v;
        };
        c.volumeM3 = number(item.substr(0, colon), "volume");
        if (colon != std::string::npos) c.weight = number(item.substr(colon + 1), "weight");
        if (!(c.volumeM3 > 0 && c.volumeM3 <= 1000))
            throw InputError("--block-volumes '" + text + "': a volume of " + readableNumber(c.volumeM3) + " m3 is not in (0, 1000]");
        if (!(c.weight > 0)) throw InputError("--block-volumes '" + text + "': a weight of " + readableNumber(c.weight) + " is not positive");
        classes.push_back(c);
    }
    if (classes.empty()) throw InputError("--block-volumes: empty list (expected V1,V2,... or V1:W1,V2:W2,...)");
    return classes;
}

HazardResults runHazard(const HazardOptions& o) {
    if (o.runsPerCell < 1) throw InputError("--runs-per-cell must be at least 1, got " + std::to_string(o.runsPerCell));
    const Dtm dtm = readDtm(o.dtmPath);
    if (const long holes = dtm.elevation.noDataCells())
        throw InputError(o.dtmPath, 0, "the DTM has " + std::to_string(holes) + " NODATA cell(s); sylvarock hazard builds its soil over the " +
                                           "whole DTM: fill them (gdal_fillnodata.py) or crop the DTM to where it has heights (gdalwarp -te)");
    const std::vector<ReleaseCell> cells = readReleaseCells(o.releasePath, dtm);
    std::vector<CheckLine> lines;
    if (!o.checkLinesPath.empty()) lines = readCheckLines(o.checkLinesPath, dtm);
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
        if (o.onNote) o.onNote("the scene's terrain (" + (config.terrain.profile.empty() ? config.terrain.dtm : config.terrain.profile) +
                               ") is replaced by the DTM " + o.dtmPath);
        config.terrain.profile.clear();
        config.terrain.dtm.clear();
    }
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
        StandForest stands = readStandPolygons(o.standsPath, dtm, o.seed);
        for (const auto& n : stands.notes)
            if (o.onNote) o.onNote(n);
        forest = std::move(stands.forest);
        results.stands = std::move(stands.polygons);
    }
    if (o.compareBare && forest.trees.empty()) throw InputError("--compare-bare compares with a forest: give --trees or --stands");
    prepareOutDir(o.outDir);
    if (!o.standsPath.empty()) stand::writeForestCsv(o.outDir + "/forest.csv", forest);

    results.releaseCells = static_cast<long>(cells.size());
    results.trees = static_cast<long>(forest.trees.size());
    const bool forested = !forest.trees.empty();
    // The ground is the same with and without the trees: both passes on the soil map.
    const auto onSoils = [&soils](dem::Scene s) { return soils ? s.withSoilZones(soils) : s; };
    const dem::Scene scene = onSoils(dem::Scene(config, dtm.elevation, std::move(forest)));
    std::optional<CheckLineTally> tally;
    if (!lines.empty()) tally.emplace(lines);
    PassOutputs outputs;
    outputs.lines = &lines;
    outputs.checkLines = tally ? &*tally : nullptr;
    outputs.paths = o.writeTrajectories || o.writeVtk;
    if (o.writeVtk) writeVtkScene(o.outDir + "/vtk", dtm, scene.forest());
    HazardMap map(dtm.grid);
    results.passes.push_back(runPass(forested ? "forest" : "bare", BlockClasses(scene, o.blockVolumes), dtm, cells, o, map, outputs));
    results.rasters = writeRasters(o.outDir, map, dtm, forested);
    const FigureSet figure = drawHazardMap(o.outDir, dtm, map.reachProbability(), scene.forest());
    results.figureWarning = figure.warning;
    std::vector<float> protection;  // with compareBare
    if (o.compareBare) {
        const dem::Scene bare = onSoils(dem::Scene(config, dtm.elevation));
        HazardMap bareMap(dtm.grid);
        results.passes.push_back(runPass("bare", BlockClasses(bare, o.blockVolumes), dtm, cells, o, bareMap, outputs));
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
                                   {"seed", st.seed}});
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

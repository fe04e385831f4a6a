// sylvarock hazard: blocks released from every cell of a release area on a DTM, through a forest or
// without it, and the hazard rasters on the DTM's own grid (GeoTIFF; libassess/HazardRun.hpp,
// docs/hazard.md).
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "Cli.hpp"
#include "ProgressBar.hpp"
#include "libassess/HazardRun.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::cli {
namespace {

int runHazardCommand(int argc, const char* const* argv) {
    po::options_description o("hazard");
    std::vector<std::string> sets;
    o.add_options()
        ("dtm", po::value<std::string>(), "the terrain: a raster GDAL reads (GeoTIFF, ESRI ASCII, ...), square cells, north up; its grid and CRS are the rasters'")
        ("release", po::value<std::string>(), "release area: polygons (GeoJSON, GeoPackage, Shapefile, ...) in the DTM's CRS, every DTM cell whose centre is inside releasing "
                    "blocks; or a raster (any grid in the DTM's CRS) whose cells other than 0 and NODATA release the DTM cells centred on them")
        ("runs-per-cell", po::value<int>()->default_value(10), "N: blocks released from each release cell (at a uniform point of the cell, random orientation)")
        ("trees", po::value<std::string>(), "trees: CSV x,y,dbh_cm in the DTM's CRS (or a sylvarock forest file), or a point layer with a dbh_cm field")
        ("stands", po::value<std::string>(), "instead of --trees: stand polygons in the DTM's CRS with fields `stand` (an inventory prefix, e.g. "
                   "../stands/MO1, looked up beside the file, then from here) and `structure` (A or NA); a virtual forest of each stand is drawn "
                   "inside its polygon (seeded by --seed) and written to OUT/forest.csv")
        ("compare-bare", po::bool_switch(), "also run without the trees: rasters in OUT/bare/ and the forest's protection map OUT/protection.tif")
        ("block-volumes", po::value<std::string>(), "a block-volume distribution: V1,V2,... m3 equally likely, or V1:W1,V2:W2,... with weights "
                          "(relative frequencies); each block draws its class; shape from the scene (a cuboid scaled alike); default: the scene's block")
        ("soil-types", po::value<std::string>(), "soil types: a CSV name,code[,kn_n_m,kappa,damping_ratio|restitution,friction_deg] of named "
                       "block/soil contact parameters (the scene's [soil] for those not given); with --soils, DEM only")
        ("soils", po::value<std::string>(), "where the soil types are: polygons with a field `soil` (a type's name) or a raster of their codes, "
                  "in the DTM's CRS; elsewhere the scene's [soil]")
        ("check-lines", po::value<std::string>(), "lines (a line layer in the DTM's CRS, named by a field `name`) where a barrier or a road would go: "
                        "the energy, passing height and speed of each block's first crossing in OUT/check_lines.csv, their distribution per line "
                        "(p50/p95/p99) in OUT/check_lines_summary.csv")
        ("trajectories", po::bool_switch(), "OUT/trajectories.gpkg: each block's path (layer paths_<pass>, a 3-D line) and the trees it hit "
                         "(impacts_<pass>), for a GIS; at most 100 000 runs a pass")
        ("vtk", po::bool_switch(), "OUT/vtk/: the terrain, the stems and the blocks' paths as legacy VTK files for ParaView")
        ("model", po::value<std::string>()->default_value("dem"), "dem (the discrete element model) | lumped (the lumped-mass model, thousands of blocks per second; docs/lumped.md)")
        ("scene", po::value<std::string>(), "scene INI for the block, contact laws and stems (its terrain, if any, is replaced by --dtm); default: the built-in values")
        ("set", po::value(&sets)->composing(), "override a scene key: --set section.key=value (repeatable; sylvarock simulate --help-scene lists them)")
        ("seed", po::value<Seed>()->default_value(Seed{}, "1"), "seed; run i's release point and draws derive from (seed, i)")
        ("resume", po::bool_switch(), "finish an interrupted map in --out (kept run by run in OUT/hazard.sqlite): only the runs it lacks are run, "
                   "the outputs are those of an uninterrupted map; refused if any input differs")
        ("threads", po::value<int>()->default_value(0), "worker threads (0: all cores); results do not depend on it")
        ("out", po::value<std::string>(), "output folder (new or empty): reach_probability.tif, passing_count.tif, deposits.tif, energy_p95_kj.tif, height_p95_m.tif, tree_impacts.tif, "
                "map.png, rasters.png, summary.json, hazard.sqlite (docs/hazard.md lists every output)");
    po::variables_map vm;
    if (!parse(argc, argv, o, vm,
               "sylvarock hazard --dtm DTM --release RELEASE.geojson|RELEASE.tif --runs-per-cell N --out DIR [--trees POINTS | --stands POLYGONS] "
               "[--compare-bare] [--soil-types T.csv --soils MAP] [--check-lines LINES] [--trajectories] [--vtk] [--block-volumes V1:W1,...] [--model dem|lumped] [--seed S] [--threads T] [--resume]",
               "  sylvarock hazard --dtm data/hazard/slope.tif --release data/hazard/release.geojson --stands data/hazard/stands.geojson \\\n"
               "      --check-lines data/hazard/check-lines.geojson --runs-per-cell 5 --compare-bare --seed 1 --out out/hazard\n"
               "  sylvarock hazard ... --trees data/hazard/trees.csv --model lumped --runs-per-cell 100 --block-volumes 0.2:6,1:3,5:1 --trajectories --out out/hz2\n"
               "  gdalinfo -stats out/hazard/reach_probability.tif     (the rasters open in QGIS over the DTM)\n"))
        return 0;
    for (const char* required : {"dtm", "release", "out"})
        if (!vm.count(required)) throw InputError(std::string("--") + required + " is required (sylvarock hazard --help)");
    assess::HazardOptions h;
    h.dtmPath = vm["dtm"].as<std::string>();
    h.releasePath = vm["release"].as<std::string>();
    if (vm.count("trees")) h.treesPath = vm["trees"].as<std::string>();
    if (vm.count("stands")) h.standsPath = vm["stands"].as<std::string>();
    if (vm.count("scene")) h.sceneFile = vm["scene"].as<std::string>();
    h.sceneOverrides = sets;
    h.model = dem::parseModel(vm["model"].as<std::string>());
    h.runsPerCell = vm["runs-per-cell"].as<int>();
    if (vm.count("block-volumes")) h.blockVolumes = assess::parseBlockVolumes(vm["block-volumes"].as<std::string>());
    h.seed = vm["seed"].as<Seed>().value;
    h.threads = threadCount(vm);
    h.compareBare = vm["compare-bare"].as<bool>();
    if (vm.count("soil-types")) h.soilTypesPath = vm["soil-types"].as<std::string>();
    if (vm.count("soils")) h.soilMapPath = vm["soils"].as<std::string>();
    if (vm.count("check-lines")) h.checkLinesPath = vm["check-lines"].as<std::string>();
    h.writeTrajectories = vm["trajectories"].as<bool>();
    h.writeVtk = vm["vtk"].as<bool>();
    h.outDir = vm["out"].as<std::string>();
    h.resume = vm["resume"].as<bool>();
    h.onNote = [](const std::string& text) { std::cerr << "sylvarock hazard: " << text << "\n"; };
    ProgressBar progress(stderrIsTerminal());
    h.onRunDone = [&progress](const std::string& pass, int done, int total) { progress.update(done, total, pass); };

    const auto t0 = std::chrono::steady_clock::now();
    const assess::HazardResults r = assess::runHazard(h);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    long failed = 0;
    std::printf("%ld release cells x %d blocks, %ld trees\n", r.releaseCells, h.runsPerCell, r.trees);
    for (const auto& s : r.stands)
        std::printf("stand %ld (%s, %s): %.2f ha, %ld stems (%.0f /ha)\n", s.feature, s.inventory.c_str(),
                    s.structure == stand::ForestStructure::Aggregated ? "A" : "NA", s.areaHa, s.stems, s.areaHa > 0 ? s.stems / s.areaHa : 0.0);
    for (const auto& p : r.passes) {
        std::printf("%-6s %ld blocks: %ld at rest, %ld left the DTM, %ld at the time limit; path length p50 %.1f m, p90 %.1f m; "
                    "reach p50 %.1f m, max %.1f m; %ld tree impacts\n",
                    p.name.c_str(), p.blocks, p.rest, p.leftDomain, p.timeLimit, p.pathP50, p.pathP90, p.reachP50, p.reachMax, p.treeImpacts);
        if (p.leftOutForPairing > 0)
            std::printf("       %ld blocks left out: their forest run failed (the passes compare the same blocks)\n", p.leftOutForPairing);
        for (std::size_t k = 0; k < p.blocksPerVolume.size(); ++k)
            std::printf("       %ld blocks of %g m3\n", p.blocksPerVolume[k], h.blockVolumes[k].volumeM3);
        failed += p.failed;
    }
    if (!r.figureWarning.empty()) std::cerr << "sylvarock hazard: warning: " << r.figureWarning << "\n";
    std::string others;
    for (const auto& f : r.files) others += ", " + f;
    std::printf("rasters%s and summary.json in %s (%.1f s)\n", others.c_str(), h.outDir.c_str(), wall);
    if (failed) {
        std::cerr << "sylvarock hazard: " << failed
                  << " run(s) could not start or stopped on a numerical error (the notes above say which) and are left out "
                     "of the maps (summary.json failed_runs)\n";
        return kRunsFailed;
    }
    return 0;
}

const CommandRegistration reg{{5, "hazard", "hazard rasters (reach probability, deposits, energy, height) on a DTM from a release area", &runHazardCommand}};

}  // namespace
}  // namespace sylva::cli

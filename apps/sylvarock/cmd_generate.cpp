// sylvarock generate: virtual forests over a slope from a stand's inventory (docs/stand.md, "Virtual forests").
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

#include "Cli.hpp"
#include "libstand/ForestGenerator.hpp"
#include "libstand/InputError.hpp"
#include "libstand/Inventory.hpp"

namespace sylva::cli {
namespace {

// Realisation k of K: "{k}" in the pattern becomes k zero-padded to 3 digits; without "{k}", a single
// realisation is written to the pattern itself and several get "_001", "_002", ... before the extension.
std::string realisationPath(const std::string& pattern, long k, long count) {
    char number[32];
    std::snprintf(number, sizeof number, "%03ld", k);
    const std::string tag = "{k}";
    std::string path = pattern;
    bool tagged = false;
    for (auto at = path.find(tag); at != std::string::npos; at = path.find(tag, at + std::strlen(number))) {
        path.replace(at, tag.size(), number);
        tagged = true;
    }
    if (tagged || count == 1) return path;
    const auto slash = path.find_last_of('/');
    const auto dot = path.find_last_of('.');
    const bool hasExtension = dot != std::string::npos && (slash == std::string::npos || dot > slash + 1);
    const std::string suffix = std::string("_") + number;
    return hasExtension ? path.substr(0, dot) + suffix + path.substr(dot) : path + suffix;
}

stand::Window parseExtent(const std::string& text) {
    const auto v = numberList("extent", text, 4);
    if (!(v[2] > v[0] && v[3] > v[1]))
        throw InputError("--extent: degenerate extent '" + text + "' (expected xmin,ymin,xmax,ymax with xmin < xmax and ymin < ymax)");
    return stand::Window::rectangle(v[0], v[1], v[2], v[3]);
}

int runGenerate(int argc, const char* const* argv) {
    po::options_description options("sylvarock generate");
    options.add_options()
        ("stems", po::value<std::string>()->required(), "inventory stems CSV (plot,stem,x,y,dbh_cm,species,stool)")
        ("plots", po::value<std::string>()->required(), "inventory plots CSV (plot,xmin,ymin,xmax,ymax or plot,wkt)")
        ("structure", po::value<std::string>()->required(),
         "aggregated (A: coppice stools resampled from the inventory, then single trees) or random (NA: uniform stems)")
        ("extent", po::value<std::string>()->required(), "xmin,ymin,xmax,ymax of the forest, in metres")
        ("seed", po::value<Seed>()->default_value(Seed{}, "1"), "seed of the random generator (GSL mt19937), >= 0")
        ("realisations", po::value<long>()->default_value(1), "number of forests K; realisation k uses seed + k - 1")
        ("out", po::value<std::string>()->required(),
         "output CSV; with K > 1 F.csv becomes F_001.csv ... F_K.csv, or put {k} in the name (F_{k}.csv)");
    po::variables_map vm;
    if (!parse(argc, argv, options, vm, "sylvarock generate --stems S.csv --plots P.csv --structure aggregated|random "
                                        "--extent xmin,ymin,xmax,ymax [--seed N] [--realisations K] --out F.csv",
               "  sylvarock generate --stems data/stands/GR1_stems.csv --plots data/stands/GR1_plots.csv \\\n"
               "      --structure aggregated --extent 0,0,500,200 --seed 7 --out GR1_A.csv\n"
               "  sylvarock generate ... --structure random --realisations 10 --out forests/GR1_NA_{k}.csv"))
        return 0;

    stand::GenerationSettings settings;
    settings.structure = stand::parseForestStructure(vm["structure"].as<std::string>());
    const stand::Window extent = parseExtent(vm["extent"].as<std::string>());
    const unsigned long seed = vm["seed"].as<Seed>().value;
    const long count = vm["realisations"].as<long>();
    if (count < 1) throw InputError("--realisations: must be >= 1, got " + std::to_string(count));

    const std::string stemsPath = vm["stems"].as<std::string>();
    const stand::Inventory inventory = stand::readInventory(stemsPath, vm["plots"].as<std::string>());
    for (const auto& w : inventory.warnings) std::cerr << "sylvarock generate: warning: " << w << "\n";
    const stand::StandCatalogue catalogue(inventory, stemsPath);

    for (long k = 1; k <= count; ++k) {
        settings.seed = seed + static_cast<unsigned long>(k - 1);
        const stand::GeneratedForest g = stand::generateForest(catalogue, extent, settings);
        for (const auto& w : g.warnings) std::cerr << "sylvarock generate: warning: " << w << "\n";
        const std::string path = realisationPath(vm["out"].as<std::string>(), k, count);
        stand::writeForestCsv(path, g.forest);
        std::cout << path << ": " << g.forest.trees.size() << " stems (" << g.stemsInStools << " in " << g.stools
                  << " stools), " << toString(settings.structure) << ", seed " << settings.seed << "\n";
    }
    return 0;
}

const CommandRegistration reg{{"generate", "virtual forest (aggregated A or random NA) over an extent from an inventory", &runGenerate}};

}  // namespace
}  // namespace sylva::cli

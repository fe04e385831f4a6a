// sylvarock generate: virtual forests over a slope from a stand's inventory (docs/stand.md, "Virtual forests").
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "Cli.hpp"
#include "Gnuplot.hpp"
#include "PcfFigure.hpp"
#include "libassess/CampaignPlan.hpp"
#include "libcommon/InputError.hpp"
#include "libstand/ForestGenerator.hpp"
#include "libstand/Inventory.hpp"
#include "libstand/PairCorrelation.hpp"
#include "libstand/PairCorrelationEnvelope.hpp"

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

// The virtual forests' g(r) against the inventory's and its CSR envelope, and a map of the first
// forest: does the generator keep the stand's aggregation (A) or remove it (NA)?
void drawForestFigures(const std::string& dir, const stand::Inventory& inventory, const stand::Window& extent,
                       const std::vector<stand::Forest>& forests, const std::string& structure) {
    const std::vector<stand::PlotPoints> plots = stand::plotPoints(inventory);
    const double rmax = stand::defaultPairCorrelationRmax(plots);
    const std::size_t nr = 257;
    const stand::PairCorrelation g = stand::pooledPairCorrelation(plots, rmax, nr);
    const stand::PairCorrelationEnvelope envelope = stand::csrEnvelope(plots, rmax, nr, 39, 1);
    std::vector<NamedPairCorrelation> curves;
    for (std::size_t k = 0; k < forests.size() && k < 4; ++k) {
        stand::PlotPoints whole{extent, {}};
        for (const auto& t : forests[k].trees) whole.points.emplace_back(t.x, t.y);
        stand::PairCorrelation forest = stand::pooledPairCorrelation({whole}, rmax, nr);
        // Past the extent's shortest side no pair of points is that far apart in every direction: g is
        // undefined there (it read 0), and is left out of the figure (NA in its CSV).
        const double shortest = (extent.upper() - extent.lower()).minCoeff();
        for (std::size_t i = 0; i < forest.r.size(); ++i)
            if (forest.r[i] >= shortest) forest.trans[i] = forest.iso[i] = std::nan("");
        curves.push_back({"virtual forest " + structure + " " + std::to_string(k + 1), forest});
    }
    drawPcfFigure(dir, "pcf_vs_inventory", "g(r): virtual forests (" + structure + ") against the inventory " + inventory.name, g,
                  &envelope, curves);
    std::ostringstream gp;
    gp << "set terminal svg size 1000,460 dynamic noenhanced\nset output " << gnuplotText(dir + "/forest_map.svg") << "\n"
       << "set title " << gnuplotText("Virtual forest " + structure + " 1 from " + inventory.name + ": " +
                                       std::to_string(forests.front().trees.size()) + " stems (dot size ~ DBH)")
       << "\nset xlabel 'x (m)'\nset ylabel 'y (m)'\nset size ratio -1\n"
       << "set xrange [" << extent.lower().x() << ":" << extent.upper().x() << "]\nset yrange [" << extent.lower().y() << ":"
       << extent.upper().y() << "]\n$stems << EOD\n";
    for (const auto& t : forests.front().trees) gp << t.x << " " << t.y << " " << t.dbhCm / 40.0 << "\n";  // symbol size ~ DBH
    gp << "EOD\nplot $stems using 1:2:3 with points pt 7 ps variable lc rgb '#2e7d32' notitle\nunset output\n";
    plotWithGnuplot(gp.str(), "forest_map.svg in " + dir);
}

int runGenerate(int argc, const char* const* argv) {
    po::options_description options("sylvarock generate");
    options.add_options()
        ("stems", po::value<std::string>()->required(), "inventory stems CSV (plot,stem,x,y,dbh_cm,species,stool)")
        ("plots", po::value<std::string>()->required(), "inventory plots CSV (plot,xmin,ymin,xmax,ymax or plot,wkt)")
        ("structure", po::value<std::string>()->required(),
         "aggregated (A: coppice stools resampled from the inventory, then single trees) or random (NA: uniform stems)")
        ("extent", po::value<std::string>()->required(), "xmin,ymin,xmax,ymax of the forest, in metres")
        ("seed", po::value<Seed>()->default_value(Seed{}, "1"), "seed of the random generator (GSL mt19937), 0 to 4294967295 (0 is GSL's default seed, 4357)")
        ("realisations", po::value<long>()->default_value(1), "number of forests K; realisation k uses seed + k - 1")
        ("out", po::value<std::string>()->required(),
         "output CSV; with K > 1 F.csv becomes F_001.csv ... F_K.csv, or put {k} in the name (F_{k}.csv)")
        ("plot-dir", po::value<std::string>(),
         "draw there the forests' g(r) against the inventory's with its CSR envelope (pcf_vs_inventory.svg, .csv) and a "
         "map of the first forest (forest_map.svg); needs gnuplot");
    po::variables_map vm;
    if (!parse(argc, argv, options, vm, "sylvarock generate --stems S.csv --plots P.csv --structure aggregated|random "
                                        "--extent xmin,ymin,xmax,ymax [--seed N] [--realisations K] --out F.csv [--plot-dir DIR]",
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
    // GSL's Mersenne twister keeps 32 bits of its seed: beyond them two seeds would draw one forest.
    constexpr unsigned long kLargestSeed = 0xFFFFFFFFUL;
    if (seed > kLargestSeed || static_cast<unsigned long>(count - 1) > kLargestSeed - seed)
        throw InputError("--seed " + std::to_string(seed) + " with --realisations " + std::to_string(count) +
                         ": the forests' seeds (seed, seed + 1, ...) must stay within 0 to 4294967295, the 32 bits GSL's "
                         "Mersenne twister keeps");

    // Before any forest is written: a folder that cannot be made would stop the command after its
    // forests, leaving them as if it had succeeded.
    if (vm.count("plot-dir")) requirePlotDir(vm["plot-dir"].as<std::string>());

    const std::string stemsPath = vm["stems"].as<std::string>();
    const stand::Inventory inventory = stand::readInventory(stemsPath, vm["plots"].as<std::string>());
    for (const auto& w : inventory.warnings) std::cerr << "sylvarock generate: warning: " << w << "\n";
    const stand::StandCatalogue catalogue(inventory, stemsPath);
    std::vector<stand::Forest> drawn;  // kept for the figures

    for (long k = 1; k <= count; ++k) {
        settings.seed = seed + static_cast<unsigned long>(k - 1);
        const stand::GeneratedForest g = stand::generateForest(catalogue, extent, settings);
        // An empty forest would go on into simulate or assess as a forest that stops nothing.
        if (g.forest.trees.empty())
            throw InputError("--extent " + vm["extent"].as<std::string>() + ": " + (g.tooSmall.empty() ? "no stem drawn" : g.tooSmall));
        for (const auto& w : g.warnings) std::cerr << "sylvarock generate: warning: " << w << "\n";
        const std::string path = realisationPath(vm["out"].as<std::string>(), k, count);
        stand::writeForestCsv(path, g.forest);
        std::cout << path << ": " << g.forest.trees.size() << " stems (" << g.stemsInStools << " in " << g.stools
                  << " stools), " << toString(settings.structure) << ", seed " << settings.seed << "\n";
        if (vm.count("plot-dir") && drawn.size() < 4) drawn.push_back(g.forest);
    }
    if (vm.count("plot-dir"))
        drawForestFigures(vm["plot-dir"].as<std::string>(), inventory, extent, drawn,
                          assess::structureCode(settings.structure));
    return 0;
}

const CommandRegistration reg{{2, "generate", "virtual forest (aggregated A or random NA) over an extent from an inventory", &runGenerate}};

}  // namespace
}  // namespace sylva::cli

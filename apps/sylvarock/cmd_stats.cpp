// sylvarock stats: dendrometric and spatial statistics of an inventory or a point pattern
// (docs/stand.md): N, G, DBH, coppice stools, Clark-Evans index and pair correlation g(r).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>

#include "Cli.hpp"
#include "Gnuplot.hpp"
#include "libstand/InputError.hpp"
#include "libstand/Inventory.hpp"
#include "libstand/PairCorrelation.hpp"
#include "libstand/PointPattern.hpp"
#include "libstand/StandStatistics.hpp"
#include "libstand/StatsReport.hpp"

namespace sylva::cli {
namespace {

const char* kPooling = "per-plot estimates averaged with weights n(n-1), the number of ordered pairs";

stand::Inventory readInput(const po::variables_map& vm) {
    const bool inventory = vm.count("stems") || vm.count("plots");
    const bool points = vm.count("points") > 0;
    if (inventory == points)
        throw InputError("give either --stems and --plots (an inventory) or --points with --window or --window-wkt");
    if (inventory) {
        if (!vm.count("stems") || !vm.count("plots")) throw InputError("--stems and --plots go together");
        if (vm.count("window") || vm.count("window-wkt"))
            throw InputError("--window/--window-wkt are for --points; an inventory's windows are in --plots");
        return stand::readInventory(vm["stems"].as<std::string>(), vm["plots"].as<std::string>());
    }
    if (vm.count("window") == vm.count("window-wkt"))
        throw InputError("--points needs exactly one of --window xmin,ymin,xmax,ymax and --window-wkt 'POLYGON((...))'");
    std::optional<stand::Window> window;
    try {
        if (vm.count("window")) {
            const auto v = numberList("window", vm["window"].as<std::string>(), 4);
            window = stand::Window::rectangle(v[0], v[1], v[2], v[3]);
        } else {
            window = stand::Window::fromWkt(vm["window-wkt"].as<std::string>());
        }
        window->requirePlotSize();
    } catch (const InputError& e) {
        throw InputError(std::string(vm.count("window") ? "--window: " : "--window-wkt: ") + e.what());
    }
    return stand::readPointPattern(vm["points"].as<std::string>(), *window);
}

// g(r) of each plot on one r grid, pooled (a single pattern is its own pool).
stand::PairCorrelation stemPairCorrelation(const stand::Inventory& inv, const po::variables_map& vm) {
    std::map<std::string, std::vector<Eigen::Vector2d>> byPlot;
    for (const auto& s : inv.stems) byPlot[s.plot].emplace_back(s.x, s.y);
    double rmax = std::numeric_limits<double>::infinity();
    if (vm.count("pcf-rmax")) {
        rmax = vm["pcf-rmax"].as<double>();
        if (!(rmax > 0)) throw InputError("--pcf-rmax: must be > 0");
    } else {
        for (const auto& p : inv.plots)
            rmax = std::min(rmax, stand::defaultPairCorrelationRmax(p.window, byPlot[p.id].size()));
    }
    const long nr = vm["pcf-nr"].as<long>();
    if (nr < 2) throw InputError("--pcf-nr: need at least 2 values of r");
    stand::PairCorrelationOptions options;
    if (vm.count("pcf-exact")) options.kernelSum = stand::KernelSum::Exact;
    std::vector<stand::PairCorrelation> estimates;
    std::vector<double> weights;
    for (const auto& p : inv.plots) {
        const auto& xy = byPlot[p.id];
        estimates.push_back(stand::pairCorrelation(xy, p.window, rmax, static_cast<std::size_t>(nr), options));
        weights.push_back(static_cast<double>(xy.size()) * (static_cast<double>(xy.size()) - 1));
    }
    return stand::poolPairCorrelations(estimates, weights);
}

std::string csvNumber(double v) {
    if (std::isnan(v)) return "NA";
    if (std::isinf(v)) return v > 0 ? "Inf" : "-Inf";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

void writePcfCsv(const std::string& path, const stand::PairCorrelation& g) {
    std::ofstream out(path);
    if (!out) throw InputError(path, 0, "cannot write the pair correlation file");
    out << "r,g_trans,g_iso\n";
    for (std::size_t i = 0; i < g.r.size(); ++i)
        out << csvNumber(g.r[i]) << "," << csvNumber(g.trans[i]) << "," << csvNumber(g.iso[i]) << "\n";
    if (!out) throw InputError(path, 0, "error while writing");
}

void drawFigures(const std::string& dir, const stand::Inventory& inv, const stand::PairCorrelation& g) {
    // gnuplot, unable to open its output, would print the SVG on the terminal instead.
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir)) throw InputError(dir, 0, "cannot create the --plot-dir directory");
    std::ostringstream gp;
    gp << "set terminal svg size 800,500 dynamic\nset grid\n$pcf << EOD\n";
    for (std::size_t i = 1; i < g.r.size(); ++i)  // g is undefined at r = 0
        gp << csvNumber(g.r[i]) << " " << csvNumber(g.trans[i]) << " " << csvNumber(g.iso[i]) << "\n";
    gp << "EOD\nset output '" << dir << "/pcf.svg'\nset title 'Pair correlation function, " << inv.name
       << "'\nset xlabel 'r (m)'\nset ylabel 'g(r)'\nset datafile missing 'NA'\n"
          "plot $pcf using 1:2 with lines title 'translation', $pcf using 1:3 with lines title 'Ripley isotropic', "
          "1 with lines dashtype 2 title 'Poisson'\n";
    if (inv.hasDiameters && !inv.stems.empty()) {
        gp << "$dbh << EOD\n";
        for (const auto& s : inv.stems)
            if (stand::measured(s)) gp << s.dbhCm << "\n";
        gp << "EOD\nset output '" << dir << "/dbh_histogram.svg'\nset title 'DBH distribution, " << inv.name
           << " (" << std::count_if(inv.stems.begin(), inv.stems.end(), stand::measured) << " measured stems)'\nset xlabel 'DBH (cm)'\nset ylabel 'stems'\nset style fill solid 0.5\n"
              "bin(x) = 2.5 * floor(x / 2.5) + 1.25\n"
              "plot $dbh using (bin($1)):(1) smooth frequency with boxes title '2.5 cm classes'\n";
    }
    gp << "unset output\n";
    plotWithGnuplot(gp.str(), "stats figures in " + dir);
}

int runStats(int argc, const char* const* argv) {
    po::options_description options("sylvarock stats");
    options.add_options()
        ("stems", po::value<std::string>(), "inventory stems CSV (plot,stem,x,y,dbh_cm,species,stool)")
        ("plots", po::value<std::string>(), "inventory plots CSV (plot,xmin,ymin,xmax,ymax or plot,wkt)")
        ("points", po::value<std::string>(), "a point pattern CSV (x,y[,dbh_cm][,stool]), e.g. a generated forest")
        ("window", po::value<std::string>(), "the pattern's rectangle xmin,ymin,xmax,ymax (with --points)")
        ("window-wkt", po::value<std::string>(), "the pattern's polygon 'POLYGON((x y, ...))' (with --points)")
        ("json", po::bool_switch(), "print JSON instead of the table")
        ("pcf-out", po::value<std::string>(),
         "write g(r) as CSV r,g_trans,g_iso (an inventory's: per-plot estimates averaged with weights n(n-1))")
        ("pcf-rmax", po::value<double>(), "largest r of g(r), m (default: spatstat's rule, a quarter of the "
                                          "shortest plot side or less)")
        ("pcf-nr", po::value<long>()->default_value(513), "number of r values from 0 to rmax")
        ("pcf-exact", "evaluate the kernel sums of g(r) exactly instead of as spatstat (R's binned density)")
        ("plot-dir", po::value<std::string>(), "draw pcf.svg and dbh_histogram.svg there (needs gnuplot)");
    po::variables_map vm;
    if (!parse(argc, argv, options, vm,
               "sylvarock stats (--stems S.csv --plots P.csv | --points X.csv (--window xmin,ymin,xmax,ymax | "
               "--window-wkt WKT)) [--json] [--pcf-out G.csv] [--plot-dir DIR]",
               "  sylvarock stats --stems data/stands/GR1_stems.csv --plots data/stands/GR1_plots.csv\n"
               "  sylvarock stats --points GR1_A.csv --window 0,0,500,200 --json --pcf-out GR1_A_pcf.csv\n"
               "  sylvarock stats --points trees.csv --window-wkt 'POLYGON((0 0, 80 0, 80 30, 30 60, 0 60, 0 0))'"))
        return 0;

    const stand::Inventory inv = readInput(vm);
    for (const auto& w : inv.warnings) std::cerr << "sylvarock stats: warning: " << w << "\n";
    const stand::StandStatistics stats = stand::standStatistics(inv);

    std::optional<stand::PcfReport> pcfReport;
    if (vm.count("pcf-out") || vm.count("plot-dir")) {
        const stand::PairCorrelation g = stemPairCorrelation(inv, vm);
        if (vm.count("pcf-out")) {
            writePcfCsv(vm["pcf-out"].as<std::string>(), g);
            pcfReport = stand::PcfReport{vm["pcf-out"].as<std::string>(), g.r.back(), g.r.size(),
                                         inv.plots.size() == 1 ? "a single pattern" : kPooling};
        }
        if (vm.count("plot-dir")) drawFigures(vm["plot-dir"].as<std::string>(), inv, g);
    }
    std::cout << (vm["json"].as<bool>() ? stand::statsJson(stats, inv.warnings, pcfReport)
                                        : stand::statsTable(stats, inv.warnings, pcfReport));
    return 0;
}

const CommandRegistration reg{
    {"stats", "stand statistics (N, G, DBH, stools, Clark-Evans, g(r)) of an inventory or a pattern", &runStats}};

}  // namespace
}  // namespace sylva::cli

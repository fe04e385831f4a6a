// sylvarock stats: dendrometric and spatial statistics of an inventory or a point pattern
// (docs/stand.md): N, G, DBH, coppice stools, Clark-Evans index and pair correlation g(r).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>

#include "Cli.hpp"
#include "Gnuplot.hpp"
#include "PcfFigure.hpp"
#include "libcommon/InputError.hpp"
#include "libstand/Inventory.hpp"
#include "libstand/PairCorrelation.hpp"
#include "libstand/PairCorrelationEnvelope.hpp"
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
    // numberList names the option itself; the window's own complaints do not.
    const std::vector<double> corners = vm.count("window") ? numberList("window", vm["window"].as<std::string>(), 4) : std::vector<double>{};
    try {
        if (vm.count("window")) {
            window = stand::Window::rectangle(corners[0], corners[1], corners[2], corners[3]);
        } else {
            window = stand::Window::fromWkt(vm["window-wkt"].as<std::string>());
        }
        window->requirePlotSize();
    } catch (const InputError& e) {
        throw InputError(std::string(vm.count("window") ? "--window: " : "--window-wkt: ") + e.what());
    }
    return stand::readPointPattern(vm["points"].as<std::string>(), *window);
}

// g(r) of each plot on one r grid, pooled (a single pattern is its own pool), and the options it
// was computed with (the CSR envelope uses the same).
struct StandPcf {
    std::vector<stand::PlotPoints> plots;
    double rmax = 0;
    std::size_t nr = 0;
    stand::PairCorrelationOptions options;
    stand::PairCorrelation g;
};

StandPcf standPairCorrelation(const stand::Inventory& inv, const po::variables_map& vm) {
    StandPcf s;
    s.plots = stand::plotPoints(inv);
    s.rmax = vm.count("pcf-rmax") ? vm["pcf-rmax"].as<double>() : stand::defaultPairCorrelationRmax(s.plots);
    if (!(s.rmax > 0)) throw InputError("--pcf-rmax: must be > 0");
    // Past a plot's shortest side some directions hold no pair of it, and the edge corrections
    // divide by a window overlap of zero: g(r) read 0 there, as if no stems stood so far apart.
    // A plot without a pair of stems adds nothing to g(r), at any r.
    for (std::size_t i = 0; i < s.plots.size(); ++i) {
        if (!stand::holdsAPair(s.plots[i])) continue;
        const Eigen::Vector2d frame = s.plots[i].window.upper() - s.plots[i].window.lower();
        if (s.rmax >= frame.minCoeff()) {
            std::ostringstream os;
            os << "--pcf-rmax " << s.rmax << " m reaches past the " << frame.minCoeff() << " m shortest side of "
               << (s.plots.size() == 1 ? "the window" : "plot " + inv.plots[i].id)
               << ", where g(r) is undefined (no pair in some directions): give less (spatstat's rule, the default here, is "
               << stand::defaultPairCorrelationRmax(s.plots) << " m)";
            throw InputError(os.str());
        }
    }
    const long nr = vm["pcf-nr"].as<long>();
    // Each value of r holds a few numbers per estimator: a million is far finer than any plot resolves.
    if (nr < 2 || nr > 1000000) throw InputError("--pcf-nr " + std::to_string(nr) + ": give 2 to 1 000 000 values of r");
    s.nr = static_cast<std::size_t>(nr);
    if (vm.count("pcf-exact")) s.options.kernelSum = stand::KernelSum::Exact;
    s.g = stand::pooledPairCorrelation(s.plots, s.rmax, s.nr, s.options);
    return s;
}

void writePcfCsv(const std::string& path, const stand::PairCorrelation& g) {
    std::ofstream out(path);
    if (!out) throw sylva::cannotWrite(path);
    out << "r,g_trans,g_iso\n";
    for (std::size_t i = 0; i < g.r.size(); ++i)
        out << csvNumber(g.r[i]) << "," << csvNumber(g.trans[i]) << "," << csvNumber(g.iso[i]) << "\n";
    if (!out) throw InputError(path, 0, "error while writing");
}

void drawFigures(const std::string& dir, const stand::Inventory& inv, const StandPcf& pcf, int simulations) {
    requirePlotDir(dir);
    std::optional<stand::PairCorrelationEnvelope> envelope;  // seeded: the same figure every time
    if (simulations > 0) envelope = stand::csrEnvelope(pcf.plots, pcf.rmax, pcf.nr, simulations, 1, pcf.options);
    drawPcfFigure(dir, "pcf", "Pair correlation function, " + inv.name, pcf.g, envelope ? &*envelope : nullptr);
    if (!inv.hasDiameters || inv.stems.empty()) return;
    std::ostringstream gp;
    gp << "set terminal svg size 800,500 dynamic noenhanced\nset grid\n$dbh << EOD\n";
    for (const auto& s : inv.stems)
        if (stand::measured(s)) gp << s.dbhCm << "\n";
    const auto measured = std::count_if(inv.stems.begin(), inv.stems.end(), stand::measured);
    gp << "EOD\nset output " << gnuplotText(dir + "/dbh_histogram.svg") << "\nset title "
       << gnuplotText("DBH distribution, " + inv.name + " (" + std::to_string(measured) + " measured stems)")
       << "\nset xlabel 'DBH (cm)'\nset ylabel 'stems'\nset style fill solid 0.5\n"
          "bin(x) = 2.5 * floor(x / 2.5) + 1.25\n"
          "plot $dbh using (bin($1)):(1) smooth frequency with boxes title '2.5 cm classes'\nunset output\n";
    plotWithGnuplot(gp.str(), "dbh_histogram.svg in " + dir);
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
                                          "shortest plot side or less; refused from the shortest side on, where g(r) is undefined)")
        ("pcf-nr", po::value<long>()->default_value(513), "number of r values from 0 to rmax")
        ("pcf-exact", "evaluate the kernel sums of g(r) exactly instead of as spatstat (R's binned density)")
        ("plot-dir", po::value<std::string>(),
         "draw pcf.svg (g(r) with its CSR envelope; data in pcf.csv) and dbh_histogram.svg there (needs gnuplot)")
        ("envelope", po::value<int>()->default_value(39),
         "simulations of complete spatial randomness for the envelope of g(r) in --plot-dir (each plot's own number of "
         "stems in its own window; 39: pointwise 5 % test, as spatstat's envelope(); 0: none)");
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
    if (vm["envelope"].as<int>() < 0 || vm["envelope"].as<int>() > 9999)
        throw InputError("--envelope " + std::to_string(vm["envelope"].as<int>()) +
                         ": a number of simulations from 0 (none) to 9999 (39 gives spatstat's pointwise 5 % test)");
    if (vm.count("pcf-out") || vm.count("plot-dir")) {
        const StandPcf pcf = standPairCorrelation(inv, vm);
        if (vm.count("pcf-out")) {
            writePcfCsv(vm["pcf-out"].as<std::string>(), pcf.g);
            pcfReport = stand::PcfReport{vm["pcf-out"].as<std::string>(), pcf.g.r.back(), pcf.g.r.size(),
                                         inv.plots.size() == 1 ? "a single pattern" : kPooling};
        }
        if (vm.count("plot-dir")) drawFigures(vm["plot-dir"].as<std::string>(), inv, pcf, vm["envelope"].as<int>());
    }
    std::cout << (vm["json"].as<bool>() ? stand::statsJson(stats, inv.warnings, pcfReport)
                                        : stand::statsTable(stats, inv.warnings, pcfReport));
    return 0;
}

const CommandRegistration reg{
    {1, "stats", "stand statistics (N, G, DBH, stools, Clark-Evans, g(r)) of an inventory or a pattern", &runStats}};

}  // namespace
}  // namespace sylva::cli

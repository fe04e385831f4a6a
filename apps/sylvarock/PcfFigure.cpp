#include "PcfFigure.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "Gnuplot.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::cli {

std::string csvNumber(double v) {
    if (std::isnan(v)) return "NA";
    if (std::isinf(v)) return v > 0 ? "Inf" : "-Inf";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

void requirePlotDir(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir)) throw InputError(dir, 0, "cannot create the --plot-dir directory");
}

void drawPcfFigure(const std::string& dir, const std::string& stem, const std::string& title, const stand::PairCorrelation& g,
                   const stand::PairCorrelationEnvelope* envelope, const std::vector<NamedPairCorrelation>& forests) {
    std::ostringstream table;
    table << "r,g_trans,g_iso";
    if (envelope) table << ",csr_trans_low,csr_trans_high";
    for (std::size_t f = 0; f < forests.size(); ++f) table << ",forest" << f + 1 << "_g_trans";
    table << "\n";
    for (std::size_t i = 1; i < g.r.size(); ++i) {  // g is undefined at r = 0
        table << csvNumber(g.r[i]) << "," << csvNumber(g.trans[i]) << "," << csvNumber(g.iso[i]);
        if (envelope) table << "," << csvNumber(envelope->transLow.at(i)) << "," << csvNumber(envelope->transHigh.at(i));
        for (const auto& f : forests) table << "," << csvNumber(f.g.trans.at(i));
        table << "\n";
    }
    const std::string csv = dir + "/" + stem + ".csv";
    std::ofstream(csv) << table.str();
    if (!std::ifstream(csv)) throw InputError(csv, 0, "cannot write the figure's data");

    std::ostringstream gp;
    gp << "set terminal svg size 800,500 dynamic noenhanced\nset grid\nset datafile separator ','\nset datafile missing 'NA'\n"
       << "set datafile columnheaders\nset output " << gnuplotText(dir + "/" + stem + ".svg") << "\nset title " << gnuplotText(title)
       << "\nset xlabel 'r (m)'\nset ylabel 'g(r), log scale'\nset logscale y\nset key top right\nplot ";
    // Log scale: a coppice stand's g reaches 20-40 at stool distances and ~1 beyond; zeros (no pair
    // at that r) fall off the plot.
    if (envelope) {
        char level[32];
        std::snprintf(level, sizeof level, "%.0f %%", 100 * envelope->level());
        gp << gnuplotText(csv) << " using 1:4:5 with filledcurves fc rgb '#d8d8d8' title 'complete spatial randomness, "
           << envelope->simulations << " simulations (pointwise " << level << ")', ";
    }
    gp << gnuplotText(csv) << " using 1:2 with lines lw 2 lc rgb 'black' title 'stand (translation)', "
       << "'' using 1:3 with lines lc rgb '#777777' dashtype 2 title 'stand (Ripley isotropic)', "
       << "1 with lines lc rgb '#999999' dashtype 3 title 'Poisson'";
    const char* colours[] = {"#1b9e77", "#d95f02", "#7570b3", "#e7298a"};
    const std::size_t first = envelope ? 6 : 4;
    for (std::size_t f = 0; f < forests.size(); ++f)
        gp << ", '' using 1:" << first + f << " with lines lc rgb '" << colours[f % 4] << "' title " << gnuplotText(forests[f].name);
    gp << "\nunset output\n";
    plotWithGnuplot(gp.str(), stem + ".svg in " + dir);
}

}  // namespace sylva::cli

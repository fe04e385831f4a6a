#include "libassess/Figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "libassess/CampaignPlan.hpp"
#include "libcommon/InputError.hpp"

namespace fs = std::filesystem;

namespace sylva::assess {

namespace {

// A gnuplot single-quoted string: a quote inside is doubled.
std::string quoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

// A shell single-quoted word.
std::string shellQuoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::ofstream openData(const std::string& path) {
    std::ofstream out(path, std::ios::trunc);
    if (!out) throw sylva::cannotWrite(path);
    out.precision(10);
    return out;
}

// Cumulative share of blocks stopped against run-out: each stop raises the curve by 1/n.
void writeCdf(const std::string& path, std::vector<double> runout) {
    std::sort(runout.begin(), runout.end());
    auto out = openData(path);
    out << "runout_m,share_stopped\n";
    for (std::size_t i = 0; i < runout.size(); ++i) out << runout[i] << ',' << (i + 1.0) / runout.size() << '\n';
}

std::vector<double> pooledRunout(const StructureAssessment& row) {
    std::vector<double> v;
    for (const auto& runs : row.runs)
        for (const auto& r : runs) v.push_back(r.runoutM);
    return v;
}

std::string cdfFile(const StructureAssessment& row) { return "data/cdf_" + row.name + "_" + structureCode(row.structure) + ".csv"; }

// Fig. 12's axes: the column of data/pf50_*.csv, the label, and the inventory's value it holds.
struct DendrometryAxis {
    const char* column;
    const char* label;
    double ForestSummary::*value;
};
const DendrometryAxis kDendrometry[] = {{"6", "G (m²/ha)", &ForestSummary::basalAreaM2Ha},
                                        {"7", "Mean D (cm)", &ForestSummary::meanDbhCm},
                                        {"8", "N (stems/ha)", &ForestSummary::stemsPerHa}};

// The axis's range over the stands: gnuplot's own, unless every stand has the same value (one stand),
// where gnuplot widens the empty range itself but prints a warning with each figure.
std::string xRange(const AssessmentResults& results, const DendrometryAxis& axis) {
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& row : results.stands) lo = std::min(lo, row.inventory.*axis.value), hi = std::max(hi, row.inventory.*axis.value);
    if (!(hi == lo)) return "set autoscale x\n";
    const double pad = lo != 0 ? 0.1 * std::abs(lo) : 1;
    std::ostringstream os;
    os << "set xrange [" << lo - pad << ':' << lo + pad << "]\n";
    return os.str();
}

std::vector<std::string> standNames(const AssessmentResults& results) {
    std::vector<std::string> names;
    for (const auto& row : results.stands)
        if (std::find(names.begin(), names.end(), row.name) == names.end()) names.push_back(row.name);
    return names;
}

void writeData(const std::string& dir, const AssessmentResults& results) {
    fs::create_directories(dir + "/data");
    std::vector<double> baseline;
    for (const auto& r : results.baseline) baseline.push_back(r.runoutM);
    writeCdf(dir + "/data/cdf_baseline.csv", baseline);
    const auto names = standNames(results);
    for (auto structure : assessedStructures()) {
        const std::string code = structureCode(structure);
        auto pf = openData(dir + "/data/pf50_" + code + ".csv");
        pf << "index,stand,pf50,pf50_low,pf50_high,basal_area_m2_ha,mean_dbh_cm,stems_per_ha\n";
        auto stops = openData(dir + "/data/stops_" + code + ".csv");
        stops << "stand,realisation,run,x_m,y_m\n";
        for (const auto& row : results.stands) {
            if (row.structure != structure) continue;
            writeCdf(dir + "/" + cdfFile(row), pooledRunout(row));
            const auto index = std::find(names.begin(), names.end(), row.name) - names.begin();
            pf << index << ',' << row.name << ',' << row.pf50 << ',' << row.pf50Ci.low << ',' << row.pf50Ci.high << ','
               << row.inventory.basalAreaM2Ha << ',' << row.inventory.meanDbhCm << ',' << row.inventory.stemsPerHa << '\n';
            for (std::size_t k = 0; k < row.runs.size(); ++k)
                for (const auto& r : row.runs[k]) stops << row.name << ',' << k + 1 << ',' << r.run << ',' << r.stopX << ',' << r.stopY << '\n';
        }
    }
    auto stops = openData(dir + "/data/stops_baseline.csv");
    stops << "stand,realisation,run,x_m,y_m\n";
    for (const auto& r : results.baseline) stops << "baseline,0," << r.run << ',' << r.stopX << ',' << r.stopY << '\n';
}

std::string script(const AssessmentResults& results) {
    const auto names = standNames(results);
    const int n = static_cast<int>(names.size());
    const int cols = std::min(n, 2), rows = (n + 1) / 2;
    std::ostringstream gp;
    gp << "# Figures of sylvarock assess; run `gnuplot figures.gp` in this folder to redraw them.\n"
       << "set datafile separator ','\nset grid\nset key bottom right\n"
       << "A = '#c0392b'; NA = '#2471a3'; BASE = '#000000'\n\n";

    gp << "# Figs. 9-10: cumulative run-out with and without forest, A against NA, one panel per stand\n"
       << "set terminal svg size " << 520 * cols << ',' << 380 * rows << " dynamic noenhanced font 'sans,11'\n"
       << "set output 'runout_cdf.svg'\nset multiplot layout " << rows << ',' << cols
       << " title 'Cumulative distribution of run-out along the slope'\n"
       << "set xlabel 'run-out along the slope (m)'\nset ylabel 'share of blocks stopped'\nset yrange [0:1]\n";
    for (const auto& name : names) {
        gp << "set title " << quoted(name) << "\nplot 'data/cdf_baseline.csv' every ::1 using 1:2 with steps lw 2 lc rgb BASE title 'no forest'";
        for (const auto& row : results.stands)
            if (row.name == name)
                gp << ", \\\n     " << quoted(cdfFile(row)) << " every ::1 using 1:2 with steps lw 2 lc rgb "
                   << structureCode(row.structure) << " title " << quoted(structureCode(row.structure));
        gp << "\n";
    }
    gp << "unset multiplot\nset autoscale y\n\n";

    gp << "# Fig. 11: PF50 per stand with its bootstrap interval\n"
       << "set terminal svg size " << std::max(500, 110 * n + 200) << ",420 dynamic noenhanced font 'sans,11'\nset output 'pf50.svg'\n"
       << "set title 'Protection index PF50 (Eq. 26) with " << confidencePercent(results.bootstrap.confidence)
       << " % bootstrap interval'\nset xlabel 'stand'\nset ylabel 'PF50'\nset xrange [-0.6:" << n - 0.4 << "]\nset key top right\n"
       << "plot 'data/pf50_A.csv' every ::1 using ($1-0.12):3:4:5:xtic(2) with yerrorbars pt 7 lc rgb A title 'A (aggregated)', \\\n"
       << "     'data/pf50_NA.csv' every ::1 using ($1+0.12):3:4:5 with yerrorbars pt 5 lc rgb NA title 'NA (random)'\n"
       << "set autoscale x\nset xtics autofreq\n\n";

    gp << "# Fig. 12: PF50 against the inventory's basal area, mean diameter and stem density\n"
       << "set terminal svg size 1200,400 dynamic noenhanced font 'sans,11'\nset output 'pf50_dendrometry.svg'\n"
       << "set multiplot layout 1,3 title 'PF50 against the stands'' dendrometry'\nunset title\nset ylabel 'PF50'\n";
    for (const auto& axis : kDendrometry)
        gp << "set xlabel '" << axis.label << "'\n" << xRange(results, axis) << "plot 'data/pf50_A.csv' every ::1 using " << axis.column
           << ":3:4:5 with yerrorbars pt 7 lc rgb A title 'A', \\\n     'data/pf50_NA.csv' every ::1 using " << axis.column
           << ":3:4:5 with yerrorbars pt 5 lc rgb NA title 'NA'\n";
    gp << "unset multiplot\nset autoscale x\n\n";

    gp << "# Fig. 8: where the blocks stopped (all stands pooled per structure); the forest starts at the dashed line\n"
       << "set terminal svg size 1000,420 dynamic noenhanced font 'sans,11'\nset output 'stop_map.svg'\nset title 'Stop positions'\n"
       << "set xlabel 'x (m)'\nset ylabel 'y (m)'\nset xrange [" << results.terrainXmin << ':' << results.terrainXmax
       << "]\nset yrange [" << results.terrainYmin << ':' << results.terrainYmax << "]\nset size ratio -1\nset key outside right\n"
       << "set arrow from " << results.forestStartX << ',' << results.terrainYmin << " to " << results.forestStartX << ','
       << results.terrainYmax << " nohead dt 2 lc rgb '#27ae60'\n"
       << "plot 'data/stops_baseline.csv' every ::1 using 4:5 with points pt 7 ps 0.4 lc rgb BASE title 'no forest', \\\n"
       << "     'data/stops_A.csv' every ::1 using 4:5 with points pt 7 ps 0.4 lc rgb A title 'A', \\\n"
       << "     'data/stops_NA.csv' every ::1 using 4:5 with points pt 7 ps 0.4 lc rgb NA title 'NA'\n";
    return gp.str();
}

}  // namespace

FigureSet runGnuplot(const std::string& reportDir, const std::string& script, const std::vector<std::string>& svgs) {
    {
        std::ofstream gp(reportDir + "/figures.gp", std::ios::trunc);
        gp << script;
        if (!gp.flush()) throw InputError(reportDir + "/figures.gp", 0, "cannot write");
    }
    FigureSet set;
    for (const auto& f : svgs) fs::remove(reportDir + "/" + f);
    // gnuplot's messages go to our standard error; its exit status tells whether it ran.
    const int status = std::system(("cd " + shellQuoted(reportDir) + " && gnuplot figures.gp 1>&2").c_str());
    for (const auto& f : svgs)
        if (fs::exists(reportDir + "/" + f)) set.files.push_back(f);
    if (status != 0 || set.files.size() != svgs.size())
        set.warning = "gnuplot did not draw every figure (is gnuplot-nox installed?); the data and figures.gp are in " + reportDir;
    return set;
}

namespace {

// The comparison's figures read each model's figure data, in <model>/data/ beside them.
std::string comparisonScript(const std::vector<AssessmentResults>& results) {
    const auto names = standNames(results.front());
    const int n = static_cast<int>(names.size());
    const int cols = std::min(n, 2), rows = (n + 1) / 2;
    const auto dir = [](const AssessmentResults& r) { return dem::toString(r.model) + "/"; };
    std::ostringstream gp;
    gp << "# Figures comparing the models of sylvarock assess; run `gnuplot figures.gp` in this folder to redraw them.\n"
       << "set datafile separator ','\nset grid\nset key bottom right\n"
       << "A = '#c0392b'; NA = '#2471a3'; BASE = '#000000'\n\n";
    // The first model drawn solid, the second dashed.
    const auto style = [](std::size_t m) { return m == 0 ? std::string(" dt 1") : std::string(" dt 2"); };

    gp << "# Figs. 9-10: cumulative run-out with and without forest, both models, one panel per stand\n"
       << "set terminal svg size " << 560 * cols << ',' << 400 * rows << " dynamic noenhanced font 'sans,11'\n"
       << "set output 'runout_cdf_models.svg'\nset multiplot layout " << rows << ',' << cols
       << " title 'Cumulative run-out along the slope: " << dem::toString(results[0].model) << " solid, "
       << dem::toString(results[1].model) << " dashed'\n"
       << "set xlabel 'run-out along the slope (m)'\nset ylabel 'share of blocks stopped'\nset yrange [0:1]\n";
    for (const auto& name : names) {
        gp << "set title " << quoted(name) << "\nplot ";
        for (std::size_t m = 0; m < results.size(); ++m) {
            const std::string model = dem::toString(results[m].model);
            gp << (m ? ", \\\n     " : "") << quoted(dir(results[m]) + "data/cdf_baseline.csv") << " every ::1 using 1:2 with steps lw 2"
               << style(m) << " lc rgb BASE title " << quoted(model + " no forest");
            for (const auto& row : results[m].stands)
                if (row.name == name)
                    gp << ", \\\n     " << quoted(dir(results[m]) + cdfFile(row)) << " every ::1 using 1:2 with steps lw 2" << style(m)
                       << " lc rgb " << structureCode(row.structure) << " title " << quoted(model + " " + structureCode(row.structure));
        }
        gp << "\n";
    }
    gp << "unset multiplot\nset autoscale y\n\n";

    gp << "# Fig. 11: PF50 per stand, both models, A and NA, with bootstrap intervals\n"
       << "set terminal svg size " << std::max(600, 150 * n + 240) << ",440 dynamic noenhanced font 'sans,11'\nset output 'pf50_models.svg'\n"
       << "set title 'PF50 per stand with " << confidencePercent(results[0].bootstrap.confidence)
       << " % bootstrap interval'\nset xlabel 'stand'\nset ylabel 'PF50'\nset xrange [-0.6:" << n - 0.4 << "]\nset key outside right\nplot ";
    const double offsets[2][2] = {{-0.27, -0.09}, {0.09, 0.27}};
    for (std::size_t m = 0; m < results.size(); ++m) {
        const std::string model = dem::toString(results[m].model);
        gp << (m ? ", \\\n     " : "") << quoted(dir(results[m]) + "data/pf50_A.csv") << " every ::1 using ($1" << std::showpos
           << offsets[m][0] << std::noshowpos << "):3:4:5" << (m == 0 ? ":xtic(2)" : "") << " with yerrorbars pt " << (m ? 6 : 7)
           << " lc rgb A title " << quoted(model + " A") << ", \\\n     " << quoted(dir(results[m]) + "data/pf50_NA.csv")
           << " every ::1 using ($1" << std::showpos << offsets[m][1] << std::noshowpos << "):3:4:5 with yerrorbars pt " << (m ? 4 : 5)
           << " lc rgb NA title " << quoted(model + " NA");
    }
    gp << "\nset autoscale x\nset xtics autofreq\nset key bottom right\n\n";

    gp << "# Fig. 12: PF50 of both models against the inventory's basal area, mean diameter and stem density\n"
       << "set terminal svg size 1300,420 dynamic noenhanced font 'sans,11'\nset output 'pf50_dendrometry_models.svg'\n"
       << "set multiplot layout 1,3 title 'PF50 against the stands'' dendrometry (filled: " << dem::toString(results[0].model)
       << ", open: " << dem::toString(results[1].model) << ")'\nunset title\nset ylabel 'PF50'\nset key top left\n";
    for (const auto& axis : kDendrometry) {
        gp << "set xlabel '" << axis.label << "'\n" << xRange(results[0], axis) << "plot ";
        for (std::size_t m = 0; m < results.size(); ++m) {
            const std::string model = dem::toString(results[m].model);
            gp << (m ? ", \\\n     " : "") << quoted(dir(results[m]) + "data/pf50_A.csv") << " every ::1 using " << axis.column
               << ":3 with points pt " << (m ? 6 : 7) << " lc rgb A title " << quoted(model + " A") << ", \\\n     "
               << quoted(dir(results[m]) + "data/pf50_NA.csv") << " every ::1 using " << axis.column << ":3 with points pt " << (m ? 4 : 5)
               << " lc rgb NA title " << quoted(model + " NA");
        }
        gp << "\n";
    }
    gp << "unset multiplot\n";
    return gp.str();
}

}  // namespace

FigureSet drawFigures(const std::string& reportDir, const AssessmentResults& results) {
    writeData(reportDir, results);
    return runGnuplot(reportDir, script(results), {"runout_cdf.svg", "pf50.svg", "pf50_dendrometry.svg", "stop_map.svg"});
}

FigureSet drawModelComparisonFigures(const std::string& reportDir, const std::vector<AssessmentResults>& results) {
    return runGnuplot(reportDir, comparisonScript(results), {"runout_cdf_models.svg", "pf50_models.svg", "pf50_dendrometry_models.svg"});
}

}  // namespace sylva::assess

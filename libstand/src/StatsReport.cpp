#include "libstand/StatsReport.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace sylva::stand {
namespace {

std::string number(double v, const char* format = "%.10g") {
    if (!std::isfinite(v)) return "null";
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

std::string number(const std::optional<double>& v, const char* format = "%.10g") {
    return v ? number(*v, format) : "null";
}

std::string clarkEvansNote(const StandStatistics& s) {
    if (s.plots.size() == 1) return "a single plot or pattern: the stand's Clark-Evans indices are its own";
    return "the stand's Clark-Evans indices are the means of the per-plot values (naive over " +
           std::to_string(s.plotsInNaiveMean) + " plots with at least 2 stems, Donnelly over " +
           std::to_string(s.plotsInDonnellyMean) + " rectangular ones)";
}

using Json = nlohmann::ordered_json;  // keys in the order written

Json optionalNumber(const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); }

// The keys shared by the stand and its plots (non-finite numbers are written as null).
void dendrometrics(Json& j, const DendrometricStatistics& d) {
    const ClarkEvansIndex& ce = d.clarkEvans;
    j["n"] = d.n;
    j["area_ha"] = d.areaHa;
    j["stems_per_ha"] = d.stemsPerHa;
    j["basal_area_m2_ha"] = optionalNumber(d.basalAreaM2Ha);
    j["mean_dbh_cm"] = optionalNumber(d.meanDbhCm);
    j["sd_dbh_cm"] = optionalNumber(d.sdDbhCm);
    j["n_stools"] = d.nStools;
    j["stems_per_stool"] = optionalNumber(d.stemsPerStool);
    j["stool_share"] = optionalNumber(d.stoolShare);
    j["clark_evans"] = {{"naive", optionalNumber(ce.naive)},
                        {"donnelly", optionalNumber(ce.donnelly)},
                        {"guard", optionalNumber(ce.guard)},
                        {"cdf", optionalNumber(ce.cdf)},
                        {"mean_nn_m", ce.naive ? Json(ce.meanNearestNeighbour) : Json(nullptr)}};
}

}  // namespace

std::string statsJson(const StandStatistics& s, const std::vector<std::string>& warnings,
                      const std::optional<PcfReport>& pcf) {
    Json root;
    root["name"] = s.name;
    Json& stand = root["stand"];
    stand["n_plots"] = s.plots.size();
    dendrometrics(stand, s.stand);
    stand["clark_evans"]["note"] = clarkEvansNote(s);
    root["plots"] = Json::array();
    for (const PlotStatistics& p : s.plots) {
        Json plot;
        plot["id"] = p.id;
        plot["window"] = p.window;
        plot["empty"] = p.empty;
        dendrometrics(plot, p.stats);
        plot["clark_evans"]["guard_distance_m"] = optionalNumber(p.stats.clarkEvans.guardDistance);
        plot["clark_evans"]["n_in_guard"] = p.stats.clarkEvans.nInGuard;
        root["plots"].push_back(plot);
    }
    root["warnings"] = warnings;
    if (pcf)
        root["pcf"] = {{"file", pcf->file}, {"rmax_m", pcf->rmax}, {"n_r", pcf->nr}, {"columns", "r,g_trans,g_iso"}, {"pooling", pcf->pooling}};
    return root.dump(2) + "\n";
}

std::string statsTable(const StandStatistics& s, const std::vector<std::string>& warnings,
                       const std::optional<PcfReport>& pcf) {
    std::ostringstream os;
    char line[512];
    const auto number = [](const auto& v, const char* format) {
        const std::string text = stand::number(v, format);
        return text == "null" ? std::string("-") : text;
    };
    const auto row = [&](const std::string& label, const DendrometricStatistics& d) {
        const ClarkEvansIndex& ce = d.clarkEvans;
        std::snprintf(line, sizeof line, "%-8s %6zu %8s %8s %7s %7s %6zu %7s %6s %7s %7s %7s %7s\n", label.c_str(), d.n,
                      number(d.stemsPerHa, "%.1f").c_str(), number(d.basalAreaM2Ha, "%.3f").c_str(),
                      number(d.meanDbhCm, "%.2f").c_str(), number(d.sdDbhCm, "%.2f").c_str(), d.nStools,
                      number(d.stemsPerStool, "%.3f").c_str(), number(d.stoolShare, "%.3f").c_str(),
                      number(ce.naive, "%.4f").c_str(), number(ce.donnelly, "%.4f").c_str(),
                      number(ce.guard, "%.4f").c_str(), number(ce.cdf, "%.4f").c_str());
        os << line;
    };
    os << "Stand " << s.name << ": " << s.plots.size() << (s.plots.size() == 1 ? " plot, " : " plots, ")
       << number(s.stand.areaHa, "%.4f") << " ha\n\n";
    std::snprintf(line, sizeof line, "%-8s %6s %8s %8s %7s %7s %6s %7s %6s %7s %7s %7s %7s\n", "plot", "n", "N/ha",
                  "G m2/ha", "meanD", "sdD", "stools", "st/stool", "share", "R naive", "R Donn.", "R guard", "R cdf");
    os << line;
    for (const auto& p : s.plots) row(p.id, p.stats);
    row("stand", s.stand);
    os << "\nN and G of the stand use the total area of all plots; DBH in cm, sd with n-1.\n"
       << "Note: " << clarkEvansNote(s) << ".\n";
    for (const auto& p : s.plots)
        if (p.empty) os << "Plot " << p.id << " has no stem (it counts in the area, lowering N and G).\n";
    if (s.plots.size() == 1 && !s.plots.front().empty)
        os << "Window: " << s.plots.front().window << "\n";
    if (pcf)
        os << "Pair correlation g(r), r = 0.." << number(pcf->rmax, "%.4g") << " m (" << pcf->nr << " values), written to "
           << pcf->file << " (" << pcf->pooling << ").\n";
    if (!warnings.empty()) os << warnings.size() << " warning(s), see standard error.\n";
    return os.str();
}

}  // namespace sylva::stand

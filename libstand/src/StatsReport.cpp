#include "libstand/StatsReport.hpp"

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

std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

std::string clarkEvansNote(const StandStatistics& s) {
    if (s.plots.size() == 1) return "a single plot or pattern: the stand's Clark-Evans indices are its own";
    return "the stand's Clark-Evans indices are the means of the per-plot values (naive over " +
           std::to_string(s.plotsInNaiveMean) + " plots with at least 2 stems, Donnelly over " +
           std::to_string(s.plotsInDonnellyMean) + " rectangular ones)";
}

// The keys shared by the stand and its plots.
void dendrometricsJson(std::ostream& os, const DendrometricStatistics& d, const std::string& indent,
                       const std::string& ceExtra) {
    const ClarkEvansIndex& ce = d.clarkEvans;
    os << indent << "\"n\": " << d.n << ",\n"
       << indent << "\"area_ha\": " << number(d.areaHa) << ",\n"
       << indent << "\"stems_per_ha\": " << number(d.stemsPerHa) << ",\n"
       << indent << "\"basal_area_m2_ha\": " << number(d.basalAreaM2Ha) << ",\n"
       << indent << "\"mean_dbh_cm\": " << number(d.meanDbhCm) << ",\n"
       << indent << "\"sd_dbh_cm\": " << number(d.sdDbhCm) << ",\n"
       << indent << "\"n_stools\": " << d.nStools << ",\n"
       << indent << "\"stems_per_stool\": " << number(d.stemsPerStool) << ",\n"
       << indent << "\"stool_share\": " << number(d.stoolShare) << ",\n"
       << indent << "\"clark_evans\": {\"naive\": " << number(ce.naive) << ", \"donnelly\": " << number(ce.donnelly)
       << ", \"guard\": " << number(ce.guard) << ", \"cdf\": " << number(ce.cdf)
       << ", \"mean_nn_m\": " << (ce.naive ? number(ce.meanNearestNeighbour) : "null") << ceExtra << "}";
}

}  // namespace

std::string statsJson(const StandStatistics& s, const std::vector<std::string>& warnings,
                      const std::optional<PcfReport>& pcf) {
    std::ostringstream os;
    os << "{\n  \"name\": " << quoted(s.name) << ",\n  \"stand\": {\n    \"n_plots\": " << s.plots.size() << ",\n";
    dendrometricsJson(os, s.stand, "    ", ", \"note\": " + quoted(clarkEvansNote(s)));
    os << "\n  },\n  \"plots\": [";
    for (std::size_t i = 0; i < s.plots.size(); ++i) {
        const PlotStatistics& p = s.plots[i];
        os << (i ? ",\n" : "\n") << "    {\n      \"id\": " << quoted(p.id) << ",\n      \"window\": " << quoted(p.window)
           << ",\n      \"empty\": " << (p.empty ? "true" : "false") << ",\n";
        dendrometricsJson(os, p.stats, "      ",
                          ", \"guard_distance_m\": " + number(p.stats.clarkEvans.guardDistance) +
                              ", \"n_in_guard\": " + std::to_string(p.stats.clarkEvans.nInGuard));
        os << "\n    }";
    }
    os << "\n  ],\n  \"warnings\": [";
    for (std::size_t i = 0; i < warnings.size(); ++i) os << (i ? ", " : "") << quoted(warnings[i]);
    os << "]";
    if (pcf)
        os << ",\n  \"pcf\": {\"file\": " << quoted(pcf->file) << ", \"rmax_m\": " << number(pcf->rmax)
           << ", \"n_r\": " << pcf->nr << ", \"columns\": \"r,g_trans,g_iso\", \"pooling\": " << quoted(pcf->pooling)
           << "}";
    os << "\n}\n";
    return os.str();
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

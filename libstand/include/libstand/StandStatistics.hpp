#pragma once
// Dendrometric and spatial statistics of an inventory, per plot and per stand (the paper's Table 3:
// N, G, mean and sd of DBH, R_Clark; plus the coppice stools).
#include <optional>
#include <string>
#include <vector>

#include "libstand/ClarkEvans.hpp"
#include "libstand/Inventory.hpp"

namespace sylva::stand {

struct DendrometricStatistics {
    std::size_t n = 0;    // stems
    double areaHa = 0;
    double stemsPerHa = 0;                  // N = n / area
    std::optional<double> basalAreaM2Ha;    // G = sum(pi (dbh/200)²) / area; empty without diameters
    std::optional<double> meanDbhCm;        // empty without diameters or stems
    std::optional<double> sdDbhCm;          // divisor n - 1; empty below 2 stems
    std::size_t nStools = 0;                // distinct stool ids
    std::optional<double> stemsPerStool;    // stems in stools / stools; empty without stools
    std::optional<double> stoolShare;       // stems in stools / n; empty without stems
    ClarkEvansIndex clarkEvans;             // a stand's: the mean of its plots' values (see below)
};

struct PlotStatistics {
    std::string id;
    std::string window;  // Window::describe()
    bool empty = false;  // no stem: valid, lowers the stand's N and G
    DendrometricStatistics stats;
};

struct StandStatistics {
    std::string name;
    DendrometricStatistics stand;  // N and G over the total area of all plots
    std::vector<PlotStatistics> plots;
    // The stand's Clark-Evans indices are the means over the plots where each is defined (at least 2
    // stems; Donnelly: rectangular plots); these are the counts of plots in each mean.
    std::size_t plotsInNaiveMean = 0, plotsInDonnellyMean = 0, plotsInGuardMean = 0, plotsInCdfMean = 0;
};

StandStatistics standStatistics(const Inventory& inventory);

}  // namespace sylva::stand

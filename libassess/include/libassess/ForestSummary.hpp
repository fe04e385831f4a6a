#pragma once
// The dendrometry of a stand or of one of its virtual forests, as the paper's Table 3 lists it (N, G,
// mean and sd of DBH, Clark-Evans with Donnelly's correction): what the protection index is set
// against (Fig. 12), and the check that the virtual forests have the inventory's structure.
#include <cstddef>
#include <string>

#include "libstand/Forest.hpp"
#include "libstand/StandStatistics.hpp"
#include "libstand/Window.hpp"

namespace sylva::assess {

struct ForestSummary {
    std::size_t stems = 0;
    double stemsPerHa = 0, basalAreaM2Ha = 0, meanDbhCm = 0, sdDbhCm = 0;
    double clarkEvans = 0;  // Donnelly-corrected; NaN if undefined (fewer than 2 stems)
};

// An inventory's: N and G over all plots, Clark-Evans the mean of its plots' (Table 3's rows).
// Throws InputError naming the stand if it has no diameters (G and the forests need them).
ForestSummary summariseInventory(const stand::StandStatistics& statistics, bool hasDiameters);
// A virtual forest's over the extent it was generated on (one window).
ForestSummary summariseForest(const stand::Forest& forest, const stand::Window& extent);

// FNV-1a of the summary's values written at 17 significant digits: the campaign store keeps it beside
// the row, so statistics edited or damaged on disk are told from those the campaign computed.
std::string forestChecksum(const ForestSummary& summary);

}  // namespace sylva::assess

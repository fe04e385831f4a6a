#pragma once
// What `sylvarock stats` prints: a JSON document or a readable table of StandStatistics.
#include <optional>
#include <string>
#include <vector>

#include "libstand/StandStatistics.hpp"

namespace sylva::stand {

// Where the pair correlation function went and how it was pooled, for the report.
struct PcfReport {
    std::string file;
    double rmax = 0;
    std::size_t nr = 0;
    std::string pooling;  // e.g. "per-plot estimates averaged with weights n(n-1)"
};

// {"name", "stand": {n, area_ha, stems_per_ha, basal_area_m2_ha, mean_dbh_cm, sd_dbh_cm, n_stools,
//  stems_per_stool, stool_share, clark_evans: {naive, donnelly, guard, cdf, mean_nn_m, note}},
//  "plots": [{id, window, empty, ...same keys, clark_evans: {..., guard_distance_m, n_in_guard}}],
//  "warnings": [...], "pcf": {...}}. Numbers as %.10g; undefined values are null.
std::string statsJson(const StandStatistics& s, const std::vector<std::string>& warnings,
                      const std::optional<PcfReport>& pcf);

std::string statsTable(const StandStatistics& s, const std::vector<std::string>& warnings,
                       const std::optional<PcfReport>& pcf);

}  // namespace sylva::stand

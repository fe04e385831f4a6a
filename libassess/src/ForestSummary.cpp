#include "libassess/ForestSummary.hpp"

#include <cmath>
#include <cstdio>

#include "libassess/Hashing.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::assess {

namespace {
ForestSummary fromStatistics(const stand::DendrometricStatistics& s) {
    ForestSummary f;
    f.stems = s.n;
    f.stemsPerHa = s.stemsPerHa;
    f.basalAreaM2Ha = s.basalAreaM2Ha.value_or(std::nan(""));
    f.meanDbhCm = s.meanDbhCm.value_or(std::nan(""));
    f.sdDbhCm = s.sdDbhCm.value_or(std::nan(""));
    f.clarkEvans = s.clarkEvans.donnelly.value_or(std::nan(""));
    return f;
}

}  // namespace

ForestSummary summariseInventory(const stand::StandStatistics& statistics, bool hasDiameters) {
    if (!hasDiameters) throw InputError("stand " + statistics.name + ": the inventory has no diameters (dbh_cm), needed for G and the forests");
    return fromStatistics(statistics.stand);
}

ForestSummary summariseForest(const stand::Forest& forest, const stand::Window& extent) {
    stand::Inventory pattern;
    pattern.name = "virtual forest";
    pattern.plots.push_back({"forest", extent});
    for (const auto& t : forest.trees) {
        stand::Stem s;
        s.plot = "forest";
        s.id = std::to_string(t.id);
        s.x = t.x;
        s.y = t.y;
        s.dbhCm = t.dbhCm;
        if (t.stool) s.stool = std::to_string(*t.stool);
        pattern.stems.push_back(std::move(s));
    }
    return fromStatistics(stand::standStatistics(pattern).stand);
}

std::string forestChecksum(const ForestSummary& s) {
    // NaN is written "nan" (an undefined Clark-Evans index), the same on every platform.
    const std::string row = std::to_string(s.stems) + ',' + exactText(s.stemsPerHa) + ',' + exactText(s.basalAreaM2Ha) + ',' +
                            exactText(s.meanDbhCm) + ',' + exactText(s.sdDbhCm) + ',' + exactText(s.clarkEvans);
    return toHex(fnv1a64(row), 16);
}

}  // namespace sylva::assess

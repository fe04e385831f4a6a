#include "libassess/ForestSummary.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "libassess/Hashing.hpp"
#include "libstand/CsvTable.hpp"
#include "libstand/InputError.hpp"

namespace sylva::assess {

namespace {
const char* const kColumns[] = {"stems", "stems_per_ha", "basal_area_m2_ha", "mean_dbh_cm", "sd_dbh_cm", "clark_evans"};

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

std::string number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
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

// The data row's checksum, as run lines carry one: a summary edited or damaged on disk is told
// from the one the campaign computed.
std::string rowChecksum(const std::string& row) { return toHex(fnv1a64(row), 16); }

void writeForestSummary(const std::string& path, const ForestSummary& s) {
    const std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp, std::ios::trunc);
        for (const char* c : kColumns) out << c << ',';
        out << "checksum\n";
        // NaN is written as "nan" and read back as NaN by strtod (an undefined Clark-Evans index).
        std::ostringstream row;
        row << s.stems << ',' << number(s.stemsPerHa) << ',' << number(s.basalAreaM2Ha) << ',' << number(s.meanDbhCm) << ','
            << number(s.sdDbhCm) << ',' << number(s.clarkEvans);
        out << row.str() << ',' << rowChecksum(row.str()) << '\n';
        if (!out.flush()) throw InputError(tmp, 0, "cannot write");
    }
    std::filesystem::rename(tmp, path);
}

bool forestSummaryIntact(const std::string& path) {
    std::ifstream in(path);
    std::string header, row;
    if (!std::getline(in, header) || !std::getline(in, row)) return false;
    const auto comma = row.rfind(',');
    return comma != std::string::npos && row.substr(comma + 1) == rowChecksum(row.substr(0, comma));
}

ForestSummary readForestSummary(const std::string& path) {
    const CsvTable t = CsvTable::read(path);
    if (t.rows() != 1) throw InputError(path, 0, "expected one row of forest statistics, found " + std::to_string(t.rows()));
    if (!forestSummaryIntact(path))
        throw InputError(path, 2, "checksum mismatch: the forest's statistics were edited or damaged (delete the file: "
                                  "--resume computes them again)");
    std::vector<double> v;
    for (const char* c : kColumns) {
        const std::size_t col = t.require(c);
        if (t.text(0, col) == "nan") {
            v.push_back(std::nan(""));
        } else {
            v.push_back(t.number(0, col));
        }
    }
    ForestSummary s;
    if (!(v[0] >= 0)) t.fail(0, "negative stem count");
    s.stems = static_cast<std::size_t>(v[0]);
    s.stemsPerHa = v[1];
    s.basalAreaM2Ha = v[2];
    s.meanDbhCm = v[3];
    s.sdDbhCm = v[4];
    s.clarkEvans = v[5];
    return s;
}

}  // namespace sylva::assess

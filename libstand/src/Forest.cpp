#include "libstand/Forest.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <unordered_map>

#include "libstand/Allometry.hpp"
#include "libstand/Inventory.hpp"
#include "libcommon/CsvTable.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::stand {

namespace {

// A species name is written as is unless it would break the row (a comma or a quote).
std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"") == std::string::npos) return s;
    std::string quoted = "\"";
    for (char c : s) quoted += (c == '"') ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

// Optional numeric column: the row's value if the file has the column, else nothing.
std::optional<double> optionalNumber(const CsvTable& t, std::size_t row, std::optional<std::size_t> col) {
    if (!col) return std::nullopt;
    return t.number(row, *col);
}

}  // namespace

void writeForestCsv(const std::string& path, const Forest& forest) {
    std::ofstream out(path);
    if (!out) throw cannotWrite(path);
    // 10 significant digits: positions to 0.1 mm on a 100 km slope, diameters as given.
    out.precision(10);
    out << "stem,x,y,dbh_cm,species,stool,height_m,crown_length_m,crown_mass_kg\n";
    for (const Tree& t : forest.trees) {
        out << t.id << ',' << t.x << ',' << t.y << ',' << t.dbhCm << ',' << csvField(t.species) << ',';
        if (t.stool) out << *t.stool;
        out << ',' << t.heightM << ',' << t.crownLengthM << ',' << t.crownMassKg << '\n';
    }
    out.flush();
    if (!out) throw InputError(path, 0, "write failed (disk full?)");
}

Forest readForestCsv(const std::string& path) {
    const CsvTable t = CsvTable::read(path);
    const std::size_t cx = t.require("x"), cy = t.require("y"), cd = t.require("dbh_cm");
    requireOnePlot(t, cx, cy, "make a forest from it with its plots (sylvarock generate --stems S --plots P)");
    const auto cStem = t.index("stem"), cSpecies = t.index("species"), cStool = t.index("stool");
    const auto cHeight = t.index("height_m"), cCrownLength = t.index("crown_length_m"),
               cCrownMass = t.index("crown_mass_kg");

    Forest forest;
    forest.source = path;
    forest.trees.reserve(t.rows());
    std::unordered_map<long, long> lineOfStem;
    std::map<std::pair<long long, long long>, long> lineAt;  // position rounded to the mm -> line
    for (std::size_t r = 0; r < t.rows(); ++r) {
        Tree tree;
        tree.line = t.lineOf(r);
        tree.id = cStem ? t.integer(r, *cStem) : static_cast<long>(r + 1);
        if (const auto [it, fresh] = lineOfStem.emplace(tree.id, t.lineOf(r)); !fresh)
            t.fail(r, *cStem, "stem id " + std::to_string(tree.id) + " already used on line " + std::to_string(it->second));
        tree.x = t.number(r, cx);
        tree.y = t.number(r, cy);
        tree.dbhCm = t.number(r, cd);
        if (const std::string why = dbhProblem(tree.dbhCm); !why.empty()) t.fail(r, cd, why);
        // Two stems at one place (a line repeated by a concatenation) would start inside each other.
        const auto cell = std::make_pair(std::llround(tree.x * 1e3), std::llround(tree.y * 1e3));
        if (const auto [it, fresh] = lineAt.emplace(cell, t.lineOf(r)); !fresh)
            t.fail(r, "stem at (" + t.text(r, cx) + ", " + t.text(r, cy) + ") stands where the stem of line " +
                          std::to_string(it->second) + " stands (to the millimetre): a repeated line?");
        if (cSpecies) tree.species = t.text(r, *cSpecies);
        if (cStool && readStoolCell(t, r, *cStool)) tree.stool = t.integer(r, *cStool);

        // Computed allometry always passes the checks below, so only a value read from the file can fail.
        const std::optional<double> height = optionalNumber(t, r, cHeight);
        tree.heightM = height.value_or(treeHeightM(tree.dbhCm));
        // Above the breast height, where the DBH was measured, and below the tallest trees known (coast
        // redwoods of 112.7 m, and a hydraulic limit of 122-130 m: Koch et al. 2004, Nature 428: 851-854):
        // 2000 is a height in cm, and would be stepped as a 2 km stem.
        if (height && (!(tree.heightM > 1.3) || tree.heightM > 150))
            t.fail(r, *cHeight, "height must lie above the breast height 1.3 m and at most 150 m, got " + t.text(r, *cHeight) +
                                    (tree.heightM > 150 ? " (cm typed as m?)" : ""));
        tree.crownLengthM = optionalNumber(t, r, cCrownLength).value_or(crownLengthM(tree.heightM));
        if (tree.crownLengthM < 0 || tree.crownLengthM > tree.heightM)
            t.fail(r, *cCrownLength, "crown length must lie in [0, height_m], got " + t.text(r, *cCrownLength));
        const std::optional<double> crownMass = optionalNumber(t, r, cCrownMass);
        tree.crownMassKg = crownMass.value_or(crownMassKg(tree.dbhCm));
        // 100 t is above Eq. 13's crown (Bartelink 1997) at the largest DBH read, 200 cm (58 t); more is
        // a unit slip (grams as kg), under which the stem could not move.
        if (crownMass && (!(tree.crownMassKg >= 0) || tree.crownMassKg > 1e5))
            t.fail(r, *cCrownMass, "crown mass must lie in [0, 100 000] kg, got " + t.text(r, *cCrownMass));
        forest.trees.push_back(std::move(tree));
    }
    return forest;
}

}  // namespace sylva::stand

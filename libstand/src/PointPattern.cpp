#include "libstand/PointPattern.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <sstream>

#include "libstand/Inventory.hpp"
#include "libcommon/CsvTable.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::stand {

Inventory readPointPattern(const std::string& csv, const Window& window) {
    const CsvTable t = CsvTable::read(csv);
    const std::size_t cX = t.require("x"), cY = t.require("y");
    requireOnePlot(t, cX, cY, "give it with its plots: --stems S --plots P");
    const auto cDbh = t.index("dbh_cm");
    const auto cStool = t.index("stool");
    const auto cStem = t.index("stem");

    Inventory inv;
    inv.name = csv.substr(csv.find_last_of("/\\") + 1);
    inv.plots.push_back({"1", window});
    std::map<std::string, long> lineOfStem;
    for (std::size_t r = 0; r < t.rows(); ++r) {
        Stem s;
        s.plot = "1";
        s.line = t.lineOf(r);
        s.id = cStem ? t.text(r, *cStem) : std::to_string(r + 1);
        if (cStem) {
            if (s.id.empty()) t.fail(r, *cStem, "empty stem id");
            if (const auto it = lineOfStem.find(s.id); it != lineOfStem.end())
                t.fail(r, *cStem, "duplicate stem id '" + s.id + "' (also on line " + std::to_string(it->second) + ")");
            lineOfStem[s.id] = s.line;
        }
        s.x = t.number(r, cX);
        s.y = t.number(r, cY);
        s.dbhCm = cDbh ? readDbhCell(t, r, *cDbh) : NAN;
        if (cStool) s.stool = readStoolCell(t, r, *cStool);
        if (!window.contains({s.x, s.y})) {
            std::ostringstream os;
            os << "point (" << s.x << ", " << s.y << ") lies outside the window (" << window.describe() << ")";
            t.fail(r, os.str());
        }
        inv.stems.push_back(std::move(s));
    }
    inv.hasDiameters = cDbh.has_value();
    inv.warnings = dataWarnings(inv, csv, "window");
    // Diameters under another name were left out without a word (G and the DBH statistics "-").
    if (!cDbh)
        for (const std::string& name : t.header()) {
            std::string lower(name);
            std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
            if (lower.rfind("dbh", 0) == 0 || lower.rfind("diam", 0) == 0 || lower == "d" || lower == "bhd" || lower == "d_cm")
                inv.warnings.push_back(csv + ": no column dbh_cm, so no G or DBH statistics; column '" + name +
                                       "' may hold the diameters: name it dbh_cm if they are in cm");
        }
    return inv;
}

}  // namespace sylva::stand

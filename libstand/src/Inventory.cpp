#include "libstand/Inventory.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

#include "libstand/Allometry.hpp"
#include "libcommon/CsvTable.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::stand {
namespace {

// "data/stands/GR1_stems.csv" -> "GR1": the stand is named after its stems file.
std::string standName(const std::string& stemsCsv) {
    std::string base = stemsCsv.substr(stemsCsv.find_last_of("/\\") + 1);
    if (const auto dot = base.rfind('.'); dot != std::string::npos && dot > 0) base.erase(dot);
    for (const std::string suffix : {"_stems", "-stems", "_trees"})
        if (base.size() > suffix.size() && base.compare(base.size() - suffix.size(), suffix.size(), suffix) == 0)
            return base.substr(0, base.size() - suffix.size());
    return base;
}

std::vector<Plot> readPlots(const std::string& path) {
    const CsvTable t = CsvTable::read(path);
    const std::size_t cPlot = t.require("plot");
    // Two geometries for one plot: one of them was used, the other passed over without a word, so
    // that two which disagree (0.25 ha and 1 ha) gave one plot's area unsaid.
    std::optional<std::size_t> cWkt;
    for (const char* name : {"wkt", "window", "geometry"})
        if (const auto c = t.index(name)) {
            if (cWkt) throw InputError(path, t.headerLine(), "two WKT columns, '" + t.header()[*cWkt] + "' and '" + name + "': give one");
            cWkt = c;
        }
    // A WKT polygon beside its bounding box (a GIS export) is one window; the box is checked against it.
    const bool boxToo = cWkt && t.has("xmin") && t.has("ymin") && t.has("xmax") && t.has("ymax");
    const auto corners = [](const std::array<double, 4>& c) {
        return readableNumber(c[0]) + "," + readableNumber(c[1]) + "," + readableNumber(c[2]) + "," + readableNumber(c[3]);
    };
    if (!cWkt && !t.has("xmin") && !t.has("ymin") && !t.has("xmax") && !t.has("ymax")) {
        std::string have;
        for (const auto& h : t.header()) have += (have.empty() ? "" : ",") + h;
        throw InputError(path, 1,
                         "a plots file needs either columns xmin,ymin,xmax,ymax or a WKT column named wkt (or window, "
                         "geometry); header has: " + have);
    }
    std::array<std::size_t, 4> cBox{};
    if (!cWkt) cBox = {t.require("xmin"), t.require("ymin"), t.require("xmax"), t.require("ymax")};

    std::vector<Plot> plots;
    std::map<std::string, long> lineOfPlot;
    for (std::size_t r = 0; r < t.rows(); ++r) {
        const std::string id = t.text(r, cPlot);
        if (id.empty()) t.fail(r, cPlot, "empty plot id");
        if (const auto it = lineOfPlot.find(id); it != lineOfPlot.end())
            t.fail(r, cPlot, "duplicate plot id '" + id + "' (first defined on line " + std::to_string(it->second) + ")");
        lineOfPlot[id] = t.lineOf(r);
        try {
            if (cWkt) {
                plots.push_back({id, Window::fromWkt(t.text(r, *cWkt))});
                if (boxToo) {
                    const Window& w = plots.back().window;
                    const std::array<double, 4> box{t.number(r, *t.index("xmin")), t.number(r, *t.index("ymin")),
                                                    t.number(r, *t.index("xmax")), t.number(r, *t.index("ymax"))};
                    const std::array<double, 4> wkt{w.lower().x(), w.lower().y(), w.upper().x(), w.upper().y()};
                    // A millimetre: the box's coordinates may be rounded where the WKT's are not.
                    for (int k = 0; k < 4; ++k)
                        if (std::fabs(box[k] - wkt[k]) > 1e-3)
                            t.fail(r, "plot '" + id + "': its WKT polygon's bounding box " + corners(wkt) + " is not its rectangle " + corners(box) +
                                          " (xmin,ymin,xmax,ymax): which is the plot?");
                }
            } else {
                const double x0 = t.number(r, cBox[0]), y0 = t.number(r, cBox[1]);
                const double x1 = t.number(r, cBox[2]), y1 = t.number(r, cBox[3]);
                plots.push_back({id, Window::rectangle(x0, y0, x1, y1)});
            }
            plots.back().window.requirePlotSize();
        } catch (const InputError& e) {
            if (e.line() > 0) throw;  // already names file and line (a bad number)
            t.fail(r, "plot '" + id + "': " + e.what());
        }
    }
    if (plots.empty()) throw InputError(path, 0, "no plots in the file");
    return plots;
}

std::string coordinates(const Stem& s) {
    std::ostringstream os;
    os << "(" << s.x << ", " << s.y << ")";
    return os.str();
}

}  // namespace

double Inventory::areaHa() const {
    double a = 0;
    for (const auto& p : plots) a += p.window.area();
    return a / 1e4;
}

namespace {
bool missingValue(const std::string& text) { return text.empty() || text == "NA" || text == "nan" || text == "NaN"; }
}  // namespace

std::optional<std::string> readStoolCell(const CsvTable& t, std::size_t row, std::size_t column) {
    const std::string& text = t.text(row, column);
    if (missingValue(text)) return std::nullopt;
    return text;
}

double readDbhCell(const CsvTable& t, std::size_t row, std::size_t column) {
    const std::string& text = t.text(row, column);
    if (missingValue(text)) return std::nan("");
    const double dbh = t.number(row, column);
    if (dbh == 0) return 0;
    if (const std::string why = dbhProblem(dbh); !why.empty()) t.fail(row, column, why);
    return dbh;
}

void requireOnePlot(const CsvTable& table, std::size_t xColumn, std::size_t yColumn, const std::string& instead) {
    const auto plot = table.index("plot");
    if (!plot) return;
    // Each plot's stems' bounding box, with its first row. Plots in one shared frame (georeferenced
    // trees with a plot attribute) lie side by side; an inventory's, each in its own frame from (0, 0),
    // on one another. An empty cell names no plot.
    struct Extent {
        std::size_t firstRow;
        double x0, y0, x1, y1;
    };
    std::map<std::string, Extent> extent;
    for (std::size_t r = 0; r < table.rows(); ++r) {
        const std::string& id = table.text(r, *plot);
        if (id.empty()) continue;
        const double x = table.number(r, xColumn), y = table.number(r, yColumn);
        const auto [it, fresh] = extent.try_emplace(id, Extent{r, x, y, x, y});
        Extent& e = it->second;
        e.x0 = std::min(e.x0, x), e.y0 = std::min(e.y0, y), e.x1 = std::max(e.x1, x), e.y1 = std::max(e.y1, y);
    }
    // Swept along x, so that a map of many small plots (a plot id per tree, even) costs little more than
    // sorting them: each plot is held against those that start before it ends.
    std::vector<const std::pair<const std::string, Extent>*> byX;
    for (const auto& e : extent) byX.push_back(&e);
    std::sort(byX.begin(), byX.end(), [](const auto* a, const auto* b) { return a->second.x0 < b->second.x0; });
    for (std::size_t i = 0; i < byX.size(); ++i)
        for (std::size_t j = i + 1; j < byX.size() && byX[j]->second.x0 <= byX[i]->second.x1; ++j) {
            const Extent &p = byX[i]->second, &q = byX[j]->second;
            if (std::min(p.y1, q.y1) < std::max(p.y0, q.y0)) continue;  // apart
            const auto* later = p.firstRow < q.firstRow ? byX[j] : byX[i];
            const auto* earlier = later == byX[j] ? byX[i] : byX[j];
            table.fail(later->second.firstRow, *plot,
                       "the stems of plot '" + later->first + "' stand among those of plot '" + earlier->first +
                           "': an inventory's stems file, each plot in its own frame, read as one frame would stack its plots on one "
                           "another; " + instead);
        }
}

std::vector<std::string> dataWarnings(const Inventory& inv, const std::string& stemsSource,
                                      const std::string& plotsSource) {
    std::vector<std::string> warnings;
    std::size_t below = 0, unmeasured = 0;
    long firstLine = 0;
    for (const auto& s : inv.stems) {
        if (measured(s)) continue;
        (s.dbhCm == 0 ? below : unmeasured) += 1;
        if (!firstLine) firstLine = s.line;
    }
    if (inv.hasDiameters && below + unmeasured > 0)
        warnings.push_back(stemsSource + ": " + std::to_string(unmeasured) + " stem(s) without a DBH (NA or empty) and " +
                           std::to_string(below) + " below breast height (DBH 0), first on line " +
                           std::to_string(firstLine) + ": N, g(r) and Clark-Evans use all " +
                           std::to_string(inv.stems.size()) + " stems; G and the DBH statistics the " +
                           std::to_string(inv.stems.size() - below - unmeasured) + " measured ones" +
                           (below > 0 ? "; virtual forests leave the stems below breast height out" : ""));
    // Diameters in mm are refused (above 200 cm); in metres they would pass as sub-centimetre stems.
    double largest = 0;
    for (const auto& s : inv.stems)
        if (measured(s)) largest = std::max(largest, s.dbhCm);
    if (largest > 0 && largest < 1)
        warnings.push_back(stemsSource + ": every DBH is below 1 cm (the largest " + readableNumber(largest) +
                           "): diameters in metres? dbh_cm is in centimetres");
    std::map<std::string, std::vector<const Stem*>> byPlot;
    for (const auto& s : inv.stems) byPlot[s.plot].push_back(&s);
    for (const auto& p : inv.plots) {
        auto& stems = byPlot[p.id];
        if (stems.empty()) {
            warnings.push_back(plotsSource + ": plot '" + p.id + "' has no stem (it counts in the area, lowering N and G)");
            continue;
        }
        std::sort(stems.begin(), stems.end(),
                  [](const Stem* a, const Stem* b) { return std::tie(a->x, a->y, a->line) < std::tie(b->x, b->y, b->line); });
        for (std::size_t i = 1; i < stems.size(); ++i) {
            const Stem &s = *stems[i], &before = *stems[i - 1];
            if (s.x != before.x || s.y != before.y) continue;
            const bool oneStool = s.stool && s.stool == before.stool;
            warnings.push_back(stemsSource + ":" + std::to_string(s.line) + ": stem '" + s.id + "' is at the same position " +
                               coordinates(s) + " as stem '" + before.id + "' (line " + std::to_string(before.line) + ")" +
                               (oneStool ? " (its stool's position given to both?)" : "") +
                               "; kept, its nearest-neighbour distance is 0" +
                               (oneStool ? "; virtual forests stand a stool's stems recorded at one point on a ring "
                                           "around it, touching at breast height"
                                         : ""));
        }
    }
    // A coppice stool's stems stand within a metre or two of each other (1.25 m at most in the shipped
    // stands); members far apart are more likely a stool id reused than one stool.
    constexpr double kStoolSpread = 3;  // m
    std::map<std::pair<std::string, std::string>, std::vector<const Stem*>> byStool;
    for (const auto& s : inv.stems)
        if (s.stool) byStool[{s.plot, *s.stool}].push_back(&s);
    std::size_t spread = 0;
    double widest = 0;
    const Stem *wa = nullptr, *wb = nullptr;
    for (const auto& [key, members] : byStool) {
        bool far = false;
        for (std::size_t i = 0; i < members.size(); ++i)
            for (std::size_t j = 0; j < i; ++j) {
                const double d = std::hypot(members[i]->x - members[j]->x, members[i]->y - members[j]->y);
                far = far || d > kStoolSpread;
                if (d > widest) widest = d, wa = members[j], wb = members[i];
            }
        spread += far ? 1 : 0;
    }
    if (spread > 0) {
        std::ostringstream os;
        os.precision(3);
        os << stemsSource << ": " << spread << " stool(s) have stems more than " << kStoolSpread << " m apart, the widest stool '"
           << *wa->stool << "' of plot '" << wa->plot << "': " << widest << " m between lines " << wa->line << " and " << wb->line
           << " (a stool's stems stand within a metre or two: is a stool id used twice?); kept as stools";
        warnings.push_back(os.str());
    }
    return warnings;
}

Inventory readInventory(const std::string& stemsCsv, const std::string& plotsCsv) {
    Inventory inv;
    inv.name = standName(stemsCsv);
    inv.plots = readPlots(plotsCsv);
    std::map<std::string, const Plot*> plotById;
    for (const auto& p : inv.plots) plotById[p.id] = &p;

    const CsvTable t = CsvTable::read(stemsCsv);
    const std::size_t cPlot = t.require("plot"), cStem = t.require("stem"), cX = t.require("x"), cY = t.require("y"),
                      cDbh = t.require("dbh_cm");
    const auto cSpecies = t.index("species");
    const auto cStool = t.index("stool");
    std::map<std::string, long> lineOfStem;
    for (std::size_t r = 0; r < t.rows(); ++r) {
        Stem s;
        s.line = t.lineOf(r);
        s.plot = t.text(r, cPlot);
        s.id = t.text(r, cStem);
        if (s.id.empty()) t.fail(r, cStem, "empty stem id");
        if (const auto it = lineOfStem.find(s.id); it != lineOfStem.end())
            t.fail(r, cStem, "duplicate stem id '" + s.id + "' (also on line " + std::to_string(it->second) + ")");
        lineOfStem[s.id] = s.line;
        s.x = t.number(r, cX);
        s.y = t.number(r, cY);
        s.dbhCm = readDbhCell(t, r, cDbh);
        if (cSpecies) s.species = t.text(r, *cSpecies);
        if (cStool) s.stool = readStoolCell(t, r, *cStool);
        const auto plot = plotById.find(s.plot);
        if (plot == plotById.end())
            t.fail(r, cPlot, "plot '" + s.plot + "' has no window in " + plotsCsv);
        if (!plot->second->window.contains({s.x, s.y}))
            t.fail(r, "stem '" + s.id + "' at " + coordinates(s) + " lies outside its plot '" + s.plot + "' (" +
                          plot->second->window.describe() + ")");
        inv.stems.push_back(std::move(s));
    }

    inv.hasDiameters = true;  // dbh_cm is a required column
    inv.warnings = dataWarnings(inv, stemsCsv, plotsCsv);
    return inv;
}

}  // namespace sylva::stand

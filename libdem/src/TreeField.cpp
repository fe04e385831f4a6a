#include "libdem/TreeField.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "libcommon/InputError.hpp"

namespace sylva::dem {

namespace {

std::string tooThin(double dbhCm, double tipDiameter) {
    return "a DBH of " + readableNumber(dbhCm) + " cm is below the stems' tip diameter (stem.tip_diameter_m = " +
           readableNumber(tipDiameter * 100) + " cm), so it cannot be built as a stem";
}

}  // namespace

void requireBuildableStems(const stand::Inventory& inventory, const std::string& stemsCsv, double tipDiameter) {
    for (const stand::Stem& s : inventory.stems)
        if (s.dbhCm > 0 && s.dbhCm / 100 < tipDiameter)  // 0: below breast height, left out; NaN: refused where drawn
            throw InputError(stemsCsv, s.line,
                             "stem '" + s.id + "': " + tooThin(s.dbhCm, tipDiameter) +
                                 ": give 0 for a stem below breast height (it is left out), or lower stem.tip_diameter_m");
}

TreeField::TreeField(const stand::Forest& forest, const SoilBed& soil, double tipDiameter) {
    if (forest.trees.empty()) return;
    double xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300;
    for (const auto& t : forest.trees) {
        if (t.x < soil.xmin() || t.x > soil.xmax() || t.y < soil.ymin() || t.y > soil.ymax()) {
            std::ostringstream what;
            what.precision(10);  // projected coordinates (Lambert-93: 6 460 196 m) to the centimetre
            // Within half a cell of a DTM's terrain is a forest clipped to the raster's extent: the
            // terrain ends at the outermost cell centres. Farther, the forest is elsewhere.
            const double beyond = std::max({soil.xmin() - t.x, t.x - soil.xmax(), soil.ymin() - t.y, t.y - soil.ymax()});
            const bool atEdge = beyond <= 0.5 * soil.dtmCellSize();
            what << (forest.source.empty() ? "forest: " : "") << "stem " << t.id << " at (" << t.x << ", " << t.y
                 << ") is outside the terrain (" << soil.boundsText() << " m)"
                 << (atEdge ? ", by " + readableNumber(std::round(beyond * 100) / 100) + " m: the terrain ends at the DTM's "
                              "outermost cell centres, half a cell inside the raster's edge; keep the trees that far inside"
                            : ": a forest in another frame or CRS?");
            throw InputError(forest.source, t.line, what.str());
        }
        // Checked here, with the file's line, rather than when the block first reaches the stem: a
        // forest that cannot be built fails before any run, whatever the seed.
        if (!(t.dbhCm / 100 >= tipDiameter))
            throw InputError(forest.source, t.line,
                             (forest.source.empty() ? "forest: " : "") + std::string("stem ") + std::to_string(t.id) + ": " +
                                 tooThin(t.dbhCm, tipDiameter) + ": leave such stems out of the forest, or lower stem.tip_diameter_m");
        StemGeometry g;
        g.dbh = t.dbhCm / 100;
        g.height = t.heightM;
        g.crownLength = t.crownLengthM;
        g.crownMass = t.crownMassKg;
        trees_.push_back({t.id, Vec3(t.x, t.y, soil.surfaceHeight(t.x, t.y)), g,
                          t.stool ? StemFoot::Clamped : StemFoot::RootSpring});  // Sect. 2.1.2
        thickest_ = std::max(thickest_, g.dbh);
        xmin = std::min(xmin, t.x), xmax = std::max(xmax, t.x);
        ymin = std::min(ymin, t.y), ymax = std::max(ymax, t.y);
    }
    x0_ = xmin, y0_ = ymin;
    nx_ = static_cast<int>((xmax - xmin) / cell_) + 1;
    ny_ = static_cast<int>((ymax - ymin) / cell_) + 1;
    std::vector<std::uint32_t> count(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
    auto cellOf = [&](const Vec3& p) {
        return static_cast<std::size_t>((p.x() - x0_) / cell_) * ny_ + static_cast<std::size_t>((p.y() - y0_) / cell_);
    };
    for (const auto& t : trees_) ++count[cellOf(t.foot) + 1];
    for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
    cellStart_ = count;
    cellTrees_.resize(trees_.size());
    for (std::uint32_t i = 0; i < trees_.size(); ++i) cellTrees_[count[cellOf(trees_[i].foot)]++] = i;
}

void TreeField::near(double x, double y, double radius, std::vector<std::uint32_t>& out) const {
    if (trees_.empty()) return;
    const int i0 = std::max(0, static_cast<int>(std::floor((x - radius - x0_) / cell_)));
    const int i1 = std::min(nx_ - 1, static_cast<int>(std::floor((x + radius - x0_) / cell_)));
    const int j0 = std::max(0, static_cast<int>(std::floor((y - radius - y0_) / cell_)));
    const int j1 = std::min(ny_ - 1, static_cast<int>(std::floor((y + radius - y0_) / cell_)));
    for (int i = i0; i <= i1; ++i)
        for (int j = j0; j <= j1; ++j) {
            const std::size_t c = static_cast<std::size_t>(i) * ny_ + j;
            for (std::uint32_t k = cellStart_[c]; k < cellStart_[c + 1]; ++k) {
                const Vec3& f = trees_[cellTrees_[k]].foot;
                if ((f.x() - x) * (f.x() - x) + (f.y() - y) * (f.y() - y) <= radius * radius) out.push_back(cellTrees_[k]);
            }
        }
}

}  // namespace sylva::dem

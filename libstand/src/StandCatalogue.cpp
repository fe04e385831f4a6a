#include "libstand/StandCatalogue.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "libcommon/InputError.hpp"

namespace sylva::stand {

StandCatalogue::StandCatalogue(const Inventory& inventory, const std::string& stemsSource) : name_(inventory.name) {
    if (inventory.stems.empty()) throw InputError(stemsSource, 0, "the inventory has no stem: nothing to resample");

    // std::map keeps the stools in id order, so the catalogue (and every forest drawn from it)
    // does not depend on hash-table order. A stool is its id within its plot (inventories often
    // number the stools of each plot from 1); keyed by id first, the order of stools with ids unique
    // in the stand, and so every forest of a seed, is the one keyed by id alone gave.
    std::map<std::pair<std::string, std::string>, std::vector<const Stem*>> stemsOfStool;
    for (const Stem& s : inventory.stems) {
        // Virtual forests are made of the stems a block meets: a stem below breast height is left
        // out (the inventory's warnings count them); one whose DBH was not measured cannot be drawn.
        if (s.dbhCm == 0) continue;
        if (!measured(s))
            throw InputError(stemsSource, s.line,
                             "stem '" + s.id + "' has no DBH: virtual forests need every stem's diameter (give it, "
                             "or 0 for a stem below breast height, which is left out)");
        const StemTemplate t{s.dbhCm, s.species};
        all_.push_back(t);
        maxDbhCm_ = std::max(maxDbhCm_, s.dbhCm);
        if (!s.stool) {
            singles_.push_back(t);
            continue;
        }
        stemsOfStool[{*s.stool, s.plot}].push_back(&s);
    }

    for (const auto& [id, members] : stemsOfStool) {
        Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
        for (const Stem* s : members) centroid += Eigen::Vector2d(s->x, s->y);
        centroid /= static_cast<double>(members.size());
        StoolTemplate stool;
        for (const Stem* s : members) {
            stool.offsets.push_back(Eigen::Vector2d(s->x, s->y) - centroid);
            stool.stems.push_back({s->dbhCm, s->species});
        }
        stools_.push_back(std::move(stool));
    }

    if (all_.empty()) throw InputError(stemsSource, 0, "every stem is below breast height (DBH 0): nothing to resample");
    const double areaHa = inventory.areaHa();
    stemsPerHa_ = static_cast<double>(all_.size()) / areaHa;
    stoolsPerHa_ = static_cast<double>(stools_.size()) / areaHa;
    stoolStemShare_ = static_cast<double>(all_.size() - singles_.size()) / static_cast<double>(all_.size());
}

}  // namespace sylva::stand

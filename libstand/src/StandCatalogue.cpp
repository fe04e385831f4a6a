#include "libstand/StandCatalogue.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "libcommon/InputError.hpp"

namespace sylva::stand {

namespace {

const double kPi = std::acos(-1.0);
// Inventories often give a coppice stool's position to each of its stems. Stems recorded this close
// share one position: a virtual forest rounds positions to the millimetre, and two stems at one
// place would start inside each other (simulate refuses such a forest).
constexpr double kSharedPosition = 0.01;  // m

// A stool's stems that share a position stand on a ring around it, in the inventory's order, each
// next to the next touching at breast height: the ring's chord 2 R sin(pi / k) is the largest
// stem's diameter, so no two of them overlap more than fused coppice stems do at their base.
void standApart(const std::vector<const Stem*>& members, std::vector<Eigen::Vector2d>& position) {
    std::vector<bool> placed(members.size(), false);
    for (std::size_t first = 0; first < members.size(); ++first) {
        if (placed[first]) continue;
        std::vector<std::size_t> group{first};
        for (std::size_t j = first + 1; j < members.size(); ++j)
            if (!placed[j] && (position[j] - position[first]).norm() < kSharedPosition) group.push_back(j);
        if (group.size() < 2) continue;
        double widest = 0;
        for (const std::size_t i : group) widest = std::max(widest, members[i]->dbhCm / 100);
        const double k = static_cast<double>(group.size());
        const double radius = 0.5 * widest / std::sin(kPi / k);
        const Eigen::Vector2d centre = position[first];
        for (std::size_t m = 0; m < group.size(); ++m) {
            const double angle = 2 * kPi * static_cast<double>(m) / k;
            position[group[m]] = centre + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle));
            placed[group[m]] = true;
        }
    }
}

}  // namespace

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
        std::vector<Eigen::Vector2d> position;
        for (const Stem* s : members) position.emplace_back(s->x, s->y);
        standApart(members, position);
        Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
        for (const Eigen::Vector2d& p : position) centroid += p;
        centroid /= static_cast<double>(members.size());
        StoolTemplate stool;
        for (std::size_t i = 0; i < members.size(); ++i) {
            stool.offsets.push_back(position[i] - centroid);
            stool.stems.push_back({members[i]->dbhCm, members[i]->species});
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

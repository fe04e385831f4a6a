#pragma once
// What the forest generator resamples from an inventory (paper Sect. 2.2.2): its coppice stools
// (stem offsets from the stool centroid, diameters, species), its single trees, all its stems, and
// the densities (per hectare) that set how many of each a virtual forest gets.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "libstand/Inventory.hpp"

namespace sylva::stand {

struct StemTemplate {
    double dbhCm = 0;
    std::string species;
};

struct StoolTemplate {
    // m, stem position minus the stool centroid (mean of its stems); stems the inventory gives one
    // position (within 1 cm) stand on a ring around it, touching at breast height
    std::vector<Eigen::Vector2d> offsets;
    std::vector<StemTemplate> stems;       // same order as offsets
};

class StandCatalogue {
public:
    // Throws InputError (naming stemsSource and the line) if the inventory has no stem or a stool
    // has stems in two different plots (its geometry would be meaningless: plots have own frames).
    StandCatalogue(const Inventory& inventory, const std::string& stemsSource);

    const std::string& name() const { return name_; }
    double stemsPerHa() const { return stemsPerHa_; }
    double stoolsPerHa() const { return stoolsPerHa_; }
    // Share of the inventory's stems that belong to a stool, in [0, 1].
    double stoolStemShare() const { return stoolStemShare_; }
    double maxDbhCm() const { return maxDbhCm_; }

    const std::vector<StoolTemplate>& stools() const { return stools_; }
    const std::vector<StemTemplate>& singles() const { return singles_; }
    const std::vector<StemTemplate>& allStems() const { return all_; }

private:
    std::string name_;
    double stemsPerHa_ = 0, stoolsPerHa_ = 0, stoolStemShare_ = 0, maxDbhCm_ = 0;
    std::vector<StoolTemplate> stools_;
    std::vector<StemTemplate> singles_, all_;
};

}  // namespace sylva::stand

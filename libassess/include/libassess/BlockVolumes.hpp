#pragma once
// A block-volume distribution for a hazard map: classes of volumes with their weights, and the scene
// of each class (the scene's block at that volume, its shape kept) a run draws its block from.
#include <string>
#include <vector>

#include "libdem/Scene.hpp"

namespace sylva::assess {

// One class of a block-volume distribution: blocks of this volume (the scene's shape scaled) are
// released with probability weight / (sum of the weights).
struct BlockVolumeClass {
    double volumeM3 = 0;
    double weight = 1;
};
// "0.5,1,2" (equally likely) or "0.5:6,1:3,2:1" (volume:weight). InputError on a volume outside
// (0, 1000] m3, a weight <= 0, or text that is not such a list.
std::vector<BlockVolumeClass> parseBlockVolumes(const std::string& text);

// The scene of each class (the scene itself without classes) and where each class ends on [0, 1].
class BlockVolumeScenes {
public:
    BlockVolumeScenes(const dem::Scene& scene, const std::vector<BlockVolumeClass>& classes);
    std::size_t classes() const { return scenes_.size(); }
    const dem::Scene& scene(std::size_t k) const { return *scenes_[k]; }
    // The class of a uniform draw u in [0, 1).
    std::size_t of(double u) const;

private:
    std::vector<dem::Scene> resized_;  // a scene per class, sharing the soil bed
    std::vector<const dem::Scene*> scenes_;
    std::vector<double> upTo_;
};

}  // namespace sylva::assess

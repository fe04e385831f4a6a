#pragma once
// A scene built from its configuration: the soil bed, the block's shape and the contact laws.
// Built once and shared, read-only, by every run (and every thread) of a campaign.
#include <memory>

#include "libdem/ContactLawTable.hpp"
#include "libdem/ElevationGrid.hpp"
#include "libdem/SceneConfig.hpp"
#include "libdem/SoilZones.hpp"
#include "libdem/TreeField.hpp"
#include "libstand/Forest.hpp"

namespace sylva::dem {

class Scene {
public:
    // Throws InputError on an unusable terrain, block or forest. The forest is the one of
    // config.forestFile if that is set, else `forest` (coordinates as in the terrain's frame).
    explicit Scene(SceneConfig config, stand::Forest forest = {});
    // The terrain is `dtm` (read by the caller, e.g. through GDAL); the configuration must name
    // no terrain file (InputError otherwise).
    Scene(SceneConfig config, const ElevationGrid& dtm, stand::Forest forest = {});

    const SceneConfig& config() const { return config_; }
    const SoilBed& soil() const { return *soil_; }
    const RigidBody& blockTemplate() const { return block_; }
    const ContactLawTable& laws() const { return laws_; }
    const stand::Forest& forest() const { return forest_; }
    bool forested() const { return !forest_.trees.empty(); }
    const TreeField& trees() const { return trees_; }
    // The same scene with other lumped-model parameters (the soil bed is shared, not rebuilt).
    Scene withLumped(const LumpedParams& params) const;
    // The same scene with a block of another volume and the same shape (a cuboid's edges scaled
    // alike), its contact laws set for the new mass; the soil bed is shared. InputError if volumeM3 <= 0.
    Scene withBlockVolume(double volumeM3) const;
    // The same scene on a soil map: the block/soil and stem/soil contacts take the parameters of
    // the zone under them (SoilZones.hpp) instead of the scene's [soil]. InputError for a zone's
    // unusable parameters.
    Scene withSoilZones(std::shared_ptr<const SoilZones> zones) const;
    const SoilZones* soilZones() const { return soilZones_.get(); }

private:
    Scene(SceneConfig config, std::shared_ptr<const SoilBed> soil, stand::Forest forest);
    void setContactLaws();
    SceneConfig config_;
    std::shared_ptr<const SoilBed> soil_;
    RigidBody block_;
    ContactLawTable laws_;
    stand::Forest forest_;
    TreeField trees_;
    std::shared_ptr<const SoilZones> soilZones_;  // none: the scene's [soil] everywhere
};

}  // namespace sylva::dem

#pragma once
// A scene built from its configuration: the soil bed, the block's shape and the contact laws.
// Built once and shared, read-only, by every run (and every thread) of a campaign.
#include <memory>

#include "libdem/ContactLawTable.hpp"
#include "libdem/SceneConfig.hpp"

namespace sylva::dem {

class Scene {
public:
    explicit Scene(SceneConfig config);  // throws InputError on an unusable terrain or block

    const SceneConfig& config() const { return config_; }
    const SoilBed& soil() const { return *soil_; }
    const RigidBody& blockTemplate() const { return block_; }
    const ContactLawTable& laws() const { return laws_; }

private:
    SceneConfig config_;
    std::shared_ptr<const SoilBed> soil_;
    RigidBody block_;
    ContactLawTable laws_;
};

}  // namespace sylva::dem

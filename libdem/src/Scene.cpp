#include "libdem/Scene.hpp"

#include "libstand/InputError.hpp"

namespace sylva::dem {

namespace {
std::shared_ptr<const SoilBed> buildSoil(const TerrainConfig& t) {
    if (t.profile.empty() == t.dtm.empty())
        throw InputError("the scene needs exactly one of terrain.profile or terrain.dtm");
    if (!t.profile.empty()) return std::make_shared<SoilBed>(SoilBed::fromProfile(SlopeProfile::readCsv(t.profile), t.soil));
    return std::make_shared<SoilBed>(SoilBed::fromGrid(ElevationGrid::readAsc(t.dtm), t.soil));
}
}  // namespace

Scene::Scene(SceneConfig config, stand::Forest forest)
    : config_(std::move(config)),
      soil_(buildSoil(config_.terrain)),
      block_(makeBlock(config_.block)),
      forest_(config_.forestFile.empty() ? std::move(forest) : stand::readForestCsv(config_.forestFile)) {
    // Forest runs release across the slope (Sect. 2.3.2: Y uniform in [80, 120] m) unless the scene
    // says otherwise.
    if (!forest_.trees.empty() && !config_.release.yRangeGiven) {
        config_.release.yMin = config_.release.forestYMin;
        config_.release.yMax = config_.release.forestYMax;
    }
    laws_.set(BodyKind::Block, BodyKind::Soil, std::make_shared<SoilContact>(config_.soilContact, block_.mass()));
}

}  // namespace sylva::dem

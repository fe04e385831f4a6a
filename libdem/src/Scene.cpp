#include "libdem/Scene.hpp"

#include <cmath>

#include "libstand/Allometry.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::dem {

namespace {
stand::Forest singleTree(const SingleTreeConfig& t) {
    stand::Tree tree;
    tree.id = 1;
    tree.x = t.x;
    tree.y = t.y;
    tree.dbhCm = t.dbhCm;
    tree.species = "beech";
    if (t.coppice) tree.stool = 1;
    tree.heightM = stand::treeHeightM(t.dbhCm);
    tree.crownLengthM = stand::crownLengthM(tree.heightM);
    tree.crownMassKg = stand::crownMassKg(t.dbhCm);
    return stand::Forest{{tree}, {}};  // no source file: a tree of the scene's keys
}

stand::Forest chooseForest(const SceneConfig& c, stand::Forest given) {
    if (c.tree.enabled) {
        // A forest given as well would be dropped without a word (and assess or hazard would run
        // their forests as this one tree).
        if (!c.forestFile.empty() || !given.trees.empty())
            throw InputError(c.sourceFile, 0, "the scene places a single tree ([tree]): a forest (forest.file, --forest, "
                                              "--stand, --trees) does not apply to it; use a scene without [tree] for a forest");
        return singleTree(c.tree);
    }
    if (!c.forestFile.empty()) {
        stand::Forest f = stand::readForestCsv(c.forestFile);
        // Run as bare ground, a header-only file would pass for a forest that stopped nothing.
        if (f.trees.empty()) throw InputError(c.forestFile, 0, "no stem in the forest file (to run without forest, leave out forest.file or --forest)");
        return f;
    }
    return given;
}

// The soil bed on a DTM, with the micro-topography the scene asks for (its seed the bed's).
std::shared_ptr<const SoilBed> bedOnGrid(const TerrainConfig& t, const ElevationGrid& dtm) {
    MicroTopographyParams micro = t.micro;
    micro.seed = t.soil.seed;
    return std::make_shared<SoilBed>(SoilBed::fromGrid(withMicroTopography(dtm, micro), t.soil));
}
std::shared_ptr<const SoilBed> buildSoil(const SceneConfig& c) {
    const TerrainConfig& t = c.terrain;
    if (t.profile.empty() == t.dtm.empty())
        throw InputError(c.sourceFile, 0, t.profile.empty() ? "the scene names no terrain: give terrain.profile (a slope profile CSV) or terrain.dtm (a DTM)"
                                                            : "the scene names two terrains (terrain.profile and terrain.dtm): give one");
    if (!t.profile.empty()) {
        if (t.micro.sigma > 0)
            throw InputError(c.sourceFile, 0, "terrain.microtopography_m is added to DTMs; a profile carries its own (data/slopes/make_standin.py --sigma)");
        return std::make_shared<SoilBed>(SoilBed::fromProfile(SlopeProfile::readCsv(t.profile), t.soil));
    }
    return bedOnGrid(t, ElevationGrid::readAsc(t.dtm));
}
std::shared_ptr<const SoilBed> soilOn(const SceneConfig& c, const ElevationGrid& dtm) {
    const TerrainConfig& t = c.terrain;
    if (!t.profile.empty() || !t.dtm.empty())
        throw InputError(c.sourceFile, 0, "the scene names a terrain (" + (t.profile.empty() ? t.dtm : t.profile) + ") and another DTM is given: give one terrain");
    return bedOnGrid(t, dtm);
}
}  // namespace

Scene::Scene(SceneConfig config, stand::Forest forest) : Scene(config, buildSoil(config), std::move(forest)) {}

Scene::Scene(SceneConfig config, const ElevationGrid& dtm, stand::Forest forest)
    : Scene(config, soilOn(config, dtm), std::move(forest)) {}

Scene::Scene(SceneConfig config, std::shared_ptr<const SoilBed> soil, stand::Forest forest)
    : config_(std::move(config)),
      soil_(std::move(soil)),
      block_(makeBlock(config_.block)),
      forest_(chooseForest(config_, std::move(forest))) {
    // Forest runs release across the slope (Sect. 2.3.2: Y uniform in [80, 120] m) unless the scene
    // says otherwise.
    if (!forest_.trees.empty() && !config_.release.yRangeGiven) {
        config_.release.yMin = config_.release.forestYMin;
        config_.release.yMax = config_.release.forestYMax;
    }
    if (!forest_.trees.empty()) trees_ = TreeField(forest_, *soil_, config_.stem.tipDiameter);
    setContactLaws();
}

// The soil's law takes the block's mass (its dashpot, Eq. 16): set again when the block changes.
void Scene::setContactLaws() {
    const auto soilLaw = [this]() -> std::shared_ptr<const ContactLaw> {
        if (soilZones_) return std::make_shared<ZonedSoilContact>(soilZones_, block_.mass());
        return std::make_shared<SoilContact>(config_.soilContact, block_.mass());
    };
    laws_.set(BodyKind::Block, BodyKind::Soil, soilLaw());
    if (!forest_.trees.empty()) {
        laws_.set(BodyKind::Block, BodyKind::Stem, std::make_shared<BlockStemContact>(config_.stemContact));
        laws_.set(BodyKind::Stem, BodyKind::Stem, std::make_shared<StemStemContact>(config_.stemContact));
        // Stems and broken pieces on the ground: the soil's law as under the block, its dashpot a
        // fraction of the critical one of each stem node (Eq. 16 with the node's mass,
        // ContactGeometry::movingMass), so that falling pieces lose energy on landing as a block does.
        laws_.set(BodyKind::Stem, BodyKind::Soil, soilLaw());
    }
}

Scene Scene::withLumped(const LumpedParams& params) const {
    Scene s(*this);
    s.config_.lumped = params;
    return s;
}

Scene Scene::withSoilZones(std::shared_ptr<const SoilZones> zones) const {
    Scene s(*this);
    s.soilZones_ = std::move(zones);
    s.setContactLaws();
    return s;
}

Scene Scene::withBlockVolume(double volumeM3) const {
    if (!(volumeM3 > 0)) throw InputError("a block volume of " + readableNumber(volumeM3) + " m3: it must be positive");
    Scene s(*this);
    BlockSpec& b = s.config_.block;
    if (b.shape == BlockShapeKind::Cuboid) {
        const double scale = std::cbrt(volumeM3 / (b.d1 * b.d2 * b.d3));
        b.d1 *= scale;
        b.d2 *= scale;
        b.d3 *= scale;
    }
    b.volumeM3 = volumeM3;
    s.block_ = makeBlock(b);
    s.setContactLaws();
    return s;
}

}  // namespace sylva::dem

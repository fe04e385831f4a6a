// Scene files: Table 2 defaults, overrides, and clear errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "libdem/SceneConfig.hpp"
#include "libstand/InputError.hpp"

using namespace sylva::dem;

namespace {
std::string writeScene(const std::string& name, const std::string& text) {
    const auto dir = std::filesystem::temp_directory_path() / "sylvarock-tests";
    std::filesystem::create_directories(dir);
    const auto path = dir / name;
    std::ofstream(path) << text;
    return path.string();
}
}  // namespace

TEST(SceneConfigParser, DefaultsAreTable2) {
    const SceneConfig c = sceneFromOverrides({});
    EXPECT_EQ(c.soilContact.kn, 1e6);
    EXPECT_EQ(c.soilContact.kappa, 0.05);
    EXPECT_EQ(c.soilContact.dampingRatio, 0.54);
    EXPECT_EQ(c.soilContact.frictionDeg, 30);
    EXPECT_EQ(c.block.volumeM3, 0.5);
    EXPECT_EQ(c.block.densityKgM3, 2700);
    EXPECT_EQ(c.terrain.soil.radius, 0.7);
    EXPECT_EQ(c.terrain.soil.roughness, 0.1);
    EXPECT_EQ(c.release.fallHeight, 5);
}

TEST(SceneConfigParser, OverridesWinAndPathsAreRelativeToTheSceneFile) {
    const std::string path = writeScene("s1.ini", "[terrain]\nprofile = slope.csv\n[soil]\nfriction_deg = 25\n");
    const SceneConfig c = loadScene(path, {"soil.friction_deg=35", "soil.restitution=0.3", "block.shape=sphere"});
    EXPECT_EQ(c.soilContact.frictionDeg, 35);
    EXPECT_NEAR(c.soilContact.dampingRatio, dampingRatioFromRestitution(0.3), 1e-12);
    EXPECT_EQ(c.block.shape, BlockShapeKind::Sphere);
    EXPECT_EQ(c.terrain.profile, (std::filesystem::path(path).parent_path() / "slope.csv").string());
}

TEST(SceneConfigParser, BadInputNamesTheFileAndTheKey) {
    const std::string path = writeScene("bad.ini", "[soil]\nfriction = 25\n");
    try {
        loadScene(path);
        FAIL() << "unknown key accepted";
    } catch (const sylva::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("bad.ini"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("soil.friction"), std::string::npos);
    }
    EXPECT_THROW(loadScene(writeScene("bad2.ini", "[soil]\nkn_n_m = stiff\n")), sylva::InputError);
    EXPECT_THROW(sceneFromOverrides({"block.shape=pyramid"}), sylva::InputError);
    EXPECT_THROW(sceneFromOverrides({"soil.restitution=1.5"}), sylva::InputError);
    EXPECT_THROW(sceneFromOverrides({"integration.safety=0"}), sylva::InputError);
    EXPECT_THROW(sceneFromOverrides({"noequals"}), sylva::InputError);
    EXPECT_THROW(loadScene("/nonexistent/scene.ini"), sylva::InputError);
}

// Scene files: Table 2 defaults, overrides, and clear errors.
#include <gtest/gtest.h>
#include <cmath>

#include <filesystem>
#include <fstream>
#include <tuple>

#include "libdem/Scene.hpp"
#include "libdem/SceneConfig.hpp"
#include "libcommon/InputError.hpp"

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
    // An unknown key, and a key given twice, are named at their line (the second one's for a repeat).
    const std::string path = writeScene("bad.ini", "# a scene\n[soil]\nfriction = 25\n");
    try {
        loadScene(path);
        FAIL() << "unknown key accepted";
    } catch (const sylva::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("bad.ini:3:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("soil.friction"), std::string::npos);
    }
    try {
        loadScene(writeScene("twice.ini", "[soil]\nfriction_deg = 25\n\n[block]\nshape = cube\n[soil]\nfriction_deg = 30\n"));
        FAIL() << "a key given twice accepted";
    } catch (const sylva::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("twice.ini:7:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("soil.friction_deg"), std::string::npos) << e.what();
    }
    EXPECT_THROW(loadScene(writeScene("bad2.ini", "[soil]\nkn_n_m = stiff\n")), sylva::InputError);
    EXPECT_THROW(sceneFromOverrides({"block.shape=pyramid"}), sylva::InputError);
    EXPECT_THROW(sceneFromOverrides({"soil.restitution=1.5"}), sylva::InputError);
    EXPECT_THROW(sceneFromOverrides({"integration.safety=0"}), sylva::InputError);
    EXPECT_THROW(sceneFromOverrides({"noequals"}), sylva::InputError);
    EXPECT_THROW(loadScene("/nonexistent/scene.ini"), sylva::InputError);
}

// A byte-order mark (some Windows editors write one) is not a line of the file; a line that is no
// key = value is named by its number; a folder is not a scene.
TEST(SceneConfigParser, ByteOrderMarkIsReadAndABadLineOrAFolderIsNamed) {
    const std::string bom = writeScene("bom.ini", "\xEF\xBB\xBF[soil]\nfriction_deg = 25\n");
    EXPECT_EQ(loadScene(bom).soilContact.frictionDeg, 25);
    // Lines ended by a carriage return alone (old Mac editors) were one line: the scene named no terrain.
    EXPECT_EQ(loadScene(writeScene("cr.ini", "[soil]\rfriction_deg = 27\r[block]\rvolume_m3 = 0.7\r")).soilContact.frictionDeg, 27);
    try {
        loadScene(writeScene("cr_junk.ini", "[soil]\rfriction_deg = 25\rthis is junk\r"));
        FAIL() << "a line without '=' was accepted";
    } catch (const sylva::InputError& e) {
        EXPECT_EQ(e.line(), 3) << e.what();
    }
    try {
        loadScene(writeScene("junk.ini", "[soil]\nfriction_deg = 25\nthis is junk\n"));
        FAIL() << "a line without '=' was accepted";
    } catch (const sylva::InputError& e) {
        EXPECT_EQ(e.line(), 3) << e.what();
        EXPECT_NE(std::string(e.what()).find("'this is junk'"), std::string::npos) << e.what();
    }
    const std::string folder = std::filesystem::path(bom).parent_path().string();
    try {
        loadScene(folder);
        FAIL() << "a folder was read as a scene";
    } catch (const sylva::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("is a folder, not a scene file"), std::string::npos) << e.what();
    }
}

// Found by tests/fuzz/fuzz_scene: Boost's message for a key holding '%canonical_option%' never came
// back (its placeholder substitution loops); the message now comes, with the key as typed.
TEST(SceneConfigParser, PercentInAKeyGivesItsMessageInsteadOfHanging) {
    const std::string path = writeScene("percent.ini", "[terrain]\nprofi%canonical_option%le = x.csv\n");
    try {
        loadScene(path);
        FAIL() << "an unknown key was accepted";
    } catch (const sylva::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("terrain.profi(%)canonical_option(%)le"), std::string::npos) << e.what();
    }
    EXPECT_THROW(sceneFromOverrides({"soil.bogus%value%=1"}), sylva::InputError);
}

// The stem's damping law is chosen by name; the calibrated set's is the default, the paper's in toe2018.
TEST(SceneConfigParser, StemDampingIsNamed) {
    EXPECT_EQ(sceneFromOverrides({}).stem.bending.damping, StemDamping::ConstantLoss);
    EXPECT_EQ(sceneFromOverrides({"stem.parameters=toe2018"}).stem.bending.damping, StemDamping::Viscous);
    const SceneConfig c = sceneFromOverrides({"stem.parameters=toe2018", "stem.damping=constant_loss", "stem.loss_factor=0.015"});
    EXPECT_EQ(c.stem.bending.damping, StemDamping::ConstantLoss);
    EXPECT_EQ(c.stem.bending.lossFactor, 0.015);
    try {
        sceneFromOverrides({"stem.damping=hysteretic"});
        FAIL() << "unknown damping accepted";
    } catch (const sylva::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("stem.damping"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("hysteretic"), std::string::npos);
    }
    EXPECT_THROW(sceneFromOverrides({"stem.loss_factor=2"}), sylva::InputError);
}

// A named set gives the defaults of every stem.* and tree_contact.* key; single keys still change
// them, and a file's stem.parameters is refused with its line when unknown.
TEST(SceneConfigParser, StemParameterSetsAreNamed) {
    const SceneConfig paper = sceneFromOverrides({"stem.parameters=toe2018"});
    EXPECT_EQ(paper.stemParameters, "toe2018");
    EXPECT_EQ(paper.stem.bending.sections, 1);
    EXPECT_EQ(paper.stem.root.anchorage, RootAnchorage::Fixed);
    EXPECT_EQ(paper.stem.root.yieldMoment, 200e3);  // Table 2
    EXPECT_EQ(paper.stemContact.crushingStrength, 0.0);
    EXPECT_TRUE(std::isinf(paper.stem.root.failureRotation));
    const SceneConfig calibrated = sceneFromOverrides({});
    EXPECT_EQ(calibrated.stemParameters, "calibrated");
    EXPECT_EQ(calibrated.stem.bending.sections, 3);
    EXPECT_EQ(calibrated.stem.root.anchorage, RootAnchorage::StemWeight);
    EXPECT_GT(calibrated.stemContact.crushingStrength, 0.0);
    EXPECT_TRUE(std::isfinite(calibrated.stem.root.failureRotation));
    const SceneConfig changed = sceneFromOverrides({"stem.parameters=toe2018", "stem.sections=5", "stem.root_failure_rotation_deg=30"});
    EXPECT_EQ(changed.stem.bending.sections, 5);
    EXPECT_NEAR(changed.stem.root.failureRotation, 30 * std::acos(-1.0) / 180, 1e-12);
    EXPECT_EQ(changed.stem.bending.damping, StemDamping::Viscous);
    try {
        loadScene(writeScene("set.ini", "[terrain]\nwidth_m = 10\n[stem]\nparameters = toe2019\n"));
        FAIL() << "unknown parameter set accepted";
    } catch (const sylva::InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("set.ini"), std::string::npos) << what;
        EXPECT_NE(what.find(":4"), std::string::npos) << what;
        EXPECT_NE(what.find("toe2019"), std::string::npos) << what;
    }
    EXPECT_THROW(sceneFromOverrides({"stem.root_failure_rotation_deg=-5"}), sylva::InputError);
}

// The fracture energy is an option: none in either set, and a value typed in the wrong unit (sigma_Rupt's
// Pa) is refused with the likely mistake.
TEST(SceneConfigParser, TheFractureEnergyIsOffByDefaultAndReadInJoulesPerSquareMetre) {
    EXPECT_EQ(sceneFromOverrides({}).stem.bending.fractureEnergy, 0.0);
    EXPECT_EQ(sceneFromOverrides({"stem.parameters=toe2018"}).stem.bending.fractureEnergy, 0.0);
    EXPECT_EQ(sceneFromOverrides({"stem.fracture_energy_j_m2=5e4"}).stem.bending.fractureEnergy, 5e4);
    EXPECT_THROW(sceneFromOverrides({"stem.fracture_energy_j_m2=-1"}), sylva::InputError);
    try {
        sceneFromOverrides({"stem.fracture_energy_j_m2=94e6"});
        FAIL() << "a strength in Pa accepted as a fracture energy";
    } catch (const sylva::InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("stem.fracture_energy_j_m2"), std::string::npos) << what;
        EXPECT_NE(what.find("a strength in Pa typed for an energy"), std::string::npos) << what;
    }
}

namespace {
std::string refusal(const std::vector<std::string>& overrides) {
    try {
        sceneFromOverrides(overrides);
    } catch (const sylva::InputError& e) {
        return e.what();
    }
    return {};
}

// The same for a scene file and its --set keys.
std::string fileRefusal(const std::string& path, const std::vector<std::string>& overrides = {}) {
    try {
        loadScene(path, overrides);
    } catch (const sylva::InputError& e) {
        return e.what();
    }
    return {};
}
}  // namespace

// The calibrated set's foot zone is 1 m, or the node spacing where the scene sets one coarser (a
// zone shorter than the spacing has no connection of its own); toe2018 has none; a zone the scene
// sets shorter than the spacing is refused with its key, its file and its line.
TEST(SceneConfigParser, TheFootZoneIsTheCalibratedSetsAndGrowsToACoarserSpacing) {
    EXPECT_EQ(sceneFromOverrides({}).stem.footZone, 1.0);
    EXPECT_EQ(sceneFromOverrides({"stem.node_spacing_m=2"}).stem.footZone, 2.0);
    EXPECT_EQ(sceneFromOverrides({"stem.node_spacing_m=0.25"}).stem.footZone, 1.0);
    EXPECT_EQ(sceneFromOverrides({"stem.parameters=toe2018", "stem.node_spacing_m=2"}).stem.footZone, 0.0);
    EXPECT_EQ(sceneFromOverrides({"stem.foot_zone_m=0", "stem.node_spacing_m=2"}).stem.footZone, 0.0);
    const std::string set = refusal({"stem.foot_zone_m=1", "stem.node_spacing_m=2"});
    EXPECT_NE(set.find("--set stem.foot_zone_m"), std::string::npos) << set;
    const std::string file = fileRefusal(writeScene("zone.ini", "[terrain]\nwidth_m = 10\n[stem]\nnode_spacing_m = 2\nfoot_zone_m = 1\n"));
    EXPECT_NE(file.find("zone.ini:5"), std::string::npos) << file;
    EXPECT_NE(file.find("stem.foot_zone_m"), std::string::npos) << file;
}

// NaN and infinities parse as numbers; none may reach the simulator (issue 13: a NaN wake margin
// silently switched the forest off, an infinite block volume ran out of memory).
TEST(SceneConfigParser, EveryNumberRefusesNanAndInfinityNamingItsKey) {
    const std::vector<std::string> keys = sceneNumberKeys();
    ASSERT_GT(keys.size(), 50u);
    // The one key whose help gives inf a meaning ("never") accepts it, and only it.
    const std::string never = "stem.root_failure_rotation_deg";
    EXPECT_EQ(refusal({never + "=inf"}), "");
    for (const std::string& key : keys)
        for (const char* bad : {"nan", "inf", "-inf"}) {
            if (key == never && std::string(bad) == "inf") continue;
            const std::string what = refusal({key + "=" + bad});
            EXPECT_NE(what.find(key), std::string::npos) << key << "=" << bad << " accepted or unnamed: " << what;
            EXPECT_NE(what.find("not a finite number"), std::string::npos) << what;
        }
}

TEST(SceneConfigParser, AbsurdValuesAreRefusedWithTheirRangeAndLikelyCause) {
    const std::string density = refusal({"block.density_kg_m3=2.7"});
    EXPECT_NE(density.find("block.density_kg_m3 = 2.7"), std::string::npos) << density;
    EXPECT_NE(density.find("kg/m^3"), std::string::npos) << density;
    EXPECT_NE(density.find("t/m^3 typed as kg/m^3"), std::string::npos) << density;
    EXPECT_NE(refusal({"block.shape=cuboid", "block.d1_m=1000", "block.d2_m=800", "block.d3_m=600"}).find("mm or cm"),
              std::string::npos);
    EXPECT_NE(refusal({"tree.dbh_cm=250.5e1"}).find("mm"), std::string::npos);
    for (const char* bad : {"forest.wake_margin_m=-1", "tree_contact.friction_block_stem_deg=-1",
                            "tree_contact.friction_block_stem_deg=90", "integration.dt_s=-1", "soil.restitution=1.5",
                            "integration.safety=0", "block.eccentricity=1.5", "terrain.width_m=1e308",
                            "integration.anticipated_contacts=0"})
        EXPECT_FALSE(refusal({bad}).empty()) << bad << " accepted";
    // The ends of each range are values a user may mean.
    for (const char* edge : {"forest.wake_margin_m=0", "tree_contact.friction_block_stem_deg=0", "integration.dt_s=0",
                             "soil.restitution=1", "integration.safety=1", "block.eccentricity=-1"})
        EXPECT_EQ(refusal({edge}), "") << edge;
}

TEST(SceneConfigParser, ARefusedValueInAFileNamesItsLine) {
    const std::string path = writeScene("range.ini", "# a block\n[block]\nshape = cube\ndensity_kg_m3 = 2.7\n");
    try {
        loadScene(path);
        FAIL() << "density 2.7 kg/m^3 accepted";
    } catch (const sylva::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("range.ini:4: block.density_kg_m3 = 2.7"), std::string::npos) << e.what();
    }
    // The same key given by --set is named as such: the file's line is not the culprit.
    try {
        loadScene(path, {"block.density_kg_m3=1"});
        FAIL() << "density 1 kg/m^3 accepted";
    } catch (const sylva::InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("--set block.density_kg_m3 = 1", 0), 0u) << e.what();
    }
}

// Values a unit slip makes plausible-looking, refused by name (they were accepted: a crushing strength
// of 3.7 Pa let the block through the tree, a warning level of 5 meant 500 %, a seed of -1 drew
// seed 2^32 - 1's soil, a 20 x 20 x 0.001 m slab asked for 2e10 clump spheres and std::bad_alloc).
TEST(SceneConfigParser, UnitSlipsAreRefusedByName) {
    EXPECT_NE(refusal({"tree_contact.crushing_strength_pa=3.7"}).find("MPa typed as Pa?"), std::string::npos);
    EXPECT_EQ(refusal({"tree_contact.crushing_strength_pa=0"}), "");  // crushing off
    EXPECT_EQ(refusal({"tree_contact.crushing_strength_pa=3.7e6"}), "");
    EXPECT_NE(refusal({"integration.energy_warning=5"}).find("integration.energy_warning"), std::string::npos);
    EXPECT_NE(refusal({"integration.energy_tolerance=10"}).find("integration.energy_tolerance"), std::string::npos);
    EXPECT_NE(refusal({"terrain.seed=-1"}).find("terrain.seed"), std::string::npos);
    EXPECT_NE(refusal({"terrain.seed=4294967296"}).find("outside 0 to 4294967295"), std::string::npos);
    EXPECT_EQ(refusal({"terrain.seed=4294967295"}), "");
    const std::vector<std::string> slab{"block.shape=cuboid", "block.d1_m=20", "block.d2_m=20", "block.d3_m=0.001"};
    EXPECT_NE(refusal(slab).find("the longest edge is 20000 times the shortest"), std::string::npos) << refusal(slab);
    EXPECT_EQ(refusal({"block.shape=cuboid", "block.d1_m=2", "block.d2_m=1", "block.d3_m=0.5"}), "");
    // The excluded lower bound is a value too low: it gets the low side's hint (none), not "cm typed as m?".
    const std::string radius = refusal({"terrain.soil_radius_m=0.01"});
    EXPECT_NE(radius.find("outside (0.01, 10] m"), std::string::npos) << radius;
    EXPECT_EQ(radius.find("cm typed as m"), std::string::npos) << radius;
}

// A key without a section after a sectioned one was read into that section ("unrecognised option
// 'block.gravity_m_s2'"), so --block sphere or --forest F (which add --set keys) broke --set gravity_m_s2.
TEST(SceneConfigParser, AKeyWithoutASectionIsReadWhateverComesBefore) {
    const SceneConfig c = sceneFromOverrides({"block.shape=sphere", "gravity_m_s2=5", "soil.kappa=0.05"});
    EXPECT_DOUBLE_EQ(c.gravity, 5);
    EXPECT_DOUBLE_EQ(c.soilContact.kappa, 0.05);
}


// A key the scene's other choices leave unread was ignored without a word: under the calibrated
// stems (wood's loss factor, anchorage from the stem's weight) --set stem.tau_s changed nothing, nor
// did block.d1_m on a sphere. It is refused naming what it needs; a file's key is let pass when
// --set changed the choice it went with.
TEST(SceneConfigParser, AKeyTheSceneDoesNotReadIsRefusedNotIgnored) {
    const std::string tau = refusal({"stem.tau_s=0.01"});
    EXPECT_EQ(tau.rfind("--set stem.tau_s is not read here", 0), 0u) << tau;
    EXPECT_NE(tau.find("stem.damping = constant_loss (stem.parameters = calibrated)"), std::string::npos) << tau;
    EXPECT_EQ(refusal({"stem.tau_s=0.01", "stem.damping=viscous"}), "");
    EXPECT_EQ(refusal({"stem.tau_s=0.01", "stem.parameters=toe2018"}), "");
    EXPECT_NE(refusal({"stem.loss_factor=0.01", "stem.parameters=toe2018"}).find("stem.loss_factor is not read"), std::string::npos);
    EXPECT_NE(refusal({"stem.root_turning_moment_nm_per_kg=100", "stem.anchorage=fixed"}).find("anchorage is fixed"),
              std::string::npos);
    EXPECT_NE(refusal({"block.shape=sphere", "block.d1_m=1"}).find("a sphere's size is block.volume_m3"), std::string::npos);
    EXPECT_NE(refusal({"block.d2_m=1"}).find("a cube's size is block.volume_m3 or its edge block.d1_m"), std::string::npos);
    EXPECT_EQ(refusal({"block.d1_m=1"}), "");  // a cube's edge
    EXPECT_NE(refusal({"block.shape=cuboid", "block.d1_m=1", "block.d2_m=1", "block.d3_m=0.5", "block.volume_m3=2"})
                  .find("a cuboid's volume is block.d1_m x d2_m x d3_m"),
              std::string::npos);
    EXPECT_NE(refusal({"soil.restitution=0.3", "soil.damping_ratio=0.5"}).find("give one of the two"), std::string::npos);
    // A cube's edge and a volume that disagree (it used to take the edge's 8 m3 without a word); a
    // file's volume gives way to an edge on --set.
    EXPECT_NE(refusal({"block.volume_m3=0.5", "block.d1_m=2"}).find("block.d1_m = 2 sets the cube's size too (8 m3)"), std::string::npos)
        << refusal({"block.volume_m3=0.5", "block.d1_m=2"});
    EXPECT_EQ(refusal({"block.volume_m3=8", "block.d1_m=2"}), "");
    const std::string cube = writeScene("cube.ini", "[block]\nvolume_m3 = 0.5\n");
    EXPECT_NEAR(loadScene(cube, {"block.d1_m=2"}).block.volumeM3, 8, 1e-12);
    const std::string both = writeScene("cube-both.ini", "[block]\nvolume_m3 = 0.5\nd1_m = 2\n");
    EXPECT_NE(fileRefusal(both).find("cube-both.ini:2: block.volume_m3 is not read here"), std::string::npos) << fileRefusal(both);

    // In a file: named by its line, unless --set changed the choice it belonged to.
    const std::string path =
        writeScene("unread.ini", "[soil]\ndamping_ratio = 0.5\n[block]\nshape = cuboid\nd1_m = 1\nd2_m = 1\nd3_m = 0.5\nvolume_m3 = 2\n");
    EXPECT_NE(fileRefusal(path).find("unread.ini:8: block.volume_m3 is not read here"), std::string::npos) << fileRefusal(path);
    EXPECT_NO_THROW(loadScene(path, {"block.shape=sphere"})) << "the file's edges went with its cuboid";
    EXPECT_NO_THROW(loadScene(path, {"block.volume_m3=1", "block.shape=cube", "block.d1_m=1", "soil.restitution=0.4"}))
        << "the file's d2_m, d3_m went with its cuboid, its damping ratio with no restitution";
}

// Refusals that look at a key's text or at two keys named neither the file's line nor --set, and
// those that did name a line blamed the file for a value typed on --set ("scene.ini: terrain.seed").
TEST(SceneConfigParser, EveryRefusalNamesWhereItsKeyWasGiven) {
    const std::string path = writeScene("where.ini", "[block]\nshape = cube\n[release]\ny_min_m = 50\ny_max_m = 40\n");
    const auto refusalOf = [&](const std::vector<std::string>& set) { return fileRefusal(path, set); };
    EXPECT_NE(refusalOf({}).find("where.ini:5: release.y_max_m = 40 is below release.y_min_m = 50"), std::string::npos) << refusalOf({});
    const std::vector<std::string> fine{"release.y_max_m=60"};
    EXPECT_EQ(refusalOf(fine), "");
    for (const std::string bad : {"terrain.seed=-1", "stem.damping=soft", "block.shape=pyramid", "release.orientation=up",
                                   "lumped.soil_type=9", "tree_contact.crushing_strength_pa=3.7"}) {
        std::vector<std::string> set = fine;
        set.push_back(bad);
        const std::string what = refusalOf(set);
        EXPECT_EQ(what.rfind("--set " + bad.substr(0, bad.find('=')), 0), 0u) << bad << ": " << what;
    }
    // Of two keys compared, the one typed on --set is named.
    EXPECT_EQ(refusalOf({"release.y_min_m=70"}).rfind("--set release.y_min_m = 70 is above release.y_max_m = 40", 0), 0u)
        << refusalOf({"release.y_min_m=70"});
    const std::string slab =
        writeScene("slab.ini", "[block]\nshape = cuboid\nd1_m = 1\nd2_m = 1\nd3_m = 0.9\n");
    EXPECT_EQ(fileRefusal(slab, {"block.d1_m=20"}).rfind("--set block.d1_m, d2_m, d3_m: the longest edge", 0), 0u) << fileRefusal(slab, {"block.d1_m=20"});
    EXPECT_NE(fileRefusal(slab, {"block.d1_m=20", "block.d3_m=1"}).find("longest edge is 20 times"), std::string::npos);
    const std::string shape = writeScene("shape.ini", "# a block\n[block]\nshape = pyramid\n");
    EXPECT_NE(fileRefusal(shape).find("shape.ini:3: block.shape"), std::string::npos) << fileRefusal(shape);
}

// An empty scene file (or one with only [block]) is read as Table 2's defaults, which name no
// terrain: the refusal must say which file lacks it, as every other scene refusal does.
TEST(SceneConfigParser, ASceneWithoutATerrainOrWithTwoNamesItsFile) {
    for (const auto& [name, text, says] :
         {std::tuple<const char*, const char*, const char*>{"empty.ini", "", "names no terrain"},
          {"two.ini", "[terrain]\nprofile = a.csv\ndtm = b.asc\n", "two terrains"}}) {
        const std::string path = writeScene(name, text);
        try {
            Scene scene(loadScene(path));
            ADD_FAILURE() << name << ": accepted";
        } catch (const sylva::InputError& e) {
            EXPECT_EQ(e.file(), path) << e.what();
            EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
        }
    }
}

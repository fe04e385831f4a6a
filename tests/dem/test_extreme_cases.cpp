// Stiff and extreme cases (issue 6, item 2): each case either completes with physical results or
// stops with a message naming its cause, never with NaN or energy that grew unnoticed. Short scenes
// (a 40 m slope, flat ground, one tree) so that the whole matrix runs in CI; docs/accuracy.md
// ("Stiff and extreme cases") lists what each case does and which test checks it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <utility>
#include <vector>

#include "DemTestScenes.hpp"
#include "libdem/BlockMotion.hpp"
#include "libdem/Campaign.hpp"
#include "libdem/CampaignSummary.hpp"
#include "libdem/ElevationGrid.hpp"
#include "libdem/SegmentGeometry.hpp"
#include "libdem/SimulationError.hpp"
#include "libdem/SoilZones.hpp"
#include "libdem/Stem.hpp"
#include "libcommon/InputError.hpp"

using namespace sylva::dem;
using namespace sylva::dem::testing;

namespace {

const SceneConfig kDefaults;
const double kWarning = kDefaults.integration.energyWarning;      // 5 %: a run above it is flagged
const double kTolerance = kDefaults.integration.energyTolerance;  // 10 %: growth above it stops a run

// The keys of `keys` plus each default whose key `keys` does not set (a key may be given only once).
std::vector<std::string> withDefaults(std::vector<std::string> keys, const std::vector<std::string>& defaults) {
    for (const auto& d : defaults) {
        const std::string key = d.substr(0, d.find('='));
        if (std::none_of(keys.begin(), keys.end(), [&](const std::string& k) { return k.rfind(key + "=", 0) == 0; }))
            keys.push_back(d);
    }
    return keys;
}

// A block launched at one tree (data/scenes/single-tree.ini: a 25 cm beech, the 0.5 m3 cube at 15 m/s).
SceneConfig singleTree(const std::vector<std::string>& keys) {
    return loadScene(std::string(SYLVAROCK_DATA) + "/scenes/single-tree.ini", withDefaults(keys, {"stop.max_time_s=3"}));
}

// Flat ground, 60 m x 20 m; the block released 5 m above (30, 10).
SceneConfig flatGround(const std::vector<std::string>& keys) {
    return sceneFromOverrides(withDefaults(keys, {"terrain.profile=" + std::string(SYLVAROCK_DATA) + "/slopes/flat.csv",
                                                  "terrain.width_m=20", "release.x_m=30", "release.y_m=10",
                                                  "stop.max_time_s=20"}));
}

// A straight 40 m slope, 20 m wide; the block released 5 m above (5, 10) (also with a forest).
SceneConfig straightSlope(double slopeDeg, const std::vector<std::string>& keys) {
    return straightSlopeScene(slopeDeg, 40, 20, withDefaults(keys, {"release.x_m=5", "release.y_min_m=10", "release.y_max_m=10",
                                                                     "stop.max_time_s=20"}));
}

// A sphere released without spin keeps to the fall line (the only sideways pushes are the bumps).
const std::vector<std::string> kSphere = {"block.shape=sphere", "release.orientation=fixed"};
std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

RunResult run(const SceneConfig& config, const RunOptions& options = {}) {
    const Scene scene(config);
    return simulateBlock(scene, 0, 1, options);
}

std::string forestCsv(const std::string& name, const std::string& rows) {
    const auto dir = std::filesystem::temp_directory_path() / "sylvarock-tests";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / (name + ".csv")).string();
    std::ofstream(path) << "x,y,dbh_cm\n" << rows;
    return path;
}

// What every completed run must give: finite numbers, dissipation that only dissipates, and a budget
// that closes below the warning level (its imbalance is the largest seen over the run).
void expectSound(const RunResult& r, const std::string& what) {
    EXPECT_TRUE(r.stop.allFinite()) << what;
    EXPECT_TRUE(std::isfinite(r.maxSpeed) && std::isfinite(r.runoutAlongSlope)) << what;
    EXPECT_GE(r.energy.contactDamping, 0) << what;
    EXPECT_GE(r.energy.friction, 0) << what;
    EXPECT_LT(r.energy.imbalance, kWarning) << what;
    EXPECT_FALSE(r.energy.flagged) << what;
}

// Dropped on flat ground a block has no source of horizontal motion but its rebounds; even if all of
// its impact speed sqrt(2 g h) were turned sideways, Coulomb friction at phi = 30 deg would stop a
// sliding block within v^2 / (2 g tan phi) = h / tan phi = 8.7 m for h = 5 m (a tumbling cube loses
// more at every face it lands on).
void expectStopsNearWhereItLands(const RunResult& r, const std::string& what) {
    expectSound(r, what);
    EXPECT_EQ(r.reason, StopReason::Rest) << what;
    EXPECT_LT(r.runoutHorizontal, 5.0 / std::tan(M_PI / 6)) << what;
}

template <class Error>
std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "(nothing thrown)";
}

bool mentions(const std::string& message, const std::string& what) { return message.find(what) != std::string::npos; }

}  // namespace

// E_b and E_r x 100 (Eq. 22): the block/stem spring is 100 times stiffer. Its stable step is
// resolved (the step adapts), but a contact's onset, which falls between two steps, loads the spring
// by up to k (v dt)^2 / 2 without work: an error that grows with k dt^2 and shrinks as the step does.
// On the paper's trees (toe2018), whose contact is Eq. 20's spring: the default's crushing caps the
// contact's force whatever its moduli, so there a stiffer spring changes nothing to check.
TEST(ExtremeContacts, StiffStemContactsCloseTheBudgetAsTheStepShrinks) {
    const RunResult table2 = run(singleTree({"stem.parameters=toe2018"}));
    const std::vector<std::string> stiff = {"stem.parameters=toe2018", "tree_contact.er_pa=1.5e11", "tree_contact.eb_pa=8e12"};
    const RunResult coarse = run(singleTree(stiff));
    const RunResult fine = run(singleTree(stiff + std::vector<std::string>{"integration.stem_safety=0.4"}));
    const RunResult finer = run(singleTree(stiff + std::vector<std::string>{"integration.stem_safety=0.2"}));
    std::printf("imbalance: Table 2 %.2e, stiff %.2e, at half the step %.2e, at a quarter %.2e; block after the impact %.0f, %.0f, %.0f, %.0f J\n",
                table2.energy.imbalance, coarse.energy.imbalance, fine.energy.imbalance, finer.energy.imbalance,
                table2.impacts.at(0).energyAfter, coarse.impacts.at(0).energyAfter, fine.impacts.at(0).energyAfter,
                finer.impacts.at(0).energyAfter);
    expectSound(coarse, "stiff");
    expectSound(fine, "stiff, half step");
    expectSound(finer, "stiff, quarter step");
    // The onset error falls 16-fold over a quarter of the step (second order), and it is most of the
    // stiff contact's imbalance: measured 1.8e-2, 1.4e-3, 4.3e-4 (42-fold). At least 16, and no growth
    // on the way: the budget closes as the step shrinks.
    EXPECT_LT(fine.energy.imbalance, coarse.energy.imbalance);
    EXPECT_LT(finer.energy.imbalance, coarse.energy.imbalance / 16);
    // The stem decides the impact: where the block hits it (0.8 m up) the 25 cm stem gives way under
    // 3 E I / h^3 = 1.3e7 N/m in bending and K_Root / h^2 = 1.2e7 N/m on its root, 6e6 N/m in series,
    // 60 times softer than even Table 2's contact (Eq. 22: 3.9e8 N/m); a 100 times stiffer contact
    // changes what the block keeps by a few per cent at most, 10 % bounds it (measured 28 Nov. 2026:
    // Table 2's contact leaves the block 14.2 kJ, the stiff one 2-5 % more at the default step, half of
    // it and a quarter).
    for (const RunResult* r : {&coarse, &fine, &finer}) {
        ASSERT_EQ(r->impacts.size(), 1u);
        EXPECT_TRUE(r->impacts[0].stemBroken);
        EXPECT_NEAR(r->impacts[0].energyAfter, table2.impacts.at(0).energyAfter, 0.1 * table2.impacts.at(0).energyAfter);
    }
}

TEST(ExtremeContacts, StiffSoilStopsTheBlockOnFlatGround) {
    expectStopsNearWhereItLands(run(flatGround({"soil.kn_n_m=1e8"})), "K_n soil x 100");
}

// A 5 cm stem (H_T = 4.85 m): at the default 0.5 m spacing the block breaks it and goes on; at
// 2 m the stem has three connections of 1.6 m.
TEST(ExtremeStems, ThinStemBreaksUnderTheBlock) {
    const RunResult r = run(singleTree({"tree.dbh_cm=5"}));
    expectSound(r, "5 cm stem");
    ASSERT_EQ(r.impacts.size(), 1u);
    EXPECT_TRUE(r.impacts[0].stemBroken);
    // Broken under the block by Fig. 3's rupture, not only at the top by the folded-connection snap.
    EXPECT_LT(r.impacts[0].breakHeight, 0.5 * r.impacts[0].stemHeight);
    // The bar for a single-tree impact (TreeImpact.EnergyBudgetClosesWithinOnePercent).
    EXPECT_LT(r.energy.imbalance, 0.01);
    // Breaking a 5 cm stem takes a few kJ: its foot's rupture moment is sigma_Rupt pi D^3 / 32 =
    // 2.5 kN m (D = 6.5 cm) over a plastic rotation to rupture of 2 (sigma_Rupt - sigma_Elast) l /
    // (E_Plast D) = 0.4 rad, about 1 kJ per connection that yields. All the stem's dissipation stays
    // below 5 % of the 152 kJ the block brings.
    const ForestLedger& f = r.forestEnergy;
    const double stem = f.bendingPlasticity + f.bendingDamping + f.rootPlasticity + f.rupture;
    std::printf("5 cm stem took %.0f J of the block's %.0f J\n", stem, r.impacts[0].energyBefore);
    EXPECT_LT(stem, 0.05 * r.impacts[0].energyBefore);
}

// Its connections would need to turn past pi before Fig. 3 breaks them; they snap once folded at a
// right angle (Stem, kFoldedConnection). The paper's stems (toe2018) are the ones that fold so: the
// calibrated default's sections and crushing never take a connection of this stem past pi/2, so on
// them the test would pass without the snap (without it, toe2018 gains +8.4 MJ in one step).
TEST(ExtremeStems, ThinStemWithCoarseNodesSnapsWhereItFoldsAndKeepsItsBudget) {
    const RunResult r = run(singleTree({"stem.parameters=toe2018", "tree.dbh_cm=5", "stem.node_spacing_m=2"}));
    expectSound(r, "5 cm stem, 2 m nodes");
    std::printf("5 cm stem, 2 m nodes: energy imbalance %.2f %%\n", 100 * r.energy.imbalance);
    ASSERT_EQ(r.impacts.size(), 1u);
    EXPECT_TRUE(r.impacts[0].stemBroken);
    // The bar for a single-tree impact (TreeImpact.EnergyBudgetClosesWithinOnePercent): a
    // snap books the energy it releases as rupture, so the account closes as a resolved stem's does.
    EXPECT_LT(r.energy.imbalance, 0.01);
}

// 10 m3 (27 t) and 0.01 m3 (27 kg): Eq. 16 scales each dashpot with sqrt(K_n m_b), so the
// restitution is the same whatever the mass; the time step follows sqrt(m / K_n).
TEST(ExtremeBlocks, HeavyAndTinyBlocksStopOnFlatGround) {
    for (const char* volume : {"block.volume_m3=10", "block.volume_m3=0.01"})
        expectStopsNearWhereItLands(run(flatGround({volume})), volume);
}

TEST(ExtremeBlocks, HeavyAndTinyBlocksRunDownASlope) {
    for (const char* volume : {"block.volume_m3=10", "block.volume_m3=0.01"}) {
        const RunResult r = run(straightSlope(35, {volume}));
        expectSound(r, volume);
        EXPECT_NE(r.reason, StopReason::TimeLimit) << volume;
    }
}

// 40 m/s into a 25 cm stem: 1.08 MJ, far beyond what it takes to break the stem
// (TreeImpact.StemBreaksOnlyWhenTheBlockCarriesEnoughEnergy). Skimming the soil bumps at 35 m/s
// after the impact, the block makes and ends many contacts per second. While contact ends went
// unbooked (their dashpot's and shear spring's last half step, ContactLaw::end), the budget closed
// to first order in the step: 4.5e-3 at the default, 1.8e-3 at a quarter of it. What is left (the
// step changing from one step to the next, contact onsets: docs/accuracy.md, "Energy audit") must
// stay under a tenth of the 1 % the issue asks of an impact's budget, at the default step as at the
// fine one (6.6e-4 and 5.1e-4 when this was written). The broken top falls
// and lands on the soil while the block runs on (a broken stem sleeps only once its pieces rest),
// so the stems' step is refined with the block's.
TEST(ExtremeSpeed, FortyMetresPerSecondBreaksTheStemAndTheBudgetCloses) {
    const RunResult coarse = run(singleTree({"block.speed_m_s=40"}));
    const RunResult fine = run(singleTree({"block.speed_m_s=40", "integration.safety=0.075", "integration.stem_safety=0.2"}));
    std::printf("40 m/s: imbalance %.2e at safety 0.3 (stems 0.8), %.2e at 0.075 (stems 0.2); block keeps %.0f of %.0f J\n", coarse.energy.imbalance,
                fine.energy.imbalance, coarse.impacts.at(0).energyAfter, coarse.impacts.at(0).energyBefore);
    for (const RunResult* r : {&coarse, &fine}) {
        ASSERT_EQ(r->impacts.size(), 1u);
        EXPECT_TRUE(r->impacts[0].stemBroken);
        EXPECT_LT(r->impacts[0].breakHeight, 0.5 * r->impacts[0].stemHeight);  // the bole, not only the top
        EXPECT_LT(r->impacts[0].energyAfter, r->impacts[0].energyBefore);
        EXPECT_LT(r->energy.imbalance, kTolerance);
    }
    expectSound(fine, "40 m/s, safety 0.075");
    EXPECT_LT(coarse.energy.imbalance, 1e-3);
    EXPECT_LT(fine.energy.imbalance, 1e-3);
}

TEST(ExtremeSpeed, BlockHittingFlatGroundAtFortyMetresPerSecondStops) {
    // From 81.5 m: sqrt(2 g 81.5) = 40 m/s at the ground.
    const RunResult r = run(flatGround({"release.fall_height_m=81.5"}));
    EXPECT_NEAR(r.maxSpeed, 40, 0.5);
    expectSound(r, "40 m/s drop");
    EXPECT_EQ(r.reason, StopReason::Rest);
}

// A sphere launched at the stem's axis (eccentricity 0) or beside it (0.99: an overlap of at most
// 1 % of r_b + r_s, 6 mm).
// The paper's tree (toe2018): M_a = 200 kN m holds a 25 cm stem's foot until it breaks.
TEST(ExtremeImpacts, HeadOnImpactStopsTheBlockAGrazingOneBarelySlowsIt) {
    const std::vector<std::string> paper = kSphere + std::vector<std::string>{"stem.parameters=toe2018"};
    const RunResult headOn = run(singleTree(paper + std::vector<std::string>{"block.eccentricity=0"}));
    // Where the graze pushed the block is read 0.9 s after it (13 m on): by 3 s the soil's bumps
    // have moved it sideways by as much, one way or the other with the step (at stem_safety 0.2 it
    // stopped 0.17 m on the stem's side, at the default 0.8 0.16 m beyond; at 0.5, 0.8 and 1.2 s it
    // is 0.16, 0.23 and 0.27 m beyond at any step).
    const RunResult grazing = run(singleTree(paper + std::vector<std::string>{"block.eccentricity=0.99", "stop.max_time_s=1"}));
    ASSERT_EQ(headOn.impacts.size(), 1u);
    ASSERT_EQ(grazing.impacts.size(), 1u);
    const TreeImpact &h = headOn.impacts[0], &g = grazing.impacts[0];
    std::printf("head-on: %.0f -> %.0f J (eccentricity %.3f); grazing: %.0f -> %.0f J (eccentricity %.3f), stop y %.2f\n",
                h.energyBefore, h.energyAfter, h.eccentricity, g.energyBefore, g.energyAfter, g.eccentricity, grazing.stop.y());
    expectSound(headOn, "head-on");
    expectSound(grazing, "grazing");
    EXPECT_NEAR(h.eccentricity, 0, 0.02);
    EXPECT_NEAR(g.eccentricity, 0.99, 0.02);
    // Head-on the 25 cm stem breaks and its root yields: the block keeps little.
    EXPECT_LT(h.energyAfter, 0.1 * h.energyBefore);
    // A 6 mm touch can only deflect the block: at eccentricity 0.99 at most sqrt(1 - 0.99^2) = 14 %
    // of its speed is normal to the stem, 2 % of its energy; the rest of the 10 % is the soil's over
    // the same time (4.4 % lost in all, measured).
    EXPECT_GT(g.energyAfter, 0.9 * g.energyBefore);
    // ... pushed away from the stem, toward +y where it passed.
    EXPECT_GT(grazing.stop.y(), grazing.release.y() + 0.1);
}

// phi = 0: the soil's force on a sphere is along the line of centres, through the block's centre:
// no torque, so a sphere released without spin slides down and never turns, and friction takes
// nothing.
TEST(ExtremeFriction, FrictionlessSoilNeverTurnsASphere) {
    RunOptions o;
    o.recordTrajectory = true;
    const RunResult r = run(straightSlope(30, kSphere + std::vector<std::string>{"soil.friction_deg=0"}), o);
    expectSound(r, "phi = 0");
    EXPECT_EQ(r.energy.friction, 0.0);
    EXPECT_EQ(r.reason, StopReason::LeftDomain);
    double spin = 0;
    for (const auto& s : r.trajectory) spin = std::max(spin, s.angularVelocity.norm());
    EXPECT_LT(spin, 1e-9);  // rounding in the lever arms only
}

// phi = 89 deg: the Coulomb limit is 57 F_n, so the soil grips the sphere and turns it. It does not
// reach pure rolling: the tangential springs are soft (K_t = 0.05 K_n, Eq. 19) and each contact with
// a bump is short, so the contact points creep (omega r / v = 0.8 measured).
TEST(ExtremeFriction, NearlyStickingSoilTurnsASphere) {
    RunOptions o;
    o.recordTrajectory = true;
    const RunResult r = run(straightSlope(30, kSphere + std::vector<std::string>{"soil.friction_deg=89"}), o);
    expectSound(r, "phi = 89 deg");
    EXPECT_EQ(r.reason, StopReason::LeftDomain);
    const double radius = std::cbrt(3 * 0.5 / (4 * M_PI));
    double sum = 0;
    int samples = 0;
    for (const auto& s : r.trajectory)
        if (s.t > r.duration - 1) sum += s.angularVelocity.norm() * radius / s.velocity.norm(), ++samples;
    const double rolling = sum / samples;
    std::printf("phi = 89 deg: omega r / v = %.2f over the last second\n", rolling);
    // Far from the frictionless case's 0 (FrictionlessSoilNeverTurnsASphere), and no faster than
    // rolling: the soil's grip slows a spin beyond it.
    EXPECT_GT(rolling, 0.5);
    EXPECT_LE(rolling, 1.0);
}

// e_n -> 0: alpha -> alpha_cr (Eq. 15), a critically damped contact does not bounce back.
TEST(ExtremeRestitution, NearZeroRestitutionDoesNotRebound) {
    const RunResult r = run(flatGround(kSphere + std::vector<std::string>{"soil.restitution=0.001"}));
    expectSound(r, "e_n = 0.001");
    EXPECT_EQ(r.reason, StopReason::Rest);
    // Rebound speed e_n v = 1 cm/s at most: a rebound of 5 um; 1 mm bounds it with the bed's bumps.
    EXPECT_LT(r.maxBounce, 1e-3);
}

// e_n = 1 and phi = 0: nothing dissipates and the sphere bounces for ever. Each landing starts its
// contacts between two steps and misses part of their springs' work: the energy creeps up bounce
// after bounce, to first order in the step.
TEST(ExtremeRestitution, UnitRestitutionWithoutFrictionBouncesForEver) {
    const std::vector<std::string> elastic = kSphere + std::vector<std::string>{"soil.restitution=1", "soil.friction_deg=0", "stop.max_time_s=6"};
    const RunResult r = run(flatGround(elastic));
    const RunResult fine = run(flatGround(elastic + std::vector<std::string>{"integration.safety=0.075"}));
    std::printf("e_n = 1: imbalance after 6 s %.2e (safety 0.3), %.2e (0.075); highest bounce %.2f m\n", r.energy.imbalance,
                fine.energy.imbalance, r.maxBounce);
    EXPECT_EQ(r.energy.contactDamping, 0.0);
    EXPECT_EQ(r.energy.friction, 0.0);
    EXPECT_EQ(r.reason, StopReason::TimeLimit);
    expectSound(r, "e_n = 1");
    EXPECT_LT(fine.energy.imbalance, r.energy.imbalance / 2);  // first order: a 4 times smaller step at least halves it
    // It rises back to about the 4.5 m its lowest point fell (a little above, by the creep): without
    // friction nothing turns it sideways, and the energy it keeps is held by the audit to 5 %
    // (expectSound), which bounds the height to 5 % too (measured 4.60 m).
    EXPECT_GT(r.maxBounce, 0.95 * (5 - std::cbrt(3 * 0.5 / (4 * M_PI))));
}

TEST(ExtremeRelease, ReleaseInsideTheSoilIsRefusedNamingTheKey) {
    // 0.1 m above the surface, the 0.5 m3 cube (0.4 m to its faces) starts in the soil's spheres.
    const SceneConfig c = flatGround({"release.fall_height_m=0.1"});
    const std::string m = messageOf<sylva::InputError>([&] { run(c); });
    EXPECT_TRUE(mentions(m, "inside the soil") && mentions(m, "release.fall_height_m")) << m;
    // On or below the surface is refused where the key is read (the help said [0, 1000] and 0 failed later).
    for (const char* h : {"0", "-3"}) {
        const std::string below = messageOf<sylva::InputError>([&] { flatGround({std::string("release.fall_height_m=") + h}); });
        EXPECT_TRUE(mentions(below, std::string("release.fall_height_m = ") + h + ": outside (0, 1000] m")) << below;
    }
}

// A soil spring too soft to hold the block up (its weight on one contact would press it deeper than a
// soil sphere's radius: 1 350 kg on 1 N/m sinks 13 km) is refused by name; it used to be stopped by
// the energy audit, blamed on the time step. Table 2's 1e6 N/m presses the block 1.3 cm.
TEST(ExtremeRelease, ASoilSpringThatCannotHoldTheBlockIsRefusedByName) {
    const std::string m = messageOf<sylva::InputError>([] { run(flatGround({"soil.kn_n_m=1"})); });
    EXPECT_TRUE(mentions(m, "soil.kn_n_m = 1 N/m") && mentions(m, "more than a soil sphere's radius (0.7 m)")) << m;
    EXPECT_FALSE(mentions(m, "time step")) << m;
    EXPECT_NO_THROW(run(flatGround({"soil.kn_n_m=1e6", "stop.max_time_s=2"})));
    // So is a soil type of a soil map (hazard's --soil-types), named as its table names it.
    auto zones = std::make_shared<SoilZones>();
    zones->zone = {1};  // one cell: the nearest for every point
    zones->columns = zones->rows = 1;
    zones->names = {"scene", "mud"};
    SoilContactParams mud;
    mud.kn = 1;
    zones->params = {SoilContactParams{}, mud};
    const Scene zoned = Scene(flatGround({})).withSoilZones(zones);
    const std::string z = messageOf<sylva::InputError>([&] { BlockMotion(zoned, drawRelease(zoned, 1)); });
    EXPECT_TRUE(mentions(z, "soil type 'mud': kn_n_m = 1 N/m")) << z;
}

TEST(ExtremeRelease, ReleaseOutsideTheTerrainIsRefused) {
    // Named by the --set that placed it (the scene file was blamed), with the terrain's bounds.
    for (const auto& [where, says] : {std::pair<const char*, const char*>{"release.x_m=100", "--set release.x_m: release point (100, "},
                                      {"release.y_m=-5", "--set release.y_m: release point ("}}) {
        const SceneConfig c = flatGround({where});
        const std::string m = messageOf<sylva::InputError>([&] { run(c); });
        EXPECT_TRUE(mentions(m, says) && mentions(m, "is outside the terrain (x in [0, ")) << where << ": " << m;
    }
    // A y drawn from the scene's range is the range's; with both coordinates out, x's first.
    const std::string range = messageOf<sylva::InputError>([] { run(flatGround({"release.y_min_m=300", "release.y_max_m=400"})); });
    EXPECT_TRUE(mentions(range, "--set release.y_min_m: release point (30, ")) << range;
    const std::string both = messageOf<sylva::InputError>([] { run(flatGround({"release.x_m=100", "release.y_m=500"})); });
    EXPECT_TRUE(mentions(both, "--set release.x_m: release point (100, 500)")) << both;
    // From the scene file: its line; a --set among the keys is named first, as the likelier cause.
    const std::string path = ::testing::TempDir() + "release_outside.ini";
    std::ofstream(path) << "[terrain]\nprofile = " << SYLVAROCK_DATA << "/slopes/flat.csv\nwidth_m = 20\n\n[release]\nx_m = 1000\ny_m = 10\n";
    const std::string file = messageOf<sylva::InputError>([&] { run(loadScene(path)); });
    EXPECT_TRUE(mentions(file, path + ":6: release point (1000, 10)")) << file;
    const std::string set = messageOf<sylva::InputError>([&] { run(loadScene(path, {"release.y_m=500"})); });
    EXPECT_TRUE(mentions(set, "--set release.y_m: release point (1000, 500)")) << set;
    const std::string launch = messageOf<sylva::InputError>([] { run(singleTree({"block.launch_distance_m=100"})); });
    EXPECT_TRUE(mentions(launch, "--set block.launch_distance_m: the launch start")) << launch;
    // A launch 1.5 m before a tree standing 0.5 m from the terrain's edge.
    const std::string m = messageOf<sylva::InputError>([] { run(singleTree({"tree.x_m=0.5"})); });
    EXPECT_TRUE(mentions(m, "--set tree.x_m: the launch start") && mentions(m, "block.launch_distance_m")) << m;
}

// A forest in another frame (map coordinates on a local slope): the message leads to the line.
TEST(ExtremeRelease, StemOutsideTheTerrainNamesTheForestFileAndLine) {
    const std::string path = forestCsv("stem-outside", "5,10,25\n612000,5170000,30\n");
    const std::string m = messageOf<sylva::InputError>([&] { Scene(straightSlope(35, {"forest.file=" + path})); });
    EXPECT_TRUE(mentions(m, path + ":3: stem 2 at (612000, 5170000) is outside the terrain (x in [0, 40]")) << m;
    EXPECT_TRUE(mentions(m, "another frame or CRS")) << m;
    // Within half a cell of a DTM's terrain (a forest clipped to the raster's extent, its terrain
    // ending at the outermost cell centres) is said as such, not as another CRS; farther, or on a
    // profile, the CRS is suspected.
    const ElevationGrid dtm = ElevationGrid::fromValues(20, 10, 2.5, 2.5, 5.0, std::vector<double>(200, 100.0), "flat.asc");
    const auto refusal = [&](const std::string& name, const std::string& stem) {
        const std::string path = forestCsv(name, "50,20,25\n" + stem + ",30\n");
        return std::pair(path, messageOf<sylva::InputError>([&] { Scene(sceneFromOverrides({"forest.file=" + path}), dtm); }));
    };
    const auto [edge, e] = refusal("stem-at-edge", "98.7,20");
    EXPECT_TRUE(mentions(e, edge + ":3: stem 2 at (98.7, 20) is outside the terrain")) << e;
    EXPECT_TRUE(mentions(e, "by 1.2 m: the terrain ends at the DTM's outermost cell centres")) << e;
    const auto [far, f] = refusal("stem-past-edge", "100.5,20");
    EXPECT_TRUE(mentions(f, "another frame or CRS")) << f;
    EXPECT_FALSE(mentions(m, "cell centres")) << m;
}

// A stem thinner than the tip diameter cannot be built: refused at load with its line, whatever the
// seed (it used to fail only in the runs whose block reached it). A file without stems is refused too.
TEST(ExtremeRelease, StemThinnerThanTheTipOrNoStemIsRefusedAtLoad) {
    const std::string path = forestCsv("stem-thin", "5,10,25\n20,10,0.5\n");
    const std::string m = messageOf<sylva::InputError>([&] { Scene(straightSlope(35, {"forest.file=" + path})); });
    EXPECT_TRUE(mentions(m, path + ":3: stem 2: a DBH of 0.5 cm is below the stems' tip diameter (stem.tip_diameter_m = 1 cm)")) << m;
    // A stem as thin as the tip is a cylinder, which Stem builds: accepted, as Stem accepts it.
    const std::string cylinder = forestCsv("stem-tip", "5,10,25\n20,10,1\n");
    EXPECT_NO_THROW(Scene(straightSlope(35, {"forest.file=" + cylinder})));
    EXPECT_NO_THROW(Stem(beechStem(1), StemParams{}, Vec3::Zero(), StemFoot::Clamped));
    // Lowering the tip below it builds the stem.
    EXPECT_NO_THROW(Scene(straightSlope(35, {"forest.file=" + path, "stem.tip_diameter_m=0.004"})));
    // A header and no stem is no forest (it ran as bare ground).
    const std::string empty = forestCsv("stem-none", "");
    const std::string none = messageOf<sylva::InputError>([&] { Scene(straightSlope(35, {"forest.file=" + empty})); });
    EXPECT_TRUE(mentions(none, empty + ": no stem in the forest file")) << none;
}

// 500 m above the ground the release is inside the terrain's footprint: the block lands at 99 m/s.
TEST(ExtremeRelease, ReleaseFarAboveTheGroundLandsAndStops) {
    const RunResult r = run(flatGround({"release.fall_height_m=500"}));
    EXPECT_LT(r.maxSpeed, std::sqrt(2 * 9.81 * 500) + 0.1);  // no energy from nowhere in the fall
    expectStopsNearWhereItLands(r, "500 m drop");
}

// The block starting inside a stem would begin with a spring that no motion loaded.
TEST(ExtremeRelease, StemAtTheReleasePointIsRefusedNamingTheStem) {
    const SceneConfig atRelease = straightSlope(35, {"forest.file=" + forestCsv("stem-at-release", "5,10,25\n")});
    std::string m = messageOf<sylva::InputError>([&] { run(atRelease); });
    EXPECT_TRUE(mentions(m, "inside stem 1")) << m;
    // A launch that starts at the stem's axis is the same error.
    m = messageOf<sylva::InputError>([] { run(singleTree({"block.launch_distance_m=0"})); });
    EXPECT_TRUE(mentions(m, "inside stem 1") && mentions(m, "block.launch_distance_m")) << m;
    // A stem 1 m downslope is clear of the block (bounding radius 0.54 m + foot radius 0.14 m).
    const Scene clear(straightSlope(35, {"forest.file=" + forestCsv("stem-below-release", "6,10,25\n")}));
    EXPECT_NO_THROW(BlockMotion(clear, drawRelease(clear, 1)));
}

// The single-tree scene has its tree: a forest given as well was dropped without a word.
TEST(ExtremeRelease, AForestGivenToTheSingleTreeSceneIsRefused) {
    const std::string m = messageOf<sylva::InputError>(
        [] { Scene(singleTree({"forest.file=" + forestCsv("beside-the-single-tree", "5,10,25\n")})); });
    EXPECT_TRUE(mentions(m, "the scene places a single tree")) << m;
}

TEST(ExtremeTimeStep, ForcedStepAboveTheStableOneIsRefusedWithItsLimit) {
    // On the ground, the block/soil springs' limit is ~1e-2 s.
    std::string m = messageOf<SimulationError>([] { run(flatGround({"integration.dt_s=0.05"})); });
    EXPECT_TRUE(mentions(m, "integration.dt_s") && mentions(m, "stable limit")) << m;
    // 1 ms is stable on the ground, and refused when the stem (limit ~6e-5 s) wakes.
    expectStopsNearWhereItLands(run(flatGround({"integration.dt_s=0.001"})), "dt 1 ms");
    m = messageOf<SimulationError>([] { run(singleTree({"integration.dt_s=0.001"})); });
    EXPECT_TRUE(mentions(m, "integration.dt_s") && mentions(m, "stable limit")) << m;
}

// integration.safety = 1: the step at the bound itself. The bound (StableStep) is an upper bound
// of the frequencies, so the leapfrog stays stable; the budget closes less well.
TEST(ExtremeTimeStep, StepAtTheStableLimitStaysStable) {
    const RunResult r = run(flatGround({"integration.safety=1"}));
    EXPECT_EQ(r.reason, StopReason::Rest);
    EXPECT_LT(r.energy.imbalance, kTolerance);
}

// Two 30 cm stems 20 cm apart: their cones overlap at rest, a fused pair rather than a contact
// (ForestMotion's fusedAtRest). With every stem awake and the block far away, nothing should move.
TEST(ExtremeForest, StemsTouchingAtGenerationStayAtRest) {
    const Scene scene(straightSlope(35, {"forest.file=" + forestCsv("touching-pair-aside", "15,5.9,30\n15,6.1,30\n"),
                                         "forest.all_awake=true"}));
    BlockMotion m(scene, drawRelease(scene, 1));
    while (m.time() < 0.25) m.step();  // the block is still falling, 3 m above the ground
    const ForestLedger l = m.forest().ledger();
    const double moved = l.bendingPlasticity + l.bendingDamping + m.energy().stored;
    EXPECT_LT(moved, 1.0);
    EXPECT_LT(m.energy().imbalance, 1e-4);
}

// The pieces of a broken stem meet one another as stems do: struck at 10 m/s, the 80 cm beech breaks
// 22 m up, and its top (1.3 t of Eq. 13's crown) fell straight down through its own stump to the soil.
// Now it lands on the stump and slides off it: no node of the top's pieces ever sinks into the stump
// by more than the stem/stem contact lets two stems overlap (a few centimetres under a 1.3 t piece;
// the stump is 0.3-0.5 m thick, which is how deep the top went through it). A node alone between two
// breaks meets the block but not stems, a documented limitation (docs/model-stems.md, "... but not
// yet other stems"), so it is left out: with the default's foot zone the top's upper connections
// shatter into such nodes, which fell 0.41 m deep (measured once, with a temporary print).
TEST(ExtremeForest, ABrokenTopDoesNotFallThroughItsStump) {
    const Scene scene(singleTree({"tree.dbh_cm=80", "block.speed_m_s=10"}));
    BlockMotion m(scene, drawRelease(scene, 1));
    double deepest = 0;
    std::size_t lowestBreak = 0;
    while (m.time() < 3) {
        m.step();
        const Stem* s = m.forest().awakeStem(0);
        if (!s) continue;
        std::size_t k = 0;
        while (k < s->connectionCount() && !s->broken(k)) ++k;
        if (k == s->connectionCount()) continue;
        lowestBreak = k;
        const auto lone = [&](std::size_t i) { return s->broken(i - 1) && (i == s->connectionCount() || s->broken(i)); };
        for (std::size_t i = k + 1; i < s->nodeCount(); ++i) {
            if (lone(i)) continue;
            for (std::size_t c = 0; c < k; ++c) {
                const Vec3 &a = s->position[c], &b = s->position[c + 1], &p = s->position[i];
                const Vec3 closest = a + closestOnSegment(p, a, b) * (b - a);
                const double overlap = s->nodeRadius(i) + 0.5 * s->connectionDiameter(c) - (p - closest).norm();
                deepest = std::max(deepest, overlap);
            }
        }
    }
    ASSERT_GT(lowestBreak, 0u) << "the stem did not break";
    std::printf("lowest break in connection %zu; the top sank at most %.3f m into its stump\n", lowestBreak, deepest);
    EXPECT_LT(deepest, 0.05);
}

TEST(ExtremeForest, BlockThroughStemsTouchingAtGenerationCompletes) {
    const RunResult r = run(straightSlope(35, kSphere + std::vector<std::string>{
                                                  "forest.file=" + forestCsv("touching-pair", "10,9.9,30\n10,10.1,30\n"),
                                                  "stop.max_time_s=4"}));
    std::printf("through the touching pair: %zu impacts, imbalance %.2e, %ld steps\n", r.impacts.size(), r.energy.imbalance, r.steps);
    expectSound(r, "touching pair");
    ASSERT_GE(r.impacts.size(), 1u);
    EXPECT_LT(r.impacts[0].energyAfter, r.impacts[0].energyBefore);
}

// The stems of a stool stand within reach of each other's displaced nodes. Each used to hold the
// other awake for as long as the other moved (a moving neighbour within reach), so a pair the block
// had set swaying or broken never slept: both were stepped until the block stopped, tens of seconds
// later (up to 3.6 s of CPU a run through this forest, against 0.1 to 0.2 s now). Within reach of
// each other they now sleep together once nothing else holds them: the node-steps a neighbour holds
// stay below those the block's own touches take (with the bug, 34 times those in these 4 runs).
TEST(ExtremeForest, StoolStemsSwayingWithinReachOfEachOtherSleepOnceTheBlockHasGone) {
    std::string rows;  // stools of two 20 cm stems 15 cm apart, every 12 m along and across the slope
    for (int i = 0; i < 41; ++i)
        for (int j = 0; j < 16; ++j) {
            const double x = 135 + 12 * i, y = 5 + 12 * j + (i % 2 ? 6 : 0);
            rows += std::to_string(x) + "," + std::to_string(y) + ",20\n" + std::to_string(x + 0.15) + "," + std::to_string(y) + ",20\n";
        }
    const Scene scene(loadScene(std::string(SYLVAROCK_DATA) + "/scenes/no-forest.ini",
                                {"forest.file=" + forestCsv("stool-grid", rows)}));
    CampaignOptions o;
    o.runs = 4;
    o.seed = 9;
    NodeSteps n;
    std::size_t impacts = 0;
    for (const RunResult& r : runCampaign(scene, o)) n += r.nodeSteps, impacts += r.impacts.size();
    std::printf("stool grid, 4 runs: %zu impacts; node-steps touched %llu, a neighbour near %llu, of %llu\n", impacts,
                static_cast<unsigned long long>(n[StemAwake::Touched]),
                static_cast<unsigned long long>(n[StemAwake::NeighbourNear]), static_cast<unsigned long long>(n.total()));
    ASSERT_GE(impacts, 4u);
    EXPECT_LT(n[StemAwake::NeighbourNear], n[StemAwake::Touched]);
}

// Steeper than any friction angle and than the cube's tipping angle: nothing can hold the block, it
// leaves at the bottom, and it can never be faster than a free fall from its release.
TEST(ExtremeTerrain, SlopeSteeperThanSixtyDegreesSendsTheBlockDown) {
    for (double slope : {70.0, 80.0}) {
        const RunResult r = run(straightSlope(slope, {}));
        std::printf("%.0f deg: top speed %.1f m/s, imbalance %.2e\n", slope, r.maxSpeed, r.energy.imbalance);
        EXPECT_EQ(r.reason, StopReason::LeftDomain) << slope;
        EXPECT_GE(r.stop.x(), 40) << slope;
        EXPECT_LT(r.maxSpeed, std::sqrt(2 * 9.81 * r.release.z())) << slope;
        EXPECT_LT(r.energy.imbalance, kTolerance) << slope;
    }
    // At 85 deg a block 5 m above the surface is 0.44 m from it horizontally: inside the soil.
    const SceneConfig c = straightSlope(85, {});
    EXPECT_TRUE(mentions(messageOf<sylva::InputError>([&] { run(c); }), "inside the soil"));
}

TEST(ExtremeTerrain, FlatSlopeStopsTheBlockWhereItLands) {
    const RunResult r = run(flatGround({}));
    expectStopsNearWhereItLands(r, "flat");
    // All the fall went into the dashpots and friction, to the warning level.
    const double fall = r.energy.initialTotal - r.energy.potential - r.energy.kinetic - r.energy.stored;
    EXPECT_NEAR(r.energy.contactDamping + r.energy.friction, fall, kWarning * fall);
}

// Issue 6, item 3: every run's budget is in runs.csv (energy_imbalance) and a run that does not
// close it to integration.energy_warning is flagged there (energy_flag) and counted in
// summary.json (energy_flagged_runs).
TEST(ExtremeEnergyAudit, RunsAboveTheWarningLevelAreFlaggedInTheOutput) {
    const auto dir = std::filesystem::temp_directory_path() / "sylvarock-tests" / "energy-flag";
    std::filesystem::create_directories(dir);
    CampaignOptions o;
    o.runs = 2;
    o.threads = 1;
    for (const char* warning : {"integration.energy_warning=1e-4", "integration.energy_warning=0.5"}) {
        const Scene scene(flatGround({warning}));
        const auto runs = runCampaign(scene, o);
        const bool strict = mentions(warning, "1e-4");
        for (const auto& r : runs) {
            // Drops on flat ground close to ~1 % (FlatSlopeStopsTheBlockWhereItLands): above 1e-4, below 0.5.
            ASSERT_GT(r.energy.imbalance, 1e-4);
            ASSERT_LT(r.energy.imbalance, 0.5);
            EXPECT_EQ(r.energy.flagged, strict) << warning;
        }
        const std::string csv = (dir / "runs.csv").string(), json = (dir / "summary.json").string();
        writeRunsCsv(csv, runs);
        writeSummaryJson(json, summarise(runs), 0, "flat", "dem");
        std::ifstream in(csv);
        std::string header, row;
        std::getline(in, header);
        std::vector<std::string> columns;
        for (std::stringstream h(header); std::getline(h, row, ',');) columns.push_back(row);
        const auto flag = std::find(columns.begin(), columns.end(), "energy_flag") - columns.begin();
        ASSERT_LT(flag, static_cast<long>(columns.size())) << header;
        for (const char* kept : {"runout_m", "tree_impacts", "stop_reason", "energy_imbalance"})
            EXPECT_NE(std::find(columns.begin(), columns.end(), kept), columns.end()) << kept;
        int rows = 0;
        while (std::getline(in, row)) {
            std::vector<std::string> cells;
            std::string cell;
            for (std::stringstream r(row); std::getline(r, cell, ',');) cells.push_back(cell);
            EXPECT_EQ(cells.at(flag), strict ? "1" : "0") << row;
            ++rows;
        }
        EXPECT_EQ(rows, 2);
        std::stringstream summary;
        summary << std::ifstream(json).rdbuf();
        EXPECT_TRUE(mentions(summary.str(), strict ? "\"energy_flagged_runs\": 2" : "\"energy_flagged_runs\": 0")) << summary.str();
    }
}

TEST(ExtremeEnergyAudit, GrowthAboveTheToleranceStopsTheRunNamingWhereItAppeared) {
    // A tolerance of 1e-6 trips at once on the leapfrog's offset in free flight, on the block's side.
    const std::string m = messageOf<SimulationError>([] { run(flatGround({"integration.energy_tolerance=1e-6"})); });
    EXPECT_TRUE(mentions(m, "energy grew without a source") && mentions(m, "the block, soil and their contacts gained") &&
                mentions(m, "integration.safety"))
        << m;
}

// A whipped crown shatters into single nodes, each between two broken connections or on top of a
// broken last one (36 in an MO1 A run on average, docs/model-stems.md). Such a node kept its mass but
// met only the soil: the block passed through it (0.11-0.20 m deep in five of these impacts, deeper
// than the intact connections went). It now meets the block as a sphere of its own diameter, so it
// sinks into the block no deeper than the stem's intact connections do in the same impact (the
// crushing contact dents those by 3-9 cm; the lone nodes go 0.6-5.5 cm). Lone nodes meet the block in
// 8 of these 16 impacts; fewer than 4 and the test says too little about their contact.
TEST(ExtremeForest, ANodeBetweenTwoBreaksMeetsTheBlock) {
    int met = 0;
    for (const char* dbh : {"15", "20", "25", "30"})
        for (const char* speed : {"10", "15"})
            for (const char* height : {"1", "2"}) {
                const Scene scene(singleTree({std::string("tree.dbh_cm=") + dbh, std::string("block.speed_m_s=") + speed,
                                              std::string("block.impact_height_m=") + height}));
                BlockMotion m(scene, drawRelease(scene, 1));
                double lone = -1, intact = -1;  // deepest overlap with a block sphere, m
                while (m.time() < 3) {
                    m.step();
                    const Stem* s = m.forest().awakeStem(0);
                    if (!s) continue;
                    const RigidBody& b = m.block();
                    for (std::size_t i = 0; i < b.spheres().size(); ++i) {
                        const Vec3 p = b.sphereCentre(i);
                        const double rb = b.spheres()[i].radius;
                        for (std::size_t c = 0; c < s->connectionCount(); ++c) {
                            const Vec3 &a0 = s->position[c], &a1 = s->position[c + 1];
                            if (!s->broken(c))
                                intact = std::max(intact, rb + 0.5 * s->connectionDiameter(c) - (p - a0 - closestOnSegment(p, a0, a1) * (a1 - a0)).norm());
                            else if (c + 1 == s->connectionCount() || s->broken(c + 1))
                                lone = std::max(lone, rb + s->nodeRadius(c + 1) - (p - a1).norm());
                        }
                    }
                }
                std::printf("%s cm at %s m/s, %s m up: a lone node %.3f m into the block, an intact connection %.3f m\n", dbh,
                            speed, height, lone, intact);
                if (lone <= 0) continue;
                ++met;
                EXPECT_LE(lone, intact) << dbh << " cm at " << speed << " m/s, " << height << " m up";
            }
    EXPECT_GE(met, 4) << "lone nodes met the block in too few impacts to test their contact";
}

// A block launched at one tree (data/scenes/single-tree.ini): the energy budget of the impact
// closes, and a stem breaks or not depending on the block's energy.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "libdem/BlockRun.hpp"
#include "libcommon/InputError.hpp"
#include "libstand/Allometry.hpp"

using namespace sylva::dem;

namespace {

RunResult launch(std::vector<std::string> keys, const RunOptions& options = {}) {
    keys.push_back("stop.max_time_s=3");
    const Scene scene(loadScene(std::string(SYLVAROCK_DATA) + "/scenes/single-tree.ini", keys));
    return simulateBlock(scene, 0, 1, options);
}

// One impact of the default scene's block on a DBH cm stem at `speed` m/s, pieces not followed.
TreeImpact impactOn(const char* dbh, const char* speed, const std::vector<std::string>& more) {
    std::vector<std::string> keys = {std::string("tree.dbh_cm=") + dbh, std::string("block.speed_m_s=") + speed,
                                     "forest.piece_max_time_s=0"};
    keys.insert(keys.end(), more.begin(), more.end());
    const RunResult r = launch(keys);
    EXPECT_EQ(r.impacts.size(), 1u);
    EXPECT_LT(r.energy.imbalance, 0.01);
    return r.impacts.at(0);
}

// The tree's own four terms over the impact.
double treeTerms(const TreeImpact& i) {
    const StemLedger& d = i.duringImpact;
    return d.bendingPlasticity + d.bendingDamping + d.rootPlasticity + d.rupture;
}

// The three impacts a numerical setting is held to, under settings `a` and `b`: the tree's own
// terms and the block's exit energy within `share` of the impact energy, and the stem broken at both
// or at neither. Returns the pairs, 20 cm at 10 m/s first, for a test's further checks.
std::vector<std::pair<TreeImpact, TreeImpact>> expectTheSameImpacts(const char* aName, const std::vector<std::string>& a,
                                                                    const char* bName, const std::vector<std::string>& b,
                                                                    double share) {
    std::vector<std::pair<TreeImpact, TreeImpact>> pairs;
    for (const auto& [dbh, speed] : {std::pair<const char*, const char*>{"20", "10"}, {"15", "15"}, {"25", "15"}}) {
        const TreeImpact ia = impactOn(dbh, speed, a), ib = impactOn(dbh, speed, b);
        pairs.emplace_back(ia, ib);
        std::cout << dbh << " cm at " << speed << " m/s: tree over the impact " << treeTerms(ia) << " J (" << aName << "), "
                  << treeTerms(ib) << " J (" << bName << "); block after " << ia.energyAfter << ", " << ib.energyAfter
                  << " J of " << ib.energyBefore << " J\n";
        EXPECT_NEAR(treeTerms(ia), treeTerms(ib), share * ib.energyBefore) << dbh << " cm";
        EXPECT_NEAR(ia.energyAfter, ib.energyAfter, share * ib.energyBefore) << dbh << " cm";
        EXPECT_EQ(ia.stemBroken, ib.stemBroken) << dbh << " cm";
    }
    return pairs;
}

// Elastic energy a cantilever cone stores when a horizontal load at height h brings its foot to the
// rupture moment (Eq. 6): F = M_rupt(0) / h and E = integral of M(z)^2 / (2 E I(z)) over [0, h].
// Plasticity (E_Plast < MOE) and the root spring only make the stem more compliant, so a block
// with less kinetic energy than this cannot break it.
double elasticEnergyToBreak(double dbhCm, double h) {
    const double H = sylva::stand::treeHeightM(dbhCm), dbh = dbhCm / 100, tip = 0.01;
    const double moe = 8.7e9, sigmaRupt = 94e6;
    auto diameter = [&](double z) { return tip + (dbh - tip) * (H - z) / (H - 1.3); };
    const double mRupt = sigmaRupt * M_PI * std::pow(diameter(0), 3) / 32;
    const double f = mRupt / h;
    double e = 0;
    const int n = 2000;
    for (int i = 0; i < n; ++i) {
        const double z = (i + 0.5) * h / n;
        const double inertia = M_PI * std::pow(diameter(z), 4) / 64;
        e += std::pow(f * (h - z), 2) / (2 * moe * inertia) * h / n;
    }
    return e;
}

}  // namespace

// The launch is refused where the block as it flies would reach into the ground, not where its
// bounding sphere would: the 0.5 m3 cube flies on a face, half its edge (0.397 m) below its centre,
// within its 0.54 m bounding radius. 0.45 m up was refused, and it strikes the stem.
TEST(TreeImpact, ALowLaunchIsRefusedByTheBlocksLowestPoint) {
    const Scene scene(loadScene(std::string(SYLVAROCK_DATA) + "/scenes/single-tree.ini", {"tree.dbh_cm=20", "block.impact_height_m=0.45"}));
    ASSERT_GT(scene.blockTemplate().boundingRadius(), 0.5);
    EXPECT_EQ(launch({"tree.dbh_cm=20", "block.impact_height_m=0.45"}).impacts.size(), 1u);
    try {
        launch({"tree.dbh_cm=20", "block.impact_height_m=0.38"});
        ADD_FAILURE() << "a launch 0.38 m up ran";
    } catch (const sylva::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("block.impact_height_m = 0.38 m puts the block into the ground: its lowest point is 0.397 m below its centre"),
                  std::string::npos)
            << e.what();
    }
}

TEST(TreeImpact, EnergyBudgetClosesWithinOnePercent) {
    // On the default trees and on the paper's: Eqs. 7-8's viscous damping and Eq. 20's elastic
    // block/stem contact are only in toe2018, crushing, root plasticity and the axial dashpots only
    // in the default's.
    for (const char* set : {"stem.parameters=calibrated", "stem.parameters=toe2018"})
    for (auto keys : std::vector<std::vector<std::string>>{
             {"tree.dbh_cm=25", "block.speed_m_s=15"},
             {"tree.dbh_cm=12", "block.speed_m_s=10", "block.eccentricity=0.5"},
             {"tree.dbh_cm=40", "block.speed_m_s=15", "tree.coppice=true"},
             {"tree.dbh_cm=20", "block.speed_m_s=5", "block.impact_height_m=2", "block.shape=sphere"}}) {
        keys.push_back(set);
        const RunResult r = launch(keys);
        ASSERT_EQ(r.impacts.size(), 1u) << keys[0];
        // The bar: the impact's budget (kinetic + potential + springs + every dissipation)
        // closes within 1 % of the energy converted.
        EXPECT_LT(r.energy.imbalance, 0.01) << keys[0] << " " << keys[1] << " " << set;
        EXPECT_LT(r.impacts[0].energyAfter, r.impacts[0].energyBefore);
    }
}

TEST(TreeImpact, StemBreaksOnlyWhenTheBlockCarriesEnoughEnergy) {
    // A sphere launched low (its centre 0.55 m up, 6 cm of fall left) from 0.9 m before the axis:
    // even slow, it reaches the stem, and gravity adds almost nothing to what it brings.
    const double dbh = 25, h = 0.55;
    const double needed = elasticEnergyToBreak(dbh, h);
    const double mass = 2700 * 0.5;
    auto speedFor = [&](double energy) { return std::sqrt(2 * energy / mass); };
    // Half the bound: it cannot break, whatever the dynamics. The bound is elastic, and so is the
    // contact here: a crushing one takes most of the block's energy (22 of the 27.8 kJ of twenty
    // times the bound), and the converged stem (uniform at 0.125 and 0.0625 m, or foot-zoned at 0.5,
    // 0.25 and 0.125 m) then keeps its bole; only the uniform stem at 0.5 and 0.25 m broke its lowest
    // connection there (docs/model-stems.md, "A bole that holds").
    const std::vector<std::string> at = {"tree.dbh_cm=25", "tree.coppice=true", "block.shape=sphere", "block.impact_height_m=0.55",
                                         "block.launch_distance_m=0.9", "tree_contact.crushing_strength_pa=0"};
    auto with = [&](double speed) {
        auto keys = at;
        keys.push_back("block.speed_m_s=" + std::to_string(speed));
        return keys;
    };
    const RunResult below = launch(with(speedFor(0.5 * needed)));
    ASSERT_EQ(below.impacts.size(), 1u);
    EXPECT_FALSE(below.impacts[0].stemBroken) << "bound " << needed << " J";
    EXPECT_TRUE(std::isnan(below.impacts[0].breakHeight)) << "no break, no break height";
    EXPECT_EQ(below.impacts[0].stemBreaks, 0u);
    std::printf("energy to break a 25 cm stem hit at 0.55 m, elastic bound: %.0f J\n", needed);
    // Twenty times the bound: far beyond what the stem stores before rupture.
    const RunResult above = launch(with(speedFor(20 * needed)));
    ASSERT_EQ(above.impacts.size(), 1u);
    EXPECT_TRUE(above.impacts[0].stemBroken) << "bound " << needed << " J";
    EXPECT_GE(above.impacts[0].stemBreaks, 1u);  // energy.json stem_breaks: the pieces less one
    // Where it broke is recorded, on the stem (a connection's middle, so strictly inside it).
    EXPECT_GT(above.impacts[0].breakHeight, 0.0);
    EXPECT_LT(above.impacts[0].breakHeight, above.impacts[0].stemHeight);
    // ... and Fig. 3's rupture breaks the bole it hits, not only the whipping top folding past pi/2.
    EXPECT_LT(above.impacts[0].breakHeight, 0.5 * above.impacts[0].stemHeight);
    EXPECT_NEAR(above.impacts[0].stemHeight, sylva::stand::treeHeightM(25), 1e-9) << "Eq. 11 for 25 cm";
}

// The impact's "after" is the block when it leaves the tree. A 15 cm stem hit at 10 m/s breaks;
// with 0.5 m between its nodes (3 sections per connection) the broken top lands on the block 0.8 s
// later, while the block slides on the soil: that touch used to move "after" on to 16.9 kJ, against
// 60.8 kJ at 0.25 m where the top misses. Those are the paper's stems on 3 sections (toe2018): the
// calibrated default's top never lands on the block while the impact is open, so on it this test
// would pass with debris counted. Debris is not the impact: both spacings agree to 0.2 % of the
// energy before; 2 % leaves room for that and fails by far (> 60 %) if the landing is counted.
TEST(TreeImpact, DebrisFallingOnTheBlockLaterIsNotPartOfTheImpact) {
    const auto impact = [](const std::string& spacing) {
        const RunResult r = launch({"stem.parameters=toe2018", "tree.dbh_cm=15", "block.speed_m_s=10", "stem.sections=3",
                                    "stem.node_spacing_m=" + spacing});
        EXPECT_EQ(r.impacts.size(), 1u);
        EXPECT_TRUE(r.impacts.at(0).stemBroken);
        return r.impacts.at(0);
    };
    const TreeImpact coarse = impact("0.5"), fine = impact("0.25");
    std::cout << "block after the impact: " << coarse.energyAfter << " J (0.5 m), " << fine.energyAfter << " J (0.25 m)\n";
    EXPECT_NEAR(coarse.energyAfter, fine.energyAfter, 0.02 * fine.energyBefore);
}

// Every broken connection is recorded, when asked, with the run's time, its height and its diameter:
// at least the breaks the impact counted, on its tree (the forest file's id, 1, not the stem's index),
// in the order of time, from the first contact on; each within the stem, the lowest the impact's
// break height, and thinner the higher it is (the stem tapers). Not asked, none are kept.
TEST(TreeImpact, EachBreakIsRecordedWhereAndWhenTheStemBrokeThere) {
    const std::vector<std::string> keys = {"tree.dbh_cm=15", "block.speed_m_s=10", "stem.node_spacing_m=0.5"};
    RunOptions options;
    options.recordBreaks = true;
    const RunResult r = launch(keys, options);
    EXPECT_TRUE(launch(keys).breaks.empty());
    ASSERT_EQ(r.impacts.size(), 1u);
    const TreeImpact& impact = r.impacts.front();
    ASSERT_TRUE(impact.stemBroken);
    ASSERT_GE(r.breaks.size(), impact.stemBreaks);
    double lowest = impact.stemHeight;
    std::vector<std::pair<double, double>> byHeight;
    for (std::size_t k = 0; k < r.breaks.size(); ++k) {
        const StemBreak& b = r.breaks[k];
        EXPECT_EQ(b.tree, impact.tree);
        EXPECT_GE(b.time, k == 0 ? impact.time : r.breaks[k - 1].time) << k;
        EXPECT_GT(b.height, 0) << k;
        EXPECT_LT(b.height, impact.stemHeight) << k;
        EXPECT_GT(b.diameter, 0) << k;
        EXPECT_LT(b.diameter, 0.15) << k;  // the DBH: this stem breaks above breast height (2.7 m up at the lowest)
        lowest = std::min(lowest, b.height);
        byHeight.emplace_back(b.height, b.diameter);
    }
    EXPECT_EQ(lowest, impact.breakHeight);
    std::sort(byHeight.begin(), byHeight.end());
    for (std::size_t k = 1; k < byHeight.size(); ++k) EXPECT_LT(byHeight[k].second, byHeight[k - 1].second) << k;
}

// A broken top falls on the soil and loses energy in the soil's dashpot there (Eq. 16 on the mass
// of each stem node), as a block does, and comes to rest before its stem sleeps; the budget still
// closes to the 1 %.
TEST(TreeImpact, BrokenPiecesLoseEnergyOnTheSoil) {
    const RunResult r = launch({"tree.dbh_cm=20", "block.speed_m_s=15"});
    ASSERT_EQ(r.impacts.size(), 1u);
    ASSERT_TRUE(r.impacts[0].stemBroken);
    std::cout << "stem/soil dashpot: " << r.forestEnergy.contactDamping << " J\n";
    EXPECT_GT(r.forestEnergy.contactDamping, 100.0) << "a falling 14 m top brings kJ to the ground";
    EXPECT_LT(r.energy.imbalance, 0.01);
    // A broken stem sleeps once its pieces rest, not mid-fall: what is frozen then is small next to
    // what the tree dissipated (issue 11's bar; it was 39 % when the top was frozen mid-air). The
    // scene never lets a stem rest (forest.return_horizon_s an hour, for the impact's account), so
    // this is asked of the forest's horizon: there a top frozen mid-fall holds ~57 % of the tree's.
    {
        const RunResult resting = launch({"tree.dbh_cm=20", "block.speed_m_s=15", "forest.return_horizon_s=0.1"});
        const ForestLedger& f = resting.forestEnergy;
        const double tree = f.bendingPlasticity + f.bendingDamping + f.rootPlasticity + f.rupture;
        std::cout << "frozen " << f.frozen << " J against the tree's " << tree << " J\n";
        ASSERT_TRUE(resting.impacts.at(0).stemBroken);
        EXPECT_LT(f.frozen, 0.05 * tree);
    }
    const ForestLedger& f = r.forestEnergy;
    const double tree = f.bendingPlasticity + f.bendingDamping + f.rootPlasticity + f.rupture;
    // Over the impact alone (first contact to the block leaving) the tree's terms are part of the
    // run's: the top's landing comes after.
    const StemLedger& d = r.impacts[0].duringImpact;
    for (const double term : {d.bendingPlasticity, d.bendingDamping, d.rootPlasticity, d.rupture}) EXPECT_GE(term, 0.0);
    EXPECT_LE(d.bendingPlasticity, f.bendingPlasticity);
    EXPECT_LE(d.rupture, f.rupture);
    const double during = d.bendingPlasticity + d.bendingDamping + d.rootPlasticity + d.rupture;
    std::cout << "the tree took " << during << " J during the impact, " << tree << " J in the run\n";
    EXPECT_LT(during, tree);
    EXPECT_GT(during, 0.0);
}

// What is frozen when stems stop still moving is split by where it was: the pieces of a broken or
// uprooted stem, or a standing stem's sway. Struck as in a forest (pieces let go, a horizon of
// 0.1 s), a 25 cm stem broken at 15 m/s stops with its top still moving: all of what is frozen is
// the pieces'. A 20 cm stem grazed at 3 m/s stands: none of it is.
TEST(TreeImpact, WhatStopsMovingIsBookedAsPiecesOrStandingSway) {
    const RunResult broken = launch({"tree.dbh_cm=25", "block.speed_m_s=15", "forest.piece_max_time_s=0",
                                     "forest.return_horizon_s=0.1"});
    ASSERT_EQ(broken.impacts.size(), 1u);
    ASSERT_TRUE(broken.impacts[0].stemBroken);
    const ForestLedger& b = broken.forestEnergy;
    std::cout << "broken: frozen " << b.frozen << " J, of which the pieces' " << b.frozenPieces << " J\n";
    EXPECT_GT(b.frozenPieces, 1000.0) << "a top of several metres stopped while moving";
    // The rest is the springs to the soil at sleep, J against the top's kJ.
    EXPECT_LE(b.frozenPieces, b.frozen);
    EXPECT_GT(b.frozenPieces, 0.99 * b.frozen);

    const RunResult grazed = launch({"tree.dbh_cm=20", "block.speed_m_s=3", "block.eccentricity=0.8",
                                     "forest.piece_max_time_s=0", "forest.return_horizon_s=0.1"});
    ASSERT_EQ(grazed.impacts.size(), 1u);
    ASSERT_FALSE(grazed.impacts[0].stemBroken);
    ASSERT_FALSE(grazed.impacts[0].rootFailed);
    EXPECT_EQ(grazed.forestEnergy.frozenPieces, 0.0);
}

// The default trees (stem.parameters = calibrated: Fig. 3 on 3 sections, wood's constant loss factor,
// the stem crushing under the block, anchorage from the stem's weight letting go at 25 deg) give the
// same impact at 0.5 and 0.25 m: the tree's own terms over the impact within the 5 % the issue asks of
// the single-tree matrix, the block's exit energy within 5 % of the impact energy (measured, with the
// default's foot zone: 20 cm at 10 m/s 41.6 and 42.4 kJ, block 3.2 and 1.6 kJ of 68 kJ; 15 cm at 15 m/s
// 13.6 and 13.4 kJ, block 128.7 and 128.7 kJ of 152 kJ). The paper's trees (toe2018) give 28.1 and
// 12.5 kJ for the first.
TEST(TreeImpact, DefaultStemAgreesAtHalfTheSpacing) {
    for (const auto& [dbh, speed] : {std::pair<const char*, const char*>{"20", "10"}, {"15", "15"}}) {
        const TreeImpact coarse = impactOn(dbh, speed, {"stem.node_spacing_m=0.5"});
        const TreeImpact fine = impactOn(dbh, speed, {"stem.node_spacing_m=0.25"});
        std::cout << dbh << " cm at " << speed << " m/s: tree over the impact " << treeTerms(coarse) << " J (0.5 m), "
                  << treeTerms(fine) << " J (0.25 m); block after " << coarse.energyAfter << ", " << fine.energyAfter << " J\n";
        EXPECT_NEAR(treeTerms(coarse), treeTerms(fine), 0.05 * treeTerms(fine)) << dbh << " cm";
        EXPECT_NEAR(coarse.energyAfter, fine.energyAfter, 0.05 * fine.energyBefore) << dbh << " cm";
    }
}

// stem.axial_softening is a resolution, not wood: on the uniform stem (no foot zone) the calibrated
// set's softened axial springs (docs/model-stems.md, "Time step") give the impact that wood's give,
// within the 2 % of the impact energy issue 12 asks of a shortcut, for the tree's own terms and for
// the block's exit energy. The 25 cm stem at 15 m/s is the impact of the 48-impact matrix that moves
// most steadily with the softening (block after 55.8, 54.0, 50.3 kJ of 152 kJ at 1, 2 and 4: 4 is
// past the converged part). The default's foot zone softens its lowest metre's springs further, and
// there the softening moves the 25 cm stem's block exit by 1.3, 2.4, 5.0 and 0.4 % at 14-17 m/s
// (docs/model-stems.md, "The foot zone"): not held to 2 %.
TEST(TreeImpact, SoftenedAxialSpringsGiveWoodsImpact) {
    expectTheSameImpacts("softened", {"stem.foot_zone_m=0"}, "wood's axial springs", {"stem.foot_zone_m=0", "stem.axial_softening=1"}, 0.02);
}

// On the default's foot zone the softening moves single impacts more (its lowest metre's axial springs
// are softened twice over): held to issue 11's 5 % between a resolution and its refinement on the same
// three impacts. Measured: tree 1.5, 0.1 and 1.4 %, block 0.9, 0.1 and 2.4 % (and on the 25 cm stem at
// 14, 16 and 17 m/s the block 1.3, 5.0 and 0.4 %: docs/model-stems.md, "The foot zone").
TEST(TreeImpact, SoftenedAxialSpringsOnTheFootZoneWithinFivePerCent) {
    expectTheSameImpacts("softened", {}, "wood's axial springs", {"stem.axial_softening=1"}, 0.05);
}

// stem.upper_spacing_factor (docs/model-stems.md, "A graded stem"): the stem cut at twice the node
// spacing in its crown (1 m above the crown base) gives the impact of the stem cut at 0.5 m all the
// way up (the default; both with its foot zone) within the 5 % of the impact energy issue 11 asks
// between a resolution and half of it, for the tree's own terms and the block's exit energy, on the
// impacts the softening is held to above. Measured: tree 0.2, 0.3 and 0.2 %, block 0.7, 0.0 and
// 0.5 % (without the zone: tree 1.1, 0.3 and 1.6 %, block 0.2, 1.6 and 2.4 %).
TEST(TreeImpact, GradedStemGivesTheUniformStemsImpact) {
    expectTheSameImpacts("graded", {"stem.upper_spacing_factor=2"}, "uniform", {}, 0.05);
}

// And the graded stem is itself a resolution: at half the node spacing (0.25 m to the crown base, 0.5 m
// in the crown) the same impacts within the same 5 % of the impact energy, the matrix's measure.
// Measured, with the default's foot zone: tree 1.1, 0.0 and 1.5 %, block 2.8, 0.1 and 1.6 % (without
// it: tree 0.0, 0.5 and 2.4 %, block 1.0, 0.1 and 4.2 %). And the 20 cm stem at 10 m/s within 5 % of
// the tree's own terms, as DefaultStemAgreesAtHalfTheSpacing asks of the default: with the zone ending
// at 4 m its whip broke the bole at 7.2-8.4 m, in the coarse part, and its terms moved by 7.9 %
// (measured now: 1.8 %). Without the foot zone the 15 and 25 cm stems at 15 m/s moved by 5.8 and 6.6 %
// of their terms, which is why the graded stem was not made the default (docs/model-stems.md); with
// it, 0.4 and 3.7 %, not yet measured at the stand level.
TEST(TreeImpact, GradedStemAgreesAtHalfTheSpacing) {
    const std::vector<std::string> coarse{"stem.upper_spacing_factor=2"},
        fine{"stem.upper_spacing_factor=2", "stem.node_spacing_m=0.25"};
    const auto [whipped, finer] = expectTheSameImpacts("graded, 0.5 m", coarse, "graded, 0.25 m", fine, 0.05).front();
    EXPECT_NEAR(treeTerms(whipped), treeTerms(finer), 0.05 * treeTerms(finer));
}

// stem.foot_zone_m (docs/model-stems.md, "The foot zone"): an impact one connection above the foot is
// not resolved at 0.5 m without it. The single-tree matrix's worst gap, 10 cm at 10 m/s, 0.1 m3, 0.5 m
// up: at 0.5 m the foot connection breaks and the block leaves with 6.2 of its 13.7 kJ, at 0.25 m the
// root plate fails and it keeps 0.5 kJ. With the lowest metre at half the spacing, 0.5 and 0.25 m agree
// within the 5 % of the impact energy issue 11 asks. Measured: tree 8.15 | 8.11 kJ, block after 0.71 |
// 0.70 kJ (0.3 and 0.1 %).
TEST(TreeImpact, FootZoneResolvesAnImpactJustAboveTheFoot) {
    const std::vector<std::string> low{"block.impact_height_m=0.5", "block.volume_m3=0.1", "stem.foot_zone_m=1"};
    auto at = [&](const char* spacing) {
        std::vector<std::string> keys = low;
        keys.push_back(std::string("stem.node_spacing_m=") + spacing);
        return impactOn("10", "10", keys);
    };
    const TreeImpact coarse = at("0.5"), fine = at("0.25");
    std::cout << "10 cm at 10 m/s, 0.5 m up: tree " << treeTerms(coarse) << " | " << treeTerms(fine) << " J, block after "
              << coarse.energyAfter << " | " << fine.energyAfter << " J of " << fine.energyBefore << " J\n";
    EXPECT_NEAR(treeTerms(coarse), treeTerms(fine), 0.05 * fine.energyBefore);
    EXPECT_NEAR(coarse.energyAfter, fine.energyAfter, 0.05 * fine.energyBefore);
    EXPECT_EQ(coarse.stemBroken, fine.stemBroken);
    EXPECT_EQ(coarse.rootFailed, fine.rootFailed);
}

// And on the impacts the other resolutions are held to (1 m up), the foot-zoned stem at 0.5 and at
// 0.25 m within the same 5 % of the impact energy. Measured: tree 1.2, 0.1 and 1.5 %, block 2.2, 0.1
// and 2.0 %.
TEST(TreeImpact, FootZonedStemAgreesAtHalfTheSpacing) {
    expectTheSameImpacts("foot zone, 0.5 m", {"stem.foot_zone_m=1"}, "foot zone, 0.25 m",
                         {"stem.foot_zone_m=1", "stem.node_spacing_m=0.25"}, 0.05);
}

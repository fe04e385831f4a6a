// The two models side by side (libassess/ModelComparison.hpp): rank agreement with its exact p-value,
// the A-against-NA count and overlapping intervals, on hand-made results; and an assessment of both
// models giving each model the very results it gives alone.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "ShortCampaign.hpp"
#include "libassess/Assessment.hpp"
#include "libassess/CampaignPlan.hpp"
#include "libassess/ModelComparison.hpp"
#include "libcommon/InputError.hpp"

namespace fs = std::filesystem;
using namespace sylva::assess;
using sylva::dem::Model;
using sylva::stand::ForestStructure;

namespace {

StructureAssessment row(const std::string& name, ForestStructure structure, double pf50, int rank) {
    StructureAssessment r;
    r.name = name;
    r.structure = structure;
    r.pf50 = pf50;
    r.pf50Ci = {pf50 - 0.05, pf50 + 0.05};
    r.rankPf50 = rank;
    return r;
}

// A and NA rows of stands S1..Sn with the given PF50s (NA rows: `na`).
AssessmentResults results(Model model, const std::vector<double>& a, const std::vector<double>& na) {
    AssessmentResults r;
    r.model = model;
    for (std::size_t i = 0; i < a.size(); ++i) r.stands.push_back(row("S" + std::to_string(i + 1), ForestStructure::Aggregated, a[i], 0));
    for (std::size_t i = 0; i < na.size(); ++i) r.stands.push_back(row("S" + std::to_string(i + 1), ForestStructure::Random, na[i], 0));
    return r;
}

TEST(ModelComparison, RankAgreementHasItsExactPermutationPValue) {
    // Four stands in the same order: of the 4! = 24 pairings of the ranks, only this one and its
    // reverse correlate as strongly, p = 2/24. Reversed: rho = -1, the same p.
    const auto dem = results(Model::Dem, {0.3, 0.4, 0.5, 0.6}, {0.4, 0.5, 0.6, 0.7});
    const auto same = results(Model::Lumped, {0.1, 0.2, 0.35, 0.9}, {0.5, 0.6, 0.65, 0.7});
    const auto reversed = results(Model::Lumped, {0.9, 0.8, 0.7, 0.6}, {0.3, 0.8, 0.2, 0.1});
    const ModelComparison c = compareModels(dem, same);
    ASSERT_EQ(c.agreement.size(), 2u);
    EXPECT_EQ(c.agreement[0].stands, 4u);
    EXPECT_NEAR(c.agreement[0].rankCorrelation, 1, 1e-12);
    EXPECT_NEAR(c.agreement[0].rankCorrelationP, 2.0 / 24, 1e-12);
    EXPECT_NEAR(compareModels(dem, reversed).agreement[0].rankCorrelation, -1, 1e-12);
    EXPECT_NEAR(compareModels(dem, reversed).agreement[0].rankCorrelationP, 2.0 / 24, 1e-12);
    // NA ranks 3, 4, 2, 1 against 1, 2, 3, 4: sum of squared rank differences 18, rho = 1 - 6*18/60 =
    // -0.8. |rho| >= 0.8 means a sum of at most 2 or at least 18: the identity and its 3 adjacent
    // swaps, the reverse and its 3: 8 of 24 pairings.
    EXPECT_NEAR(compareModels(dem, reversed).agreement[1].rankCorrelation, -0.8, 1e-12);
    EXPECT_NEAR(compareModels(dem, reversed).agreement[1].rankCorrelationP, 8.0 / 24, 1e-12);
}

TEST(ModelComparison, CountsStandsWhereRandomForestsProtectMore) {
    const auto dem = results(Model::Dem, {0.3, 0.4, 0.5}, {0.4, 0.3, 0.6});         // NA above A in S1 and S3
    const auto lumped = results(Model::Lumped, {0.3, 0.4, 0.5}, {0.2, 0.3, 0.4});   // in none
    const ModelComparison c = compareModels(dem, lumped);
    EXPECT_EQ(c.standsWithBoth, 3);
    EXPECT_EQ(c.naAboveA[0], 2);
    EXPECT_EQ(c.naAboveA[1], 0);
    // Intervals +-0.05: S1 NA 0.4 and 0.2 do not overlap, S1 A 0.3 and 0.3 do.
    ASSERT_EQ(c.stands.size(), 6u);
    EXPECT_TRUE(c.stands[0].intervalsOverlap);
    EXPECT_FALSE(c.stands[3].intervalsOverlap);
    EXPECT_THROW(compareModels(dem, results(Model::Lumped, {0.3, 0.4}, {0.2, 0.3})), std::invalid_argument);
}

TEST(ModelComparison, BothModelsRunThroughTheSameForestsWithTheDemsSeeds) {
    AssessmentDesign dem = shortCampaign("unused", 3, 2, 4, 7).design;
    AssessmentDesign both = dem;
    both.models = {Model::Dem, Model::Lumped};
    both.lumpedRuns = 11;
    both.lumpedBaselineRuns = 13;
    const auto alone = planCampaigns(dem), together = planCampaigns(both);
    ASSERT_EQ(together.size(), 2 * alone.size());
    for (std::size_t c = 0; c < alone.size(); ++c) {
        const Campaign &d = together[c], &l = together[c + alone.size()];
        EXPECT_EQ(d.id, alone[c].id);  // the DEM's campaigns are those of a DEM-only design
        EXPECT_EQ(d.runSeed, alone[c].runSeed);
        EXPECT_EQ(d.forestSeed, alone[c].forestSeed);
        EXPECT_EQ(l.model, Model::Lumped);
        EXPECT_EQ(l.id, "lumped_" + d.id);
        EXPECT_EQ(l.forestSeed, d.forestSeed);  // the same trees
        EXPECT_NE(l.runSeed, d.runSeed);
        EXPECT_EQ(l.runs, l.forested ? 11 : 13);
    }
    EXPECT_THROW(parseModels("rf3d"), sylva::InputError);
    EXPECT_EQ(parseModels("both"), (std::vector<Model>{Model::Dem, Model::Lumped}));
}

// Each model's results in a two-model assessment are those it gives alone: same forests, same
// runs, same bootstrap, whichever other model shares the campaign.
TEST(ModelComparison, EachModelGivesItsResultsAloneInATwoModelAssessment) {
    const fs::path root = fs::temp_directory_path() / "sylvarock-two-models";
    fs::remove_all(root);
    const auto options = [&](const std::string& out, std::vector<Model> models) {
        AssessmentOptions o = shortCampaign(root / out, 3, 1, 4, 5);
        o.design.models = std::move(models);
        o.design.lumpedRuns = 40;
        o.design.lumpedBaselineRuns = 50;
        o.bootstrapReplicates = 200;
        o.threads = 2;
        return o;
    };
    const auto both = runAssessment(options("both", {Model::Dem, Model::Lumped}));
    const auto dem = runAssessment(options("dem", {Model::Dem}));
    const auto lumped = runAssessment(options("lumped", {Model::Lumped}));
    ASSERT_EQ(both.size(), 2u);
    for (const auto& [together, alone] : {std::pair{&both[0], &dem.at(0)}, std::pair{&both[1], &lumped.at(0)}}) {
        EXPECT_EQ(together->model, alone->model);
        ASSERT_EQ(together->baseline.size(), alone->baseline.size());
        for (std::size_t i = 0; i < alone->baseline.size(); ++i) EXPECT_EQ(together->baseline[i].runoutM, alone->baseline[i].runoutM);
        ASSERT_EQ(together->stands.size(), alone->stands.size());
        for (std::size_t s = 0; s < alone->stands.size(); ++s) {
            EXPECT_EQ(together->stands[s].pf50, alone->stands[s].pf50);
            EXPECT_EQ(together->stands[s].pf50Ci.low, alone->stands[s].pf50Ci.low);
            EXPECT_EQ(together->stands[s].pf50Ci.high, alone->stands[s].pf50Ci.high);
            EXPECT_EQ(together->stands[s].forests.at(0).clarkEvans, alone->stands[s].forests.at(0).clarkEvans);  // same trees
        }
    }
    for (std::size_t s = 0; s < both[0].stands.size(); ++s)  // and both models of one assessment ran through the same trees
        EXPECT_EQ(both[1].stands[s].forests.at(0).clarkEvans, both[0].stands[s].forests.at(0).clarkEvans);
    EXPECT_EQ(both[1].baseline.size(), 50u);
    EXPECT_EQ(both[1].stands.at(0).runs.at(0).size(), 40u);
    fs::remove_all(root);
}

}  // namespace

// Campaign ids join names with "_": a stand named "lumped_GR1" beside GR1, both models, would share
// ids with GR1's lumped campaigns (and the store failed on "UNIQUE constraint failed"). Refused up
// front, naming both.
TEST(ModelComparison, StandsWhoseCampaignIdsClashAreRefusedByName) {
    AssessmentDesign both = shortCampaign("unused", 3, 1, 4, 7).design;
    both.models = {Model::Dem, Model::Lumped};
    StandSource clash = both.stands[0];
    clash.name = "lumped_" + clash.name;
    both.stands.push_back(clash);
    try {
        planCampaigns(both);
        FAIL() << "two campaigns with one id were planned";
    } catch (const sylva::InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("stand 'lumped_GR1' (dem) and stand 'GR1' (lumped) give the same campaign id 'lumped_GR1_A_001'"),
                  std::string::npos) << what;
    }
    both.models = {Model::Dem};
    EXPECT_NO_THROW(planCampaigns(both));
}


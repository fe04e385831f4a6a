// Per-plot and per-stand statistics: the 8 stands of data/stands against the summary of the script
// that made them (R, spatstat), and a small inventory worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "libcommon/CsvTable.hpp"
#include "libstand/Inventory.hpp"
#include "libstand/PointPattern.hpp"
#include "libstand/StandStatistics.hpp"

using namespace sylva::stand;

namespace {

std::string data(const std::string& file) { return std::string(SYLVAROCK_TEST_DATA) + "/stand/" + file; }

class StandStatisticsTable3 : public ::testing::TestWithParam<std::string> {};

TEST_P(StandStatisticsTable3, AgreesWithTheInventorySummary) {
    const std::string stand = GetParam();
    const Inventory inv = readInventory(std::string(SYLVAROCK_DATA) + "/stands/" + stand + "_stems.csv",
                                        std::string(SYLVAROCK_DATA) + "/stands/" + stand + "_plots.csv");
    const StandStatistics s = standStatistics(inv);
    const sylva::CsvTable ref = sylva::CsvTable::read(data("inventory_summary.csv"));
    std::size_t row = 0;
    while (row < ref.rows() && ref.text(row, ref.require("stand")) != stand) ++row;
    ASSERT_LT(row, ref.rows());
    const auto want = [&](const char* column) { return ref.number(row, ref.require(column)); };
    // Tolerances are the summary's rounding (half a unit of its last decimal, see
    // tests/data/stand/README.md), plus 1e-9 for the binary representation of the decimals.
    const double r3 = 0.5e-3 + 1e-9, r4 = 0.5e-4 + 1e-9;
    EXPECT_NEAR(s.stand.stemsPerHa, want("N_achieved"), 1e-9);
    EXPECT_NEAR(*s.stand.meanDbhCm, want("MeanD_achieved"), r3);
    EXPECT_NEAR(*s.stand.sdDbhCm, want("StdD_achieved"), r3);
    EXPECT_NEAR(*s.stand.basalAreaM2Ha, want("G_achieved"), r3);
    EXPECT_NEAR(*s.stand.clarkEvans.donnelly, want("R_mean"), r4);
    EXPECT_EQ(s.plotsInDonnellyMean, 8u);
    EXPECT_EQ(static_cast<double>(s.stand.nStools), want("n_stools"));
    EXPECT_NEAR(*s.stand.stemsPerStool, want("mean_stems_per_stool"), r3);
    EXPECT_NEAR(*s.stand.stoolShare, want("stool_fraction"), r4);
}

INSTANTIATE_TEST_SUITE_P(Stands, StandStatisticsTable3,
                         ::testing::Values("GR1", "MO1", "MO2", "SP1", "SP2", "SP3", "PY1", "PY2"));

TEST(StandStatistics, SmallInventoryByHand) {
    // stems_ok.csv: plot 1 (20 x 20 m) holds a stool "7" of 12.5 and 10.0 cm at (2,3), (2.5,3.5) and a
    // single 30.2 cm tree at (15,15); plot 2 (10 x 10 m) a single 20 cm tree.
    const StandStatistics s = standStatistics(readInventory(data("stems_ok.csv"), data("plots_ok.csv")));
    const double areaHa = (400 + 100) / 1e4;
    EXPECT_EQ(s.stand.n, 4u);
    EXPECT_DOUBLE_EQ(s.stand.stemsPerHa, 4 / areaHa);
    const double sumSq = 0.0625 * 0.0625 + 0.050 * 0.050 + 0.151 * 0.151 + 0.100 * 0.100;  // radii in m
    EXPECT_NEAR(*s.stand.basalAreaM2Ha, M_PI * sumSq / areaHa, 1e-12);
    const double mean = (12.5 + 10.0 + 30.2 + 20.0) / 4;
    EXPECT_NEAR(*s.stand.meanDbhCm, mean, 1e-12);
    const double var = (std::pow(12.5 - mean, 2) + std::pow(10 - mean, 2) + std::pow(30.2 - mean, 2) +
                        std::pow(20 - mean, 2)) / 3;
    EXPECT_NEAR(*s.stand.sdDbhCm, std::sqrt(var), 1e-12);
    EXPECT_EQ(s.stand.nStools, 1u);
    EXPECT_DOUBLE_EQ(*s.stand.stemsPerStool, 2);
    EXPECT_DOUBLE_EQ(*s.stand.stoolShare, 0.5);

    ASSERT_EQ(s.plots.size(), 2u);
    const auto& p1 = s.plots[0].stats;
    EXPECT_DOUBLE_EQ(p1.stemsPerHa, 3 / 0.04);
    EXPECT_DOUBLE_EQ(*p1.stoolShare, 2.0 / 3);
    // nearest neighbours: the stool's stems at sqrt(0.5) from each other, the big tree 16.985 m away
    const double dObs = (2 * std::sqrt(0.5) + std::hypot(12.5, 11.5)) / 3;
    const double expected = 0.5 * std::sqrt(400.0 / 3);  // Eq. 25
    EXPECT_NEAR(*p1.clarkEvans.naive, dObs / expected, 1e-12);
    EXPECT_NEAR(*p1.clarkEvans.donnelly, dObs / (expected + (0.0514 + 0.0412 / std::sqrt(3.0)) * 80 / 3), 1e-12);
    // Plot 2 has one stem: no Clark-Evans index; the stand's is plot 1's.
    EXPECT_FALSE(s.plots[1].stats.clarkEvans.naive.has_value());
    EXPECT_FALSE(s.plots[1].stats.sdDbhCm.has_value());
    EXPECT_EQ(s.plotsInNaiveMean, 1u);
    EXPECT_DOUBLE_EQ(*s.stand.clarkEvans.naive, *p1.clarkEvans.naive);
}

// A stool id used in two plots names two stools (the plots' own numbering), not one of four stems.
TEST(StandStatistics, AStoolIdInTwoPlotsNamesTwoStools) {
    Inventory inv = readInventory(data("stems_ok.csv"), data("plots_ok.csv"));
    for (const double x : {2.0, 2.5}) {
        Stem s = inv.stems.front();  // of stool "7" in plot 1
        s.id = "p2-" + std::to_string(x);
        s.plot = "2";
        s.x = x;
        s.y = 2;
        inv.stems.push_back(s);
    }
    const StandStatistics s = standStatistics(inv);
    EXPECT_EQ(s.stand.nStools, 2u);
    EXPECT_DOUBLE_EQ(*s.stand.stemsPerStool, 2);
    EXPECT_EQ(s.plots[1].stats.nStools, 1u);
}

// Stems below breast height (DBH 0) have no basal area: a stand of them only has G = 0, and is warned
// of (it printed no G and no warning). Stems whose DBH is unknown leave G unknown.
TEST(StandStatistics, StemsBelowBreastHeightGiveNoBasalAreaAndAWarning) {
    const std::string stems = ::testing::TempDir() + "stems_all_below_breast_height.csv";
    std::ofstream(stems) << "plot,stem,x,y,dbh_cm\n1,1,2,3,0\n1,2,2.5,3.5,0\n1,3,15,15,0\n2,4,5,5,0\n";
    Inventory inv = readInventory(stems, data("plots_ok.csv"));
    const StandStatistics zero = standStatistics(inv);
    ASSERT_TRUE(zero.stand.basalAreaM2Ha.has_value());
    EXPECT_EQ(*zero.stand.basalAreaM2Ha, 0.0);
    EXPECT_FALSE(zero.stand.meanDbhCm.has_value());
    ASSERT_EQ(dataWarnings(inv, "s.csv", "p.csv").size(), 1u);
    EXPECT_NE(dataWarnings(inv, "s.csv", "p.csv")[0].find("4 below breast height"), std::string::npos);
    for (Stem& s : inv.stems) s.dbhCm = std::nan("");
    EXPECT_FALSE(standStatistics(inv).stand.basalAreaM2Ha.has_value());
}

TEST(StandStatistics, EmptyPlotLowersNAndG) {
    const StandStatistics with = standStatistics(readInventory(data("stems_ok.csv"), data("plots_with_empty_plot.csv")));
    const StandStatistics without = standStatistics(readInventory(data("stems_ok.csv"), data("plots_ok.csv")));
    ASSERT_EQ(with.plots.size(), 3u);
    EXPECT_TRUE(with.plots[2].empty);
    EXPECT_FALSE(with.plots[0].empty);
    EXPECT_EQ(with.plots[2].stats.n, 0u);
    EXPECT_DOUBLE_EQ(with.plots[2].stats.stemsPerHa, 0);
    EXPECT_FALSE(with.plots[2].stats.meanDbhCm.has_value());
    // 500 m² -> 600 m²: N and G scale by 5/6, the DBH statistics do not change.
    EXPECT_DOUBLE_EQ(with.stand.stemsPerHa, without.stand.stemsPerHa * 5 / 6);
    EXPECT_NEAR(*with.stand.basalAreaM2Ha, *without.stand.basalAreaM2Ha * 5 / 6, 1e-12);
    EXPECT_DOUBLE_EQ(*with.stand.meanDbhCm, *without.stand.meanDbhCm);
}

TEST(StandStatistics, PatternWithoutDiametersHasNoBasalArea) {
    const StandStatistics s = standStatistics(readPointPattern(data("points_no_dbh.csv"), Window::rectangle(0, 0, 10, 10)));
    EXPECT_DOUBLE_EQ(s.stand.stemsPerHa, 4 / 0.01);
    EXPECT_FALSE(s.stand.basalAreaM2Ha || s.stand.meanDbhCm || s.stand.sdDbhCm);
    EXPECT_TRUE(s.stand.clarkEvans.donnelly.has_value());
    EXPECT_EQ(s.stand.nStools, 0u);
    EXPECT_FALSE(s.stand.stemsPerStool.has_value());
}

}  // namespace

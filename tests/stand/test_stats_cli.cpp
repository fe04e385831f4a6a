// `sylvarock stats` end to end: the JSON the outside checks read, the table, the pcf file against
// spatstat, figures, and exit code 2 with file:line on bad input.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "libcommon/CsvTable.hpp"
#include "libstand/Inventory.hpp"
#include "libstand/StandStatistics.hpp"
#include "test_stand_statistics_data.hpp"

using namespace sylva::stand;
namespace td = sylva::stand::testdata;

namespace {

struct CliRun {
    int status = -1;
    std::string out, err;
};

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

CliRun stats(const std::string& args) {
    // One file pair per test: CTest runs the tests of this file in parallel processes.
    const std::string tag = ::testing::TempDir() + "/stats_cli_" + ::testing::UnitTest::GetInstance()->current_test_info()->name();
    const std::string out = tag + "_out.txt", err = tag + "_err.txt";
    const int rc = std::system((std::string(SYLVAROCK_CLI) + " stats " + args + " >" + out + " 2>" + err).c_str());
    return {WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, slurp(out), slurp(err)};
}

std::string data(const std::string& file) { return std::string(SYLVAROCK_TEST_DATA) + "/stand/" + file; }
std::string stand(const std::string& file) { return std::string(SYLVAROCK_DATA) + "/stands/" + file; }

// The first `"key": value` after `from` in the JSON text; NaN for null.
double jsonNumber(const std::string& json, const std::string& key, std::size_t from = 0) {
    const std::regex re("\"" + key + "\": (null|[-+0-9.eE]+)");
    std::smatch m;
    const std::string tail = json.substr(from);
    if (!std::regex_search(tail, m, re)) throw std::runtime_error("no key " + key);
    return m[1] == "null" ? NAN : std::stod(m[1]);
}

TEST(StatsCli, InventoryJsonCarriesStandAndPlots) {
    const CliRun r = stats("--stems " + stand("SP2_stems.csv") + " --plots " + stand("SP2_plots.csv") + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const StandStatistics lib = standStatistics(readInventory(stand("SP2_stems.csv"), stand("SP2_plots.csv")));
    const std::size_t at = r.out.find("\"stand\": {");
    ASSERT_NE(at, std::string::npos);
    // %.10g: ten significant digits, so 1e-9 relative.
    const auto same = [](double got, double want) { EXPECT_NEAR(got, want, 1e-9 * std::abs(want)); };
    same(jsonNumber(r.out, "stems_per_ha", at), lib.stand.stemsPerHa);
    same(jsonNumber(r.out, "basal_area_m2_ha", at), *lib.stand.basalAreaM2Ha);
    same(jsonNumber(r.out, "mean_dbh_cm", at), *lib.stand.meanDbhCm);
    same(jsonNumber(r.out, "sd_dbh_cm", at), *lib.stand.sdDbhCm);
    same(jsonNumber(r.out, "stool_share", at), *lib.stand.stoolShare);
    same(jsonNumber(r.out, "donnelly", at), *lib.stand.clarkEvans.donnelly);
    EXPECT_NE(r.out.find("\"note\": \"the stand's Clark-Evans indices are the means of the per-plot values"),
              std::string::npos);
    const std::size_t plots = r.out.find("\"plots\": [");
    ASSERT_NE(plots, std::string::npos);
    EXPECT_NE(r.out.find("\"id\": \"8\"", plots), std::string::npos);
    EXPECT_NE(r.out.find("\"empty\": false", plots), std::string::npos);
    same(jsonNumber(r.out, "stems_per_ha", plots), lib.plots[0].stats.stemsPerHa);
}

TEST(StatsCli, TableIsTheDefault) {
    const CliRun r = stats("--stems " + data("stems_ok.csv") + " --plots " + data("plots_with_empty_plot.csv"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("Stand stems_ok: 3 plots"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Plot 3 has no stem"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("means of the per-plot values"), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("warning: "), std::string::npos) << r.err;  // the empty plots
}

TEST(StatsCli, PointsInRectangleAndPolygon) {
    const CliRun rect = stats("--points " + data("points_ok.csv") + " --window 0,0,10,10 --json");
    ASSERT_EQ(rect.status, 0) << rect.err;
    EXPECT_DOUBLE_EQ(jsonNumber(rect.out, "stems_per_ha"), 3 / 0.01);
    EXPECT_FALSE(std::isnan(jsonNumber(rect.out, "donnelly")));
    const CliRun poly = stats("--points " + data("points_ok.csv") +
                           " --window-wkt 'POLYGON((0 0, 10 0, 10 10, 0 10, 0 0))' --json");
    ASSERT_EQ(poly.status, 0) << poly.err;
    EXPECT_TRUE(std::isnan(jsonNumber(poly.out, "donnelly")));  // null: Donnelly needs a rectangle
    EXPECT_DOUBLE_EQ(jsonNumber(poly.out, "guard"), jsonNumber(rect.out, "guard"));
    const CliRun nodbh = stats("--points " + data("points_no_dbh.csv") + " --window 0,0,10,10 --json");
    ASSERT_EQ(nodbh.status, 0) << nodbh.err;
    EXPECT_TRUE(std::isnan(jsonNumber(nodbh.out, "basal_area_m2_ha")));
}

// Issue 13: spatstat's gordon, whose window has two holes, was refused.
TEST(StatsCli, PointsInAWindowWithHoles) {
    std::string wkt = slurp(td::spatstatDir() + "gordon_window.txt");
    wkt = wkt.substr(wkt.find("POLYGON"));
    wkt.erase(wkt.find_last_not_of("\n") + 1);
    const CliRun r = stats("--points " + td::spatstatDir() + "gordon_points.csv --window-wkt '" + wkt + "' --json");
    ASSERT_EQ(r.status, 0) << r.err;
    // The holes are out of the area (2 163.8 m2, not the outer ring's 2 244.6) and the boundary
    // (spatstat's clarkevans() guard index on the same window: test_window_holes.cpp).
    EXPECT_NEAR(jsonNumber(r.out, "stems_per_ha"), 99 / 0.21637679027576, 1e-6);
    EXPECT_NEAR(jsonNumber(r.out, "guard"), 0.641794224593362, 1e-9);
}

TEST(StatsCli, PcfFileAgreesWithSpatstat) {
    const std::string csv = ::testing::TempDir() + "/stats_cli_pcf.csv";
    const CliRun r = stats("--points " + td::spatstatDir() + "spruces_points.csv --window 0,0,56,38 --pcf-rmax 9.5 "
                        "--pcf-nr 51 --pcf-out " + csv);
    ASSERT_EQ(r.status, 0) << r.err;
    const sylva::CsvTable t = sylva::CsvTable::parse(slurp(csv), csv);
    ASSERT_EQ(t.header(), (std::vector<std::string>{"r", "g_trans", "g_iso"}));
    const td::ReferencePcf ref = td::spatstatPcf("spruces");
    ASSERT_EQ(t.rows(), ref.r.size() + 1);
    int compared = 0;
    for (std::size_t k = 0; k < ref.r.size(); ++k) {
        if (ref.trans[k] <= 0.1) continue;
        // The 1e-3 (the library agrees to ~1e-14; the file's %.10g adds 1e-10).
        EXPECT_NEAR(t.number(k + 1, 1), ref.trans[k], 1e-3 * ref.trans[k]) << ref.r[k];
        EXPECT_NEAR(t.number(k + 1, 2), ref.iso[k], 1e-3 * ref.iso[k]) << ref.r[k];
        ++compared;
    }
    EXPECT_GT(compared, 40);
}

// The folder is created with its parents (issue 13: with a missing parent gnuplot printed the SVG
// on the terminal).
TEST(StatsCli, FiguresWithGnuplot) {
    const std::string dir = ::testing::TempDir() + "/stats_cli_figures/nested/deeper";
    std::filesystem::remove_all(::testing::TempDir() + "/stats_cli_figures");
    const CliRun r = stats("--stems " + data("stems_ok.csv") + " --plots " + data("plots_ok.csv") + " --plot-dir " + dir);
    ASSERT_EQ(r.status, 0) << r.err;  // never fails because of figures
    EXPECT_EQ(r.out.find("<svg"), std::string::npos) << "an SVG went to the terminal";
    // The figure's numbers are written with or without gnuplot: g(r) and its CSR envelope.
    const std::string pcf = slurp(dir + "/pcf.csv");
    EXPECT_EQ(pcf.substr(0, pcf.find('\n')), "r,g_trans,g_iso,csr_trans_low,csr_trans_high");
    EXPECT_GT(std::count(pcf.begin(), pcf.end(), '\n'), 500);
    const std::string plain = ::testing::TempDir() + "/stats_cli_figures/plain";
    ASSERT_EQ(stats("--stems " + data("stems_ok.csv") + " --plots " + data("plots_ok.csv") + " --plot-dir " + plain + " --envelope 0").status, 0);
    const std::string noEnvelope = slurp(plain + "/pcf.csv");
    EXPECT_EQ(noEnvelope.substr(0, noEnvelope.find('\n')), "r,g_trans,g_iso");
    EXPECT_EQ(stats("--stems " + data("stems_ok.csv") + " --plots " + data("plots_ok.csv") + " --plot-dir " + plain + " --envelope -1").status, 2);
    if (std::system("gnuplot --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot not installed";
    EXPECT_NE(slurp(dir + "/pcf.svg").find("<svg"), std::string::npos);
    EXPECT_NE(slurp(dir + "/dbh_histogram.svg").find("<svg"), std::string::npos);
}

TEST(StatsCli, BadInputExitsWithFileAndLine) {
    const CliRun r = stats("--stems " + data("stems_negative_dbh.csv") + " --plots " + data("plots_ok.csv"));
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find(data("stems_negative_dbh.csv") + ":3:"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty());
}

// Results printed to a full disk were lost with exit 0 (stats --json > results.json): the write's
// failure is an error (/dev/full fails every write, as a full disk does).
TEST(StatsCli, AnUnwritableStandardOutputIsAnError) {
    const std::string err = ::testing::TempDir() + "/stats_cli_full_err.txt";
    const int rc = std::system((std::string(SYLVAROCK_CLI) + " stats --stems " + stand("GR1_stems.csv") + " --plots " +
                                stand("GR1_plots.csv") + " --json >/dev/full 2>" + err).c_str());
    EXPECT_EQ(WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, 2);
    EXPECT_NE(slurp(err).find("sylvarock stats: error: cannot write the standard output"), std::string::npos) << slurp(err);
}

TEST(StatsCli, InconsistentOptionsExit2) {
    EXPECT_EQ(stats("--points " + data("points_ok.csv")).status, 2);
    EXPECT_EQ(stats("--stems " + data("stems_ok.csv")).status, 2);
    const CliRun three = stats("--points " + data("points_ok.csv") + " --window 0,0,10");
    EXPECT_EQ(three.status, 2);
    EXPECT_EQ(three.err.find("--window: --window"), std::string::npos) << three.err;  // named once
    EXPECT_NE(three.err.find("--window: expected 4 comma-separated numbers"), std::string::npos) << three.err;
    const CliRun flat = stats("--points " + data("points_ok.csv") + " --window 0,0,0,4");
    EXPECT_EQ(flat.status, 2);
    EXPECT_NE(flat.err.find("--window: degenerate window"), std::string::npos) << flat.err;
    const CliRun r = stats("--points " + data("points_ok.csv") + " --window-wkt 'POLYGON((0 0, 1 1))'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--window-wkt"), std::string::npos) << r.err;
    // g(r) past a window's shortest side is undefined (it read 0 there, and was written so).
    const std::string csv = ::testing::TempDir() + "/stats_cli_far.csv";
    std::filesystem::remove(csv);
    const CliRun far = stats("--points " + td::spatstatDir() + "spruces_points.csv --window 0,0,56,38 --pcf-rmax 38 --pcf-out " + csv);
    EXPECT_EQ(far.status, 2);
    EXPECT_NE(far.err.find("--pcf-rmax 38 m reaches past the 38 m shortest side of the window"), std::string::npos) << far.err;
    EXPECT_FALSE(std::filesystem::exists(csv));
    const CliRun inventory = stats("--stems " + stand("MO1_stems.csv") + " --plots " + stand("MO1_plots.csv") + " --pcf-rmax 500 --pcf-out " + csv);
    EXPECT_EQ(inventory.status, 2);
    EXPECT_NE(inventory.err.find("shortest side of plot 1"), std::string::npos) << inventory.err;
}

}  // namespace

// Two billion values of r asked for 16 GB and ended in std::bad_alloc: refused with the option's name.
TEST(StatsCli, AnAbsurdNumberOfRValuesIsRefused) {
    const CliRun r = stats("--points " + td::spatstatDir() + "spruces_points.csv --window 0,0,56,38 --pcf-nr 2000000000 "
                           "--pcf-out " + ::testing::TempDir() + "/stats_cli_pcf_huge.csv");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("--pcf-nr 2000000000: give 2 to 1 000 000 values of r"), std::string::npos) << r.err;
}


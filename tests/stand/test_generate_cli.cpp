// `sylvarock generate` end to end: the interface the outside checks call, file naming of realisations,
// and the exit status and message of bad options.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "libstand/Forest.hpp"

using namespace sylva::stand;

#include "../CliRun.hpp"

namespace {

using sylva::testing::CliRun;

CliRun generate(const std::string& arguments) {
    const std::string stand = std::string(SYLVAROCK_DATA) + "/stands/PY2";
    return sylva::testing::runCli("generate --stems " + stand + "_stems.csv --plots " + stand + "_plots.csv " + arguments);
}

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

bool exists(const std::string& path) { return std::ifstream(path).good(); }

}  // namespace

TEST(GenerateCli, WritesTheForestTheChecksRead) {
    const std::string out = ::testing::TempDir() + "cli_PY2_A.csv";
    const CliRun r = generate("--structure aggregated --extent 0,0,100,50 --seed 7 --out " + out);
    ASSERT_EQ(r.status, 0) << r.output;
    const Forest f = readForestCsv(out);
    ASSERT_EQ(f.trees.size(), 486u);  // 972 stems/ha (1944 stems in 2 ha) x 0.5 ha
    std::set<long> stools;
    for (std::size_t i = 0; i < f.trees.size(); ++i) {
        EXPECT_EQ(f.trees[i].id, static_cast<long>(i) + 1);
        EXPECT_TRUE(f.trees[i].x >= 0 && f.trees[i].x <= 100 && f.trees[i].y >= 0 && f.trees[i].y <= 50);
        if (f.trees[i].stool) stools.insert(*f.trees[i].stool);
    }
    EXPECT_FALSE(stools.empty());
    EXPECT_EQ(*stools.begin(), 1);
    EXPECT_EQ(*stools.rbegin(), static_cast<long>(stools.size()));
    EXPECT_EQ(slurp(out).substr(0, 68), "stem,x,y,dbh_cm,species,stool,height_m,crown_length_m,crown_mass_kg\n");
}

TEST(GenerateCli, RealisationsAreNumberedAndUseConsecutiveSeeds) {
    const std::string dir = ::testing::TempDir();
    ASSERT_EQ(generate("--structure random --extent 0,0,60,40 --seed 5 --realisations 2 --out " + dir + "cli_F.csv").status, 0);
    ASSERT_TRUE(exists(dir + "cli_F_001.csv"));
    ASSERT_TRUE(exists(dir + "cli_F_002.csv"));
    EXPECT_FALSE(exists(dir + "cli_F_003.csv"));
    ASSERT_EQ(generate("--structure random --extent 0,0,60,40 --seed 6 --out " + dir + "cli_G_{k}.csv").status, 0);
    ASSERT_TRUE(exists(dir + "cli_G_001.csv"));
    EXPECT_EQ(slurp(dir + "cli_F_002.csv"), slurp(dir + "cli_G_001.csv"));  // realisation k uses seed + k - 1
    EXPECT_NE(slurp(dir + "cli_F_001.csv"), slurp(dir + "cli_F_002.csv"));
}

TEST(GenerateCli, BadOptionsExitWithStatusTwoAndSayWhy) {
    const std::string out = " --out " + ::testing::TempDir() + "cli_bad.csv";
    CliRun r = generate("--structure clustered --extent 0,0,100,50" + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("unknown forest structure 'clustered'"), std::string::npos) << r.output;
    r = generate("--structure random --extent 0,0,0,50" + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("degenerate extent"), std::string::npos) << r.output;
    r = generate("--structure random --extent 0,0,100" + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("expected 4"), std::string::npos) << r.output;
    // A last comma once went unnoticed (getline drops the empty word after it).
    r = generate("--structure random --extent 0,0,100,50," + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("--extent: '0,0,100,50,' ends without a number"), std::string::npos) << r.output;
    // An output that cannot be written says why (it said "cannot open file for writing" alone).
    r = generate("--structure random --extent 0,0,100,50 --out " + ::testing::TempDir());
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("is a folder: give a file's name to write"), std::string::npos) << r.output;
    r = generate("--structure random --extent 0,0,100,50 --out " + ::testing::TempDir() + "no-such-folder/f.csv");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("no-such-folder does not exist"), std::string::npos) << r.output;
    // An empty value (a shell variable left unset) was told it "ends without a number".
    r = generate("--structure random --extent ''" + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("--extent is empty: expected 4 comma-separated numbers"), std::string::npos) << r.output;
    r = generate("--structure random --extent 0,0,100,50 --realisations 0" + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("--realisations"), std::string::npos) << r.output;
    r = generate("--structure random --extent 0,0,100,50 --seed -3" + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("--seed"), std::string::npos) << r.output;
    // A word is not told of 64-bit seeds that generate would refuse next (it keeps 32 bits).
    r = generate("--structure random --extent 0,0,100,50 --seed abc" + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("--seed 'abc': a seed is a whole number (0, 1, 2, ...)"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("18446744073709551615"), std::string::npos) << r.output;
    r = generate("--structure random --extent 0,0,100,50 --seed 18446744073709551616" + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("--seed '18446744073709551616': too large a number for a seed"), std::string::npos) << r.output;
    // GSL keeps 32 bits of a seed: 4294967297 would draw seed 1's forest, and the second forest from
    // 4294967295 seed 0's.
    for (const char* seeds : {"--seed 4294967297", "--seed 4294967295 --realisations 2"}) {
        r = generate(std::string("--structure random --extent 0,0,100,50 ") + seeds + out);
        EXPECT_EQ(r.status, 2) << seeds;
        EXPECT_NE(r.output.find("must stay within 0 to 4294967295"), std::string::npos) << r.output;
    }
    // An extent too small for one stem: an empty forest would go on as a forest that stops nothing.
    const std::string tiny = ::testing::TempDir() + "cli_tiny.csv";
    std::filesystem::remove(tiny);
    r = generate("--structure random --extent 0,0,1,1 --out " + tiny);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("stems, not one"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(tiny));
}

// A stool's position given to each of its stems: generate wrote a forest with two stems at one place,
// which simulate refuses ("stands where the stem of line 2 stands"). Its stems now stand apart.
TEST(GenerateCli, AStoolRecordedAtOnePointGivesAForestSimulateReads) {
    const std::string dir = ::testing::TempDir();
    {
        std::ofstream stems(dir + "cli_point_stems.csv");
        stems << "plot,stem,x,y,dbh_cm,species,stool\n1,1,10,10,20,beech,1\n1,2,10,10,18,beech,1\n"
                 "1,3,30,20,25,beech,\n1,4,20,30,22,beech,2\n1,5,20,30,12,beech,2\n1,6,20,30,16,beech,2\n";
        std::ofstream plots(dir + "cli_point_plots.csv");
        plots << "plot,xmin,ymin,xmax,ymax\n1,0,0,50,50\n";
    }
    const std::string out = dir + "cli_point_A.csv";
    const CliRun r = sylva::testing::runCli("generate --stems " + dir + "cli_point_stems.csv --plots " + dir +
                                            "cli_point_plots.csv --structure aggregated --extent 0,0,200,200 --seed 3 --out " + out);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("cli_point_stems.csv:3: stem '2' is at the same position (10, 10) as stem '1' (line 2) (its "
                            "stool's position given to both?)"),
              std::string::npos) << r.output;
    EXPECT_NE(r.output.find("on a ring around it, touching at breast height"), std::string::npos) << r.output;
    const Forest f = readForestCsv(out);  // threw on the old code
    EXPECT_EQ(f.trees.size(), 96u);       // 6 stems in 0.25 ha, over 4 ha
}

// A --plot-dir that cannot be made is refused before any forest is written: found after them, it
// left the forests behind a failed command (exit 2), to be taken for its output.
TEST(GenerateCli, AnUnmakeablePlotDirIsRefusedBeforeAnyForestIsWritten) {
    const std::string dir = ::testing::TempDir() + "/generate_cli_plot_dir/";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::ofstream(dir + "a_file") << "not a folder\n";
    const CliRun r = generate("--structure random --extent 0,0,60,40 --seed 5 --out " + dir + "F.csv --plot-dir " + dir + "a_file/fig");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("--plot-dir"), std::string::npos) << r.output;
    EXPECT_FALSE(exists(dir + "F.csv"));
}

// Figures for people (issue 13): the virtual forests' g(r) against the inventory's and its CSR
// envelope, and a map; the numbers are written with or without gnuplot. The folder's name has an
// apostrophe and a space, which once ended gnuplot's quoted paths early and lost every figure.
TEST(GenerateCli, FiguresCompareTheForestsWithTheInventory) {
    const std::string dir = ::testing::TempDir() + "/generate_cli_figures/the stand's figures/";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const CliRun r = generate("--structure aggregated --extent 0,0,100,60 --seed 3 --realisations 2 --out \"" + dir +
                              "F.csv\" --plot-dir \"" + dir + "fig\"");
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string csv = slurp(dir + "fig/pcf_vs_inventory.csv");
    EXPECT_EQ(csv.substr(0, csv.find('\n')), "r,g_trans,g_iso,csr_trans_low,csr_trans_high,forest1_g_trans,forest2_g_trans");
    // A strip 8 m wide: the forest's g is undefined past 8 m (it read 0 there), so it is NA, and a number below.
    const CliRun strip = generate("--structure random --extent 0,0,300,8 --seed 3 --out \"" + dir + "S.csv\" --plot-dir \"" + dir + "strip\"");
    ASSERT_EQ(strip.status, 0) << strip.output;
    std::istringstream rows(slurp(dir + "strip/pcf_vs_inventory.csv"));
    std::string row;
    std::getline(rows, row);
    int below = 0, beyond = 0;
    while (std::getline(rows, row)) {
        const double r = std::stod(row.substr(0, row.find(',')));
        const std::string forest = row.substr(row.rfind(',') + 1);
        if (r >= 8) {
            EXPECT_EQ(forest, "NA") << row;
            ++beyond;
        } else if (r > 1) {
            EXPECT_NE(forest, "NA") << row;
            ++below;
        }
    }
    EXPECT_GT(below, 0);
    EXPECT_GT(beyond, 0);
    if (std::system("gnuplot --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot not installed";
    EXPECT_NE(slurp(dir + "fig/pcf_vs_inventory.svg").find("<svg"), std::string::npos);
    EXPECT_NE(slurp(dir + "fig/forest_map.svg").find("<svg"), std::string::npos);
}

// The command line teaches itself: the top-level help lists every command in a study's order, and each command's
// --help exits cleanly. (A command name longer than the help's column once crashed the listing.)
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <utility>
#include <sstream>
#include <string>
#include <vector>

#include "../CliRun.hpp"

using sylva::testing::runCli;

namespace {

// The command names printed by `sylvarock --help`: the first word of each indented line after "Commands:".
std::vector<std::string> listedCommands(const std::string& help) {
    std::vector<std::string> names;
    std::istringstream lines(help.substr(help.find("Commands:")));
    std::string line;
    std::getline(lines, line);
    while (std::getline(lines, line))
        if (line.rfind("  ", 0) == 0) names.push_back(line.substr(2, line.find(' ', 2) - 2));
    return names;
}

}  // namespace

TEST(CliHelp, TopLevelHelpListsEveryCommandInAStudysOrderAndEachCommandsHelpWorks) {
    const auto top = runCli("--help");
    ASSERT_EQ(top.status, 0) << top.output;
    const auto names = listedCommands(top.output);
    // Every command, in the order a study uses them (not the link order the registrations ran in).
    const std::vector<std::string> study = {"stats", "generate", "simulate", "assess", "hazard", "calibrate-lumped", "scene"};
    EXPECT_EQ(names, study) << top.output;
    for (const auto& name : names) {
        const auto help = runCli(name + " --help");
        EXPECT_EQ(help.status, 0) << name << ":\n" << help.output;
        EXPECT_NE(help.output.find("sylvarock " + name), std::string::npos) << name << ":\n" << help.output;
    }
}

TEST(CliHelp, NoCommandOrAnUnknownOneIsAUsageError) {
    EXPECT_EQ(runCli("").status, 2);
    const auto unknown = runCli("simulat");
    EXPECT_EQ(unknown.status, 2) << unknown.output;
    EXPECT_NE(unknown.output.find("sylvarock: error: unknown command 'simulat'"), std::string::npos) << unknown.output;
}

// A refused option says "error:" as every other refusal does, so that a script grepping for it finds it.
TEST(CliHelp, AnUnknownOptionIsAnErrorForEveryCommand) {
    for (const auto& name : listedCommands(runCli("--help").output)) {
        const auto bogus = runCli(name + " --bogus");
        EXPECT_EQ(bogus.status, 2) << name << ":\n" << bogus.output;
        EXPECT_NE(bogus.output.find("sylvarock " + name + ": error: unrecognised option '--bogus'"), std::string::npos)
            << name << ":\n" << bogus.output;
    }
}

// A word no option takes is refused, not dropped: "--runs 2 000" once ran 2 runs without a word.
TEST(CliHelp, AStrayWordIsRefusedByEveryCommand) {
    for (const auto& name : listedCommands(runCli("--help").output)) {
        const auto stray = runCli(name + " --help 000");
        EXPECT_EQ(stray.status, 2) << name << ":\n" << stray.output;
        EXPECT_NE(stray.output.find("'000' belongs to no option"), std::string::npos) << name << ":\n" << stray.output;
    }
    // Two values after a repeatable option (as a shell's brace expansion gives): repeat the option.
    const auto two = runCli("assess --stand data/stands/GR1 data/stands/MO1 --out x");
    EXPECT_EQ(two.status, 2) << two.output;
    EXPECT_NE(two.output.find("repeat the option (--stand data/stands/GR1 --stand data/stands/MO1)"), std::string::npos) << two.output;
}

// --config (options from a file, as on the command line): a refused value or key names the file and
// its line, as a scene file's refusals do; it named the file alone.
TEST(CliHelp, AConfigFileRefusalNamesItsLine) {
    const std::string path = ::testing::TempDir() + "cli_config_refusal.ini";
    for (const auto& [text, line] : {std::pair<const char*, const char*>{"# a campaign\nruns = 5\n\nseed = x\n", ":4:"},
                                     {"runs = 5\nthreads = two\n", ":2:"},
                                     {"runs = 5\n\nrun = 6\n", ":3:"},
                                     // Boost refuses the unknown key before it reads any value.
                                     {"seed = x\nruns = 5\nbogus = 1\n", ":3: unrecognised option 'bogus'"},
                                     // Lines ended by a carriage return alone are lines.
                                     {"runs = 5\rthreads = two\r", ":2:"}}) {
        std::ofstream(path) << text;
        const auto r = runCli("simulate --scene data/scenes/no-forest.ini --config " + path + " --out " +
                              ::testing::TempDir() + "cli_config_refusal");
        EXPECT_EQ(r.status, 2) << r.output;
        EXPECT_NE(r.output.find(path + line), std::string::npos) << text << "\n" << r.output;
    }
}

#pragma once
// The sylvarock command line: subcommands register themselves in a table (one file per
// subcommand), and share one way of reading options from the command line and INI files.
#include <boost/program_options.hpp>
#include <string>
#include <vector>

namespace sylva::cli {

namespace po = boost::program_options;

struct Command {
    int place;            // where it comes in a study, which `sylvarock --help` lists them by
    std::string name;
    std::string summary;  // one line for `sylvarock --help`
    int (*run)(int argc, const char* const* argv);  // argv[0] is the subcommand's name
    bool spreadsOverRanks = false;  // runs under mpirun with several ranks (see libassess/MpiWorld.hpp)
};

// In the order of their places (registration order is the link order's, which nobody chose).
const std::vector<Command>& commands();

// A file-scope instance of this in cmd_<name>.cpp puts the subcommand in the table.
struct CommandRegistration {
    explicit CommandRegistration(Command c);
};

// Parses argv into vm. Adds --help and --config FILE (an INI file whose keys are the long option
// names; command-line values win over the file's). Returns false if --help was given (the usage,
// the description and the example text were printed). Throws po::error on a bad option and
// InputError on an unreadable config file.
bool parse(int argc, const char* const* argv, const po::options_description& options, po::variables_map& vm,
           const std::string& usage, const std::string& examples = {});

// Splits "a,b,c" into numbers, requiring exactly n of them (n == 0: any count); throws InputError
// naming the option on a bad list.
std::vector<double> numberList(const std::string& option, const std::string& text, std::size_t n = 0);

// A campaign seed: a whole number in [0, 2^64). program_options alone would read "-1" as 2^64 - 1.
struct Seed {
    unsigned long value = 1;
};
void validate(boost::any& v, const std::vector<std::string>& tokens, Seed*, int);

// --threads: 0 (all cores) or a count; throws InputError on a negative or absurd one.
int threadCount(const po::variables_map& vm);

// True when standard error is a terminal (progress bars are drawn only then).
bool stderrIsTerminal();

// Exit status of a command that finished and wrote its results, but with runs that stopped on a
// numerical error (left out of the statistics and listed): scripts must not take it for success.
inline constexpr int kRunsFailed = 3;

// `--forest F.csv` as simulate and scene export take it: the scene key forest.file, made absolute
// (paths in a scene are relative to the scene file) and placed first so that it wins.
inline constexpr const char* kForestHelp =
    "forest CSV (sylvarock generate's, or any x,y,dbh_cm[,stool] tree file) in the terrain's frame";
void applyForestOption(const po::variables_map& vm, std::vector<std::string>& sets);

}  // namespace sylva::cli

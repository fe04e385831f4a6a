#include "Cli.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "libdem/OptionErrorMessage.hpp"
#include "libcommon/InputError.hpp"
#include "libcommon/LineEnds.hpp"

namespace sylva::cli {

namespace {
std::vector<Command>& table() {
    static std::vector<Command> t;
    return t;
}
}  // namespace

const std::vector<Command>& commands() { return table(); }

namespace {
// Boost names the option a config file got wrong but not its line: each line is read again on its
// own (under its section) until one is refused with the same message (Boost refuses an unknown key
// while reading, before any value, so the first refused line need not be the one it named). 0 when
// none is (a key given twice).
long refusedLine(const std::string& text, const po::options_description& options, const std::string& message) {
    std::istringstream in(text);
    std::string line, section;
    for (long n = 1; std::getline(in, line); ++n) {
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        if (line[first] == '[') {
            section = line;
            continue;
        }
        std::istringstream alone(section + "\n" + line + "\n");
        po::variables_map scratch;
        try {
            po::store(po::parse_config_file(alone, options), scratch);
        } catch (const po::error& e) {
            if (optionErrorMessage(e) == message) return n;
        }
    }
    return 0;
}
}  // namespace

CommandRegistration::CommandRegistration(Command c) {
    auto& t = table();
    const auto after = std::upper_bound(t.begin(), t.end(), c.place, [](int place, const Command& d) { return place < d.place; });
    t.insert(after, std::move(c));
}

bool parse(int argc, const char* const* argv, const po::options_description& options, po::variables_map& vm,
           const std::string& usage, const std::string& examples) {
    po::options_description common("General");
    common.add_options()("help,h", "print this help")(
        "config", po::value<std::string>(), "read options from an INI file (key = value, keys as the long options)");
    po::options_description all;
    all.add(options).add(common);
    const po::parsed_options parsed = po::command_line_parser(argc, argv).options(all).run();
    // No command takes words of its own: one here is a value cut off its option ("--runs 2 000")
    // or a typo, and program_options would drop it without a word.
    const po::option* previous = nullptr;
    for (const po::option& o : parsed.options) {
        if (o.position_key >= 0) {
            std::string hint = "a number is written without spaces, and each option takes one value";
            const po::option_description* before =
                previous && previous->position_key < 0 && !previous->value.empty() ? all.find_nothrow(previous->string_key, false) : nullptr;
            if (before && before->semantic()->is_composing())  // a repeatable option (--stand, --set)
                hint += ": for a second value, repeat the option (--" + previous->string_key + " " + previous->value.front() + " --" +
                        previous->string_key + " " + o.value.front() + ")";
            throw InputError("'" + o.value.front() + "' belongs to no option (" + hint + ")");
        }
        previous = &o;
    }
    po::store(parsed, vm);
    if (vm.count("help")) {
        std::cout << "usage: " << usage << "\n\n" << all << "\n";
        if (!examples.empty()) std::cout << "Examples:\n" << examples << "\n";
        return false;
    }
    if (vm.count("config")) {
        const std::string path = vm["config"].as<std::string>();
        if (std::filesystem::is_directory(path)) throw InputError(path, 0, "is a folder, not a config file");
        std::ifstream file(path);
        if (!file) throw InputError(path, 0, "cannot open config file");
        std::stringstream read;
        read << file.rdbuf();
        const std::string text = withCrOnlyLineEndsAsLineFeeds(read.str());
        std::istringstream in(text);
        try {
            po::store(po::parse_config_file(in, options), vm);
        } catch (const po::error& e) {
            const std::string message = optionErrorMessage(e);
            throw InputError(path, refusedLine(text, options, message), message);
        }
    }
    po::notify(vm);
    return true;
}

void validate(boost::any& v, const std::vector<std::string>& tokens, Seed*, int) {
    po::validators::check_first_occurrence(v);  // as Boost's own validators do: a second --seed is refused
    const std::string& t = po::validators::get_single_string(tokens);
    errno = 0;
    char* end = nullptr;
    const unsigned long long n = t.empty() || t[0] == '-' || t[0] == '+' ? 0 : std::strtoull(t.c_str(), &end, 10);
    // No largest seed is named: commands whose generator keeps fewer bits (generate's 32) say their own
    // bound, and a user told 2^64 - 1 would be refused again.
    if (!end || *end != '\0') throw po::error("--seed '" + t + "': a seed is a whole number (0, 1, 2, ...)");
    if (errno == ERANGE) throw po::error("--seed '" + t + "': too large a number for a seed");
    v = Seed{static_cast<unsigned long>(n)};
}

int threadCount(const po::variables_map& vm) {
    const int t = vm["threads"].as<int>();
    if (t < 0 || t > 4096)
        throw InputError("--threads " + std::to_string(t) + ": give 0 (all cores) or a number of threads from 1 to 4096");
    return t;
}

std::vector<double> numberList(const std::string& option, const std::string& text, std::size_t n) {
    const std::string expected = n != 0 ? std::to_string(n) + " comma-separated numbers" : "a comma-separated list of numbers";
    if (text.empty()) throw InputError("--" + option + " is empty: expected " + expected);
    std::vector<double> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        errno = 0;
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (item.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
            throw InputError("--" + option + ": '" + item + "' is not a number (expected a comma-separated list)");
        out.push_back(v);
    }
    // getline drops the empty word after a last comma: "130,0,630,200," read as four numbers.
    if (text.back() == ',')
        throw InputError("--" + option + ": '" + text + "' ends without a number (expected a comma-separated list)");
    if (n != 0 && out.size() != n)
        throw InputError("--" + option + ": expected " + std::to_string(n) + " comma-separated numbers, got " +
                         std::to_string(out.size()) + " in '" + text + "'");
    return out;
}

bool stderrIsTerminal() { return isatty(STDERR_FILENO) != 0; }

void applyForestOption(const po::variables_map& vm, std::vector<std::string>& sets) {
    if (vm.count("forest"))
        sets.insert(sets.begin(), "forest.file=" + std::filesystem::absolute(vm["forest"].as<std::string>()).string());
}

}  // namespace sylva::cli

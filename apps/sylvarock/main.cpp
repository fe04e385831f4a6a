// sylvarock: one executable, one subcommand per task (see Cli.hpp for how they register).
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "Cli.hpp"
#include "libassess/MpiWorld.hpp"
#include "libdem/OptionErrorMessage.hpp"
#include "libcommon/BuildId.hpp"
#include "libcommon/InputError.hpp"

namespace {

void printUsage(std::ostream& os) {
    os << "usage: sylvarock <command> [options]   (sylvarock <command> --help for each command's options)\n\n"
          "How well does a mountain forest protect what lies below it from rockfall? A study describes its\n"
          "stands (stats), draws virtual forests from them (generate), runs blocks through them (simulate)\n"
          "and ranks the stands by their protection (assess); on a real slope, hazard maps it.\n\nCommands:\n";
    std::size_t width = 0;
    for (const auto& c : sylva::cli::commands()) width = std::max(width, c.name.size());
    for (const auto& c : sylva::cli::commands()) os << "  " << c.name << std::string(width + 2 - c.name.size(), ' ') << c.summary << "\n";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "help")) {
        printUsage(argc < 2 ? std::cerr : std::cout);
        return argc < 2 ? 2 : 0;
    }
    if (!std::strcmp(argv[1], "--version")) {
        std::cout << "sylvarock 0.1.0 (build " << sylva::buildId() << ")\n";
        return 0;
    }
    for (const auto& c : sylva::cli::commands()) {
        if (c.name != argv[1]) continue;
        try {
            const sylva::assess::MpiWorld world(&argc, &argv);
            if (world.size() > 1 && !c.spreadsOverRanks)
                world.agree(world.coordinator() ? std::make_exception_ptr(sylva::InputError(
                                                      "sylvarock " + c.name + " does not spread over MPI ranks: run it "
                                                      "without mpirun (sylvarock assess does)"))
                                                : nullptr);
            const int status = c.run(argc - 1, argv + 1);
            // Results printed to a full disk (stats --json > results.json) were lost with exit 0.
            std::cout.flush();
            if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout)) {
                std::cerr << "sylvarock " << c.name << ": error: cannot write the standard output (a full disk?): what it printed is incomplete\n";
                return status == 0 ? 2 : status;
            }
            return status;
        } catch (const sylva::assess::PeerFailed&) {
            return 0;
        } catch (const sylva::InputError& e) {
            std::cerr << "sylvarock " << c.name << ": error: " << e.what() << "\n";
            return 2;
        } catch (const boost::program_options::error& e) {
            std::cerr << "sylvarock " << c.name << ": error: " << sylva::optionErrorMessage(e) << " (see sylvarock " << c.name
                      << " --help)\n";
            return 2;
        } catch (const std::filesystem::filesystem_error& e) {
            // A folder or file the user named that cannot be made (--out under /proc, a read-only disk):
            // their path and the system's reason, not the library's wording.
            std::cerr << "sylvarock " << c.name << ": error: cannot create or write " << e.path1() << ": "
                      << e.code().message() << "\n";
            return 2;
        } catch (const std::exception& e) {
            std::cerr << "sylvarock " << c.name << ": error: " << e.what() << "\n";
            return 1;
        }
    }
    std::cerr << "sylvarock: error: unknown command '" << argv[1] << "'\n\n";
    printUsage(std::cerr);
    return 2;
}

#pragma once
// Runs the sylvarock command line (SYLVAROCK_CLI) as a test: its exit status and everything it printed.
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace sylva::testing {

struct CliRun {
    int status;
    std::string output;  // stdout and stderr
};

// `arguments` follow the program's name, e.g. "generate --stems ...".
inline CliRun runCli(const std::string& arguments) {
    const std::string command = std::string(SYLVAROCK_CLI) + " " + arguments + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    CliRun run{-1, {}};
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe)) run.output += buffer;
    const int raw = pclose(pipe);
    run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    return run;
}

}  // namespace sylva::testing

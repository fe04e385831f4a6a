#include "Gnuplot.hpp"

#include <cstdio>
#include <iostream>

#include <sys/wait.h>

namespace sylva::cli {

bool plotWithGnuplot(const std::string& script, const std::string& what) {
    FILE* p = popen("gnuplot 1>&2", "w");
    if (!p) {
        std::cerr << "warning: cannot start gnuplot; " << what << " not drawn\n";
        return false;
    }
    std::fwrite(script.data(), 1, script.size(), p);
    const int status = pclose(p);
    if (status != 0) {
        // The shell says 127 for a command it cannot find.
        if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
            std::cerr << "warning: gnuplot not found (apt-get install gnuplot-nox); " << what << " not drawn\n";
        else
            std::cerr << "warning: gnuplot stopped on the figure's script (its message is above); " << what << " not drawn\n";
        return false;
    }
    return true;
}

std::string gnuplotText(const std::string& text) {
    std::string quoted = "'";
    for (const char c : text) quoted += c == '\'' ? std::string("''") : std::string(1, c);
    return quoted + "'";
}

}  // namespace sylva::cli

#include "Gnuplot.hpp"

#include <cstdio>
#include <iostream>

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
        std::cerr << "warning: gnuplot failed (is gnuplot-nox installed?); " << what << " not drawn\n";
        return false;
    }
    return true;
}

}  // namespace sylva::cli

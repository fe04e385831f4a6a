#pragma once
// Figures are drawn by gnuplot (Debian's gnuplot-nox) into SVG files. Without gnuplot the numbers
// are still written; the figures are skipped with a warning, never an error.
#include <string>

namespace sylva::cli {

// Runs the script with gnuplot; returns false (and prints a warning naming `what`) if gnuplot is
// missing or fails.
bool plotWithGnuplot(const std::string& script, const std::string& what);

}  // namespace sylva::cli

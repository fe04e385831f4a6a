#pragma once
// Figures are drawn by gnuplot (Debian's gnuplot-nox) into SVG files. Without gnuplot the numbers
// are still written; the figures are skipped with a warning, never an error.
#include <string>

namespace sylva::cli {

// Runs the script with gnuplot; returns false (and prints a warning naming `what`) if gnuplot is
// missing or fails.
bool plotWithGnuplot(const std::string& script, const std::string& what);

// `text` as a gnuplot single-quoted string, quotes and all: a path or a stand's name with an
// apostrophe in it would otherwise end the string early and fail the whole script.
std::string gnuplotText(const std::string& text);

}  // namespace sylva::cli

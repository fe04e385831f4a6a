#pragma once
// The report's figures, drawn by gnuplot into SVG files from CSV data written beside them (as the
// paper's Figs. 8-12): run-out distributions with and without forest, A against NA per stand
// (runout_cdf.svg), PF50 per stand with its interval (pf50.svg), PF50 against G, Mean_D and N
// (pf50_dendrometry.svg), and the stop positions (stop_map.svg). The script stays in the folder
// (figures.gp) so a user can restyle and redraw them.
#include <string>
#include <vector>

#include "libassess/ProtectionAnalysis.hpp"

namespace sylva::assess {

struct FigureSet {
    std::vector<std::string> files;  // the SVG files drawn (names relative to the report folder)
    std::string warning;             // why none were drawn (no gnuplot), empty if they were
};

// Writes data/ and figures.gp into reportDir and runs gnuplot there. Without a working gnuplot the
// data and the script are still written and the warning says so.
FigureSet drawFigures(const std::string& reportDir, const AssessmentResults& results);
// The two models side by side (Figs. 9-12 as the paper draws them, runout_cdf_models.svg,
// pf50_models.svg, pf50_dendrometry_models.svg) from the data drawFigures wrote for each model in
// reportDir/<model>/; the script is reportDir/figures.gp.
FigureSet drawModelComparisonFigures(const std::string& reportDir, const std::vector<AssessmentResults>& results);

// Writes `script` as figures.gp into `dir` and runs gnuplot there; `svgs` are the files it should
// draw (the warning says so when some are missing).
FigureSet runGnuplot(const std::string& dir, const std::string& script, const std::vector<std::string>& svgs);

}  // namespace sylva::assess

#pragma once
// What an assessment hands over: OUT/results.json (every number, for scripts), and the folder
// OUT/report/ with report.md (the tables and figures for a reader), CSV tables (stands.csv,
// forests.csv, correlations.csv, runs.csv) and the figures (Figures.hpp). With two models, each has
// its report in OUT/report/<model>/ and OUT/report/report.md sets them side by side (the paper's
// comparison); results.json then holds the first model's results at its top level, the second's
// under its name, and "model_comparison". Nothing in them depends on the threads, the wall time or
// whether the campaign was resumed.
#include <string>
#include <vector>

#include "libassess/Figures.hpp"
#include "libassess/ProtectionAnalysis.hpp"

namespace sylva::assess {

// `results`: one per model (runAssessment's).
void writeResultsJson(const std::string& path, const std::vector<AssessmentResults>& results);
// Writes the report folder; returns the figures drawn at its top (and gnuplot's warning, if any).
FigureSet writeReport(const std::string& reportDir, const std::vector<AssessmentResults>& results);

}  // namespace sylva::assess

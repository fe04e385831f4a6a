#pragma once
// What an assessment hands over: OUT/results.json (every number, for scripts), and the folder
// OUT/report/ with report.md (the tables and figures for a reader), CSV tables (stands.csv,
// forests.csv, correlations.csv, runs.csv) and the figures (Figures.hpp). Nothing in them depends on
// the threads, the wall time or whether the campaign was resumed.
#include <string>

#include "libassess/Figures.hpp"
#include "libassess/ProtectionAnalysis.hpp"

namespace sylva::assess {

void writeResultsJson(const std::string& path, const AssessmentResults& results);
// Writes the report folder; returns the figures drawn (and gnuplot's warning, if any).
FigureSet writeReport(const std::string& reportDir, const AssessmentResults& results);

}  // namespace sylva::assess

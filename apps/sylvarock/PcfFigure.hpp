#pragma once
// The figure of a stand's pair correlation function g(r) for people: the stand's estimates, the band
// of g under complete spatial randomness (the CSR envelope), and optionally the g of virtual forests
// generated from the stand, to see whether they keep its aggregation (`stats` and `generate --plot-dir`).
#include <string>
#include <vector>

#include "libstand/PairCorrelation.hpp"
#include "libstand/PairCorrelationEnvelope.hpp"

namespace sylva::cli {

struct NamedPairCorrelation {
    std::string name;  // legend, e.g. "virtual forest A, seed 1"
    stand::PairCorrelation g;
};

// Writes DIR/<stem>.svg (through gnuplot, skipped with a warning without it) and DIR/<stem>.csv with
// every curve: r, the stand's g_trans and g_iso, the envelope's bounds (csr_trans_low, csr_trans_high;
// without an envelope, none) and each forest's g_trans.
void drawPcfFigure(const std::string& dir, const std::string& stem, const std::string& title, const stand::PairCorrelation& stand,
                   const stand::PairCorrelationEnvelope* envelope, const std::vector<NamedPairCorrelation>& forests = {});

// A number as R reads it from a CSV: %.10g, NA for NaN, Inf and -Inf.
std::string csvNumber(double v);

// Creates DIR (and its parents); InputError if it cannot, instead of gnuplot printing the SVG on the terminal.
void requirePlotDir(const std::string& dir);

}  // namespace sylva::cli

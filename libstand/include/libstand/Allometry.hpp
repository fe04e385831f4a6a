#pragma once
// Beech allometry used for every stem (paper Sect. 2.1.2; units per model-notes.md).
#include <string>

namespace sylva::stand {

// Largest DBH the allometry and the stem model are meant for (the paper's stands reach ~60 cm;
// Europe's largest beeches ~200 cm). Readers refuse above it: such a value is almost surely in mm.
inline constexpr double kLargestDbhCm = 200;
// Why a DBH read from a file cannot be a stem's ("DBH 0 cm is not positive", "... in mm?"), or "".
std::string dbhProblem(double dbhCm);

double treeHeightM(double dbhCm);        // Eq. 11, with D_stem in metres
double crownLengthM(double heightM);     // Eq. 12
double crownMassKg(double dbhCm);        // Eq. 13, with D_stem in centimetres

}  // namespace sylva::stand

#pragma once
// Beech allometry used for every stem (paper Sect. 2.1.2; units per model-notes.md).
namespace sylva::stand {

double treeHeightM(double dbhCm);        // Eq. 11, with D_stem in metres
double crownLengthM(double heightM);     // Eq. 12
double crownMassKg(double dbhCm);        // Eq. 13, with D_stem in centimetres

}  // namespace sylva::stand

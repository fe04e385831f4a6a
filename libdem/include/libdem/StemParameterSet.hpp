#pragma once
// Named sets of the tree's parameters (docs/model-stems.md, "Parameter sets"). `toe2018` is the
// paper's Table 2 and its stem as published (one hinge per connection, Eqs. 7-8, elastic contact,
// M_a = 200 kN m for every tree): what reruns the paper's study. `calibrated` is the model whose
// answer does not move with the node spacing and whose anchorage follows the winching tests.
#include <string>

#include "libdem/StemContact.hpp"
#include "libdem/StemParams.hpp"

namespace sylva::dem {

enum class StemParameterSet { Toe2018, Calibrated };

// "toe2018" or "calibrated"; anything else is an InputError naming both.
StemParameterSet parseStemParameterSet(const std::string& name);
const char* name(StemParameterSet set);

// The stem and its contacts of a set; the keys of a scene then change single values of it.
void apply(StemParameterSet set, StemParams& stem, StemContactParams& contact);
// The stem's part of a set alone (a stem built apart from any scene). The calibrated set's foot zone
// (1 m) asks a node spacing of at most 1 m; a scene raises it to a coarser one (SceneConfig).
StemParams stemParameters(StemParameterSet set);

}  // namespace sylva::dem

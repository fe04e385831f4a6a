#include "libdem/StemParameterSet.hpp"

#include <cmath>

#include "libcommon/InputError.hpp"

namespace sylva::dem {

StemParameterSet parseStemParameterSet(const std::string& name) {
    if (name == "toe2018") return StemParameterSet::Toe2018;
    if (name == "calibrated") return StemParameterSet::Calibrated;
    throw InputError("stem.parameters must be toe2018 (the paper's Table 2) or calibrated, not '" + name + "'");
}

const char* name(StemParameterSet set) { return set == StemParameterSet::Toe2018 ? "toe2018" : "calibrated"; }

void apply(StemParameterSet set, StemParams& stem, StemContactParams& contact) {
    stem = StemParams{};  // Table 2
    contact = StemContactParams{};
    if (set == StemParameterSet::Toe2018) return;
    // Each choice below removes a node-spacing dependence or follows measurements on real trees;
    // docs/model-stems.md gives the reasons, the sources and the convergence they buy.
    stem.bending.sections = 3;                          // "A connection is a beam"
    stem.bending.damping = StemDamping::ConstantLoss;   // "Damping": wood's loss factor
    contact.crushingStrength = 3.7e6;                   // "Crushing": green beech across the grain
    stem.root.anchorage = RootAnchorage::StemWeight;    // "Anchorage": M_a = C_reg x stem mass
    stem.root.failureRotation = 25 * std::acos(-1.0) / 180;  // "The root plate lets go"
    stem.axialSoftening = 2;                            // "Time step": the axial springs softened
    stem.footZone = 1;                                  // "The foot zone": its lowest metre at half the spacing
}

StemParams stemParameters(StemParameterSet set) {
    StemParams stem;
    StemContactParams contact;
    apply(set, stem, contact);
    return stem;
}

}  // namespace sylva::dem

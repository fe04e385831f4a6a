#pragma once
// Where the energy the forest took during a run went, J: the forest's part of the run's energy
// budget (ForestMotion keeps it; RunResult reports it; energy.json writes it).
#include "libdem/StemLedger.hpp"

namespace sylva::dem {

struct ForestLedger {
    double bendingPlasticity = 0, bendingDamping = 0, axialDamping = 0, rootPlasticity = 0, rupture = 0;
    double unloadingGain = 0;    // created by Fig. 3 at a connection's first yield (docs/model-stems.md)
    double contactFriction = 0;  // block/stem, stem/stem and stem/soil sliding
    double contactDamping = 0;   // the soil's dashpot under stems and broken pieces (Eqs. 14-16)
    double contactCrushing = 0;  // wood crushed under the block (tree_contact.crushing_strength_pa)
    // Frozen when stems rested or slept still moving: their kinetic energy and their contact springs'.
    double frozen = 0;
    // Of which the motion of broken or uprooted stems' pieces (falling, rolling, or pushed by the
    // block); the rest is what standing stems were left swaying with, and the springs.
    double frozenPieces = 0;

    // The tree's own terms: what the stems themselves took.
    double treeTerms() const { return bendingPlasticity + bendingDamping + axialDamping + rootPlasticity + rupture; }
    void add(const ForestLedger& o) {
        bendingPlasticity += o.bendingPlasticity, bendingDamping += o.bendingDamping, axialDamping += o.axialDamping;
        rootPlasticity += o.rootPlasticity;
        rupture += o.rupture, unloadingGain += o.unloadingGain, contactFriction += o.contactFriction;
        contactDamping += o.contactDamping, contactCrushing += o.contactCrushing, frozen += o.frozen;
        frozenPieces += o.frozenPieces;
    }

    // Books a stem's own terms (sign +1), or takes them back (-1) when the stem is woken again.
    void addStem(const StemLedger& s, double sign = 1) {
        bendingPlasticity += sign * s.bendingPlasticity;
        bendingDamping += sign * s.bendingDamping;
        axialDamping += sign * s.axialDamping;
        rootPlasticity += sign * s.rootPlasticity;
        rupture += sign * s.rupture;
        unloadingGain += sign * s.unloadingGain;
    }
};

}  // namespace sylva::dem

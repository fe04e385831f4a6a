#pragma once
// Where a stem's mechanical energy went, J: the stem's counterpart of the contacts'
// DissipationLedger. With E_kin + E_elastic + E_potential the budget reads
//   E(t) + dissipated - unloadingGain - externalWork = E(0),
// dissipated being the sum of the six dissipative entries.
namespace sylva::dem {

struct StemLedger {
    double bendingPlasticity = 0;  // plastic branch of the trilinear law (Eqs. 2-6), >= 0
    double bendingDamping = 0;     // damping of the bending (Eqs. 7-8 or wood's loss factor), >= 0
    double axialDamping = 0;       // wood's loss factor in the axial springs (calibrated stems), >= 0
    double rootPlasticity = 0;     // plateau of the root spring at M_a (Eqs. 9-10), >= 0
    double rupture = 0;            // energy stored in a connection when it broke, lost with it
    double relaxation = 0;         // numerical damping used to settle a stem (StemStepper), not physics
    // Energy Fig. 3 creates, once per connection: at the first yield the recoverable energy jumps
    // from M_Elast^2 / (2 K_Elast) to M_Elast^2 / (2 K_Unld), because E_Unld < MOE. A source, >= 0.
    double unloadingGain = 0;
    double externalWork = 0;       // work of the loads given to StemStepper (not gravity, which is potential)

    double dissipated() const { return bendingPlasticity + bendingDamping + axialDamping + rootPlasticity + rupture + relaxation; }
    // What was booked since `earlier` (an earlier state of the same ledger).
    StemLedger since(const StemLedger& earlier) const {
        return {bendingPlasticity - earlier.bendingPlasticity, bendingDamping - earlier.bendingDamping,
                axialDamping - earlier.axialDamping,           rootPlasticity - earlier.rootPlasticity,       rupture - earlier.rupture,
                relaxation - earlier.relaxation,               unloadingGain - earlier.unloadingGain,
                externalWork - earlier.externalWork};
    }
};

}  // namespace sylva::dem

#pragma once
// How a stem connection breaks once a section has reached M_Rupt (Eq. 6), given a fracture energy
// G_f: what it transmits of its bending and shear falls linearly to nothing over a further plastic
// hinge rotation theta_f, so that breaking costs G_f per m^2 of its section whatever the connection's
// length and whichever way it is bent (the crack band's regularisation, Bazant & Oh 1983, Materiaux
// et Constructions 16:155).
// Without one (G_f = 0, the paper) the connection breaks at once (ConnectionBeam).
// docs/model-stems.md, "A fracture energy".
//
// Continuum damage's balance (Lemaitre & Chaboche 1990, ch. 7): a connection transmitting (1 - d)
// of its intact springs' forces stores (1 - d) psi0, dissipates (1 - d) of what they dissipate, and
// d's growth releases psi0 dd.
#include <limits>

#include "libdem/BendingLaw.hpp"  // Vec2

namespace sylva::dem {

class ConnectionFracture {
public:
    ConnectionFracture() = default;  // brittle: never softens
    // theta_f = 2 G_f A / M_Rupt = 16 G_f / (sigma_Rupt D) for a round section of diameter D, rad: the
    // intact hinge's plastic work M_Rupt theta_f = 2 G_f A opens the crack through.
    ConnectionFracture(double fractureEnergy, double diameter);

    // The intact hinge has flowed, dissipating `plasticWork` (J) this step, and the connection has slid
    // by `slip` (m, its shear stretch), its intact springs storing `intactEnergy` (J); M_Rupt was
    // reached at this call or before. Returns the energy the damage's growth released, J.
    double advance(double plasticWork, const Vec2& slip, double intactEnergy);

    double carried() const { return 1 - damage_; }  // the share of the intact forces transmitted
    bool started() const { return started_; }
    bool through() const { return damage_ >= 1; }  // broken: nothing transmitted any more
    double openingWork() const { return openingWork_; }

private:
    double openingWork_ = std::numeric_limits<double>::infinity();  // M_Rupt theta_f = 2 G_f A, J
    double radius_ = 0;  // D / 2, m
    bool started_ = false;
    Vec2 ruptureSlip_ = Vec2::Zero();
    double damage_ = 0;  // d
};

}  // namespace sylva::dem

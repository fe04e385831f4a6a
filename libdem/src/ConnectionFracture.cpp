#include "libdem/ConnectionFracture.hpp"

#include <algorithm>
#include <cmath>

namespace sylva::dem {

ConnectionFracture::ConnectionFracture(double fractureEnergy, double diameter)
    : openingWork_(0.5 * std::acos(-1.0) * fractureEnergy * diameter * diameter),
      radius_(0.5 * diameter) {}

double ConnectionFracture::advance(double plasticWork, const Vec2& slip, double intactEnergy) {
    double damage = damage_;
    if (!started_) {
        // The step that reached M_Rupt flowed partly below it: its work is Eq. 6's hardening, not the
        // crack's.
        started_ = true;
        ruptureSlip_ = slip;
    } else {
        // Opened by the hinge's plastic rotation, M_Rupt dkappa = the intact hinge's plastic work, in
        // whichever direction: opened by |theta| - |theta at rupture|, a hinge bent back flowed at M_Rupt
        // unopened and took six times G_f A. Opened also by the rim's slip and stretch over the same
        // theta_f (prototype C), the crack went through at a few mm and the breaks came back.
        damage = std::min(1.0, damage_ + plasticWork / openingWork_);
    }
    // Faces slid apart by half the section no longer hold. Without this bound the shear, softened
    // with the bending, let a node slide sideways unresisted, metres, until the couple of the axial
    // spring about that lever broke the explicit step (the energy audit stopped such runs).
    if ((slip - ruptureSlip_).norm() > radius_) damage = 1;
    const double released = intactEnergy * (damage - damage_);
    damage_ = damage;
    return released;
}

}  // namespace sylva::dem

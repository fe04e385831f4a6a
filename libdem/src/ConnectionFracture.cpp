#include "libdem/ConnectionFracture.hpp"

#include <algorithm>

namespace sylva::dem {

ConnectionFracture::ConnectionFracture(double fractureEnergy, double sigmaRupt, double diameter)
    : fractureRotation_(16 * fractureEnergy / (sigmaRupt * diameter)), radius_(0.5 * diameter) {}

double ConnectionFracture::advance(double rotation, const Vec2& slip, double intactEnergy) {
    if (!started()) ruptureRotation_ = rotation, ruptureSlip_ = slip;
    // Opened by the hinge's rotation alone: opened also by the rim's slip and stretch, over the same
    // theta_f, the crack went through at a few mm and the breaks came back (docs/model-stems.md).
    // Monotone: a crack that closes does not heal.
    double damage = std::min(1.0, std::max(damage_, (rotation - ruptureRotation_) / fractureRotation_));
    // Faces slid apart by half the section no longer hold. Without this bound the shear, softened
    // with the bending, let a node slide sideways unresisted, metres, until the couple of the axial
    // spring about that lever broke the explicit step (the energy audit stopped such runs).
    if ((slip - ruptureSlip_).norm() > radius_) damage = 1;
    const double released = intactEnergy * (damage - damage_);
    damage_ = damage;
    return released;
}

}  // namespace sylva::dem

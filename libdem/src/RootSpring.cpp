#include "libdem/RootSpring.hpp"

#include <limits>

namespace sylva::dem {

namespace {
HingeCoefficients rootCoefficients(const RootSpringParams& p) {
    HingeCoefficients k;
    k.elastic = k.unloading = p.stiffness;  // Eqs. 9-10
    k.plastic = 0;                          // perfectly plastic at M_a
    k.yieldMoment = p.yieldMoment;
    k.ruptureMoment = std::numeric_limits<double>::infinity();
    return k;
}
}  // namespace

RootSpring::RootSpring(const RootSpringParams& p, BendingReading reading)
    : bending_(rootCoefficients(p), reading), stiffness_(p.stiffness), failureRotation_(p.failureRotation) {}

double RootSpring::rotate(const Eigen::Vector3d& dTheta) {
    if (failed_) return 0;
    twistAngle_ += dTheta.z();
    tilt_ += dTheta.head<2>();
    const double dissipated = bending_.rotate(dTheta.head<2>()).dissipated;
    // The foot's tilt, not the plastic rotation summed over its swings: a foot rocking on the plateau
    // back and forth would otherwise let go without ever leaning as far as the failure rotation.
    if (tilt_.norm() < failureRotation_) return dissipated;
    const double released = storedEnergy();
    failed_ = true;
    bending_.snap();
    twistAngle_ = 0;
    return dissipated + released;
}

Eigen::Vector3d RootSpring::moment() const {
    if (failed_) return Eigen::Vector3d::Zero();
    const Vec2& m = bending_.moment();
    return {m.x(), m.y(), stiffness_ * twistAngle_};
}

double RootSpring::storedEnergy() const {
    if (failed_) return 0;
    return bending_.storedEnergy() + 0.5 * stiffness_ * twistAngle_ * twistAngle_;
}

}  // namespace sylva::dem

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
    : bending_(rootCoefficients(p), reading), stiffness_(p.stiffness) {}

double RootSpring::rotate(const Eigen::Vector3d& dTheta) {
    twistAngle_ += dTheta.z();
    return bending_.rotate(dTheta.head<2>()).dissipated;
}

Eigen::Vector3d RootSpring::moment() const {
    const Vec2& m = bending_.moment();
    return {m.x(), m.y(), stiffness_ * twistAngle_};
}

double RootSpring::storedEnergy() const {
    return bending_.storedEnergy() + 0.5 * stiffness_ * twistAngle_ * twistAngle_;
}

}  // namespace sylva::dem

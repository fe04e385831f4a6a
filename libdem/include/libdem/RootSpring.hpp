#pragma once
// The root system of a single tree (paper Sect. 2.1.2, Eqs. 9-10): an elastic-perfectly plastic
// rotational spring between the ground and the stem's foot, stiffness K_Root, moment limited to M_a.
// It is the trilinear hinge with K_Plast = 0, K_Unld = K_Elast and no rupture. The paper gives the
// x and y axes only; the twist about the stem axis is held by a linear spring of the same K_Root,
// so that a rubbing block cannot spin the whole tree in its soil (docs/model-stems.md).
// Optionally the plate lets go at a failure rotation (winching tests: the resistance of a root plate
// does not last for ever): from then on the foot is a pin and the root carries nothing.
#include <Eigen/Core>

#include "libdem/BendingLaw.hpp"

namespace sylva::dem {

class RootSpring {
public:
    RootSpring(const RootSpringParams& p, BendingReading reading);

    // Follows an increment of the foot's rotation relative to the ground (x, y, z of the foot's
    // frame, rad) and returns the energy the root dissipated, J: its plastic work and, when the plate
    // lets go, the elastic energy it held.
    double rotate(const Eigen::Vector3d& dTheta);

    Eigen::Vector3d moment() const;  // N m: bending x, y (Eqs. 9-10) and twist z
    double storedEnergy() const;
    double stiffness() const { return stiffness_; }
    double yieldMoment() const { return bending_.coefficients().yieldMoment; }  // M_a, N m
    bool failed() const { return failed_; }

private:
    BendingLaw bending_;
    double stiffness_;
    double failureRotation_;                       // rad, of the foot's tilt
    Eigen::Vector2d tilt_ = Eigen::Vector2d::Zero();  // rad, the foot's rotation about x and y from rest
    double twistAngle_ = 0;
    bool failed_ = false;
};

}  // namespace sylva::dem

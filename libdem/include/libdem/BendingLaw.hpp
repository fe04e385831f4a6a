#pragma once
// The bending hinge of one stem connection: the trilinear elastic-plastic law of Fig. 3 with
// unloading, reloading and rupture (Eqs. 2-6); its coefficients include the viscosity of Eqs. 7-8,
// which ConnectionBeam applies.
// The law is incremental: it is fed the increments of the relative rotation of the two nodes.
#include <Eigen/Core>

#include "libdem/StemParams.hpp"

namespace sylva::dem {

using Vec2 = Eigen::Vector2d;

// Stiffnesses (N m/rad), thresholds (N m) and viscosity (N m s/rad) of one hinge.
struct HingeCoefficients {
    double elastic = 0;        // first loading, K_Elast (Eq. 2)
    double plastic = 0;        // beyond the yield moment, K_Plast (Eq. 3)
    double unloading = 0;      // unloading and reloading once yielded, K_Unld (Eq. 4)
    double yieldMoment = 0;    // M_Elast (Eq. 5)
    double ruptureMoment = 0;  // M_Rupt (Eq. 6); infinity: never breaks
    double viscosity = 0;      // tau K_Elast (Eqs. 7-8)
};

// The hinge of a connection of mean diameter D_con (m) and length l (m).
HingeCoefficients bendingCoefficients(const BendingParams& p, double diameter, double length);

// Energy moved by one increment, J.
struct HingeWork {
    double dissipated = 0;  // plastic work, >= 0
    double created = 0;     // recoverable energy appearing at the first yield (see StemLedger::unloadingGain)
    double released = 0;    // energy stored in the hinge when it broke
};

class BendingLaw {
public:
    BendingLaw(const HingeCoefficients& k, BendingReading reading);

    // Follows an increment of the relative rotation about x and y of the connection frame (rad).
    // Reaching M_Rupt breaks the hinge: the moment drops to zero for good.
    HingeWork rotate(const Vec2& dTheta);

    // Breaks the hinge now, whatever its moment (Stem: a connection folded beyond what any wood
    // fibre survives); its stored energy is released.
    HingeWork snap();
    const Vec2& moment() const { return moment_; }  // elastic-plastic moment, N m
    bool broken() const { return broken_; }
    double storedEnergy() const;  // recoverable by elastic unloading, J
    const HingeCoefficients& coefficients() const { return k_; }
    BendingReading reading() const { return reading_; }

private:
    // One trilinear channel: the whole 2-D moment (isotropic) or one axis (per axis).
    struct Channel {
        double yieldMoment;  // radius of the elastic domain: M_Elast, then the largest moment reached
        bool yielded = false;
    };
    using Moment = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 2, 1>;
    HingeWork advance(Moment& m, const Moment& d, Channel& ch);
    double stiffness(const Channel& ch) const { return ch.yielded ? k_.unloading : k_.elastic; }

    HingeCoefficients k_;
    BendingReading reading_;
    Channel channels_[2];
    Vec2 moment_ = Vec2::Zero();
    bool broken_ = false;
};

}  // namespace sylva::dem

#pragma once
// The bending of one stem connection as a beam whose moment varies linearly along it, as the statics
// of a connection carrying a shear force demand: a force-based beam element with distributed
// plasticity (Spacone, Filippou & Taucer 1996, Earthquake Eng. Struct. Dyn. 25:711; Neuenhofer &
// Filippou 1997, J. Struct. Eng. 123:958). The trilinear law of Fig. 3 (Eqs. 2-6) acts on each of its
// sections, placed by Gauss-Lobatto quadrature; with one section, at the middle, it is the paper's
// hinge exactly and the shear spring is the connection's only transverse flexibility.
// Derivation and measurements: docs/model-stems.md, "A connection is a beam".
//
// Generalised deformations, per moment component of the connection frame: theta, the relative
// rotation of the nodes (conjugate to the mean moment M), and eps = (2 / l) (s_y, -s_x), s the
// transverse stretch of the connection (conjugate to dM, half the change of the moment along it: the
// moment at a section xi in [-1, 1] from node a to node b is M + xi dM). Each section has the
// diameter of the stem where it sits, so its stiffness, yield and rupture moments (Eqs. 2-6).
#include <array>

#include <Eigen/Core>

#include "libdem/BendingLaw.hpp"

namespace sylva::dem {

class ConnectionBeam {
public:
    static constexpr int kMaxSections = 5;

    // A connection of length l (m) whose diameter goes linearly from `diameterA` at node a to
    // `diameterB` at node b, with shear stiffness G A / l (N/m). `sections`: 1 (the paper's hinge,
    // at the middle, with the mean diameter D_con), 3 or 5 (Gauss-Lobatto points, both ends included).
    ConnectionBeam(const BendingParams& p, double diameterA, double diameterB, double shearStiffness, double length,
                   int sections);

    // Brings the connection to the relative rotation `theta` (about x, y of the connection frame, rad)
    // and the transverse stretch `stretch` (x, y, m). Without a fracture energy a section reaching
    // M_Rupt breaks the connection: it transmits nothing from then on (with one, see ruptureReached).
    HingeWork deform(const Vec2& theta, const Vec2& stretch);
    // Breaks the connection now; its stored energy is released.
    HingeWork snap();

    const Vec2& moment() const { return moment_; }  // mean moment M, N m: what the nodes' rotations feel
    Vec2 sectionMoment(int section) const;          // M + xi dM at a section, N m
    // Transverse force the connection exerts on node a (node b takes the opposite), connection frame, N.
    Vec2 shearForce() const;
    bool broken() const { return broken_; }
    // A section has reached M_Rupt. With a fracture energy (BendingParams::fractureEnergy) the beam
    // goes on as if intact and its owner softens what it transmits (Stem::updateConnections); without
    // one (Eq. 6) the connection is broken at once.
    bool ruptureReached() const { return ruptureReached_; }
    double storedEnergy() const { return stored_; }  // bending and shear, recoverable elastically, J
    const HingeCoefficients& coefficients() const { return k_; }  // of the whole connection at D_con
    double shearStiffness() const { return shearStiffness_; }
    // Of one moment component, intact and elastic: (M, dM) = S (theta, eps). Yielding only softens it
    // (K_Unld < K_Elast, then the plastic branch), so it bounds the connection's stiffness for good.
    Eigen::Matrix2d elasticStiffness() const;
    int sectionCount() const;
    BendingReading reading() const { return reading_; }

    struct Rule;  // where the sections sit and what they weigh (ConnectionBeam.cpp)

private:
    // Two components for the moment vector; a per-axis channel uses the first and keeps the second
    // at zero, where every norm and product gives the one-component result exactly.
    using Moment = Vec2;
    struct Section {
        Moment plastic;      // plastic rotation per unit weight, rad: l times the plastic curvature
        double yieldMoment;  // radius of the elastic domain: M_Elast, then the largest moment reached
        bool yielded = false;
    };
    struct Flexibility {
        double mm, mc, cc;  // rad per N m: theta = mm M + mc dM + ..., eps = mc M + cc dM + ...
        double inverseDet;  // 1 / (mm cc - mc^2): inverting it is every step's work
    };
    // One set of sections: all of them for the moment vector (isotropic), or one per axis.
    struct Channel {
        std::array<Section, kMaxSections> section;
        Moment mean, change;  // M and dM
        Flexibility flexibility;  // changes only when a section first yields
        bool flexibilityStale = true;
    };
    HingeWork deformChannel(Channel& ch, const Moment& theta, const Moment& eps);
    Flexibility flexibility(const Channel& ch) const;
    Flexibility flexibility(const std::array<double, kMaxSections>& compliance) const;
    void solveForces(Channel& ch, const Moment& theta, const Moment& eps) const;
    double channelEnergy(const Channel& ch) const;
    double compliance(int i, const Section& s) const { return s.yielded ? unloadingCompliance_[i] : elasticCompliance_[i]; }

    HingeCoefficients k_;
    double shearStiffness_, length_;
    const Rule* rule_;
    BendingReading reading_;
    std::array<HingeCoefficients, kMaxSections> sectionK_;
    std::array<double, kMaxSections> elasticCompliance_, unloadingCompliance_;  // 1 / K_Elast, 1 / K_Unld per section
    std::array<double, kMaxSections> hardening_;  // dM / d(plastic rotation) along the plastic branch, N m/rad
    std::array<Channel, 2> channels_;
    Vec2 moment_ = Vec2::Zero(), change_ = Vec2::Zero();
    double stored_ = 0;
    bool brittle_ = true;  // no fracture energy: Eq. 6
    bool ruptureReached_ = false;
    bool broken_ = false;
};

}  // namespace sylva::dem

#pragma once
// A tree stem as a chain of rigid nodes from the foot up (paper Sect. 2.1.2, Fig. 2).
// Geometry: a truncated cone through the DBH at 1.3 m, tapering linearly to StemParams::tipDiameter
// at H_T, cut into equal connections of length l up to StemParams::nodeSpacing (a graded stem: equal
// ones so up to the crown base, and equal ones up to StemParams::upperSpacingFactor times that above it;
// a foot zone: its lowest StemParams::footZone metres at half that).
// Each cone segment's mass goes half to each of its nodes; the crown mass m_C is spread over the nodes
// within L_C of the top, each carrying the crown along the connection below it (equally, on equal
// connections, as the paper spreads it). Between neighbouring nodes a connection of length l
// and mean diameter D_con carries linear elastic axial and twist springs (MOE and
// G = MOE / (2 (1 + nu)); the axial one damped by wood's loss factor) and, for bending and shear, a ConnectionBeam (the trilinear law of Fig. 3
// on its sections), which once M_Rupt is reached breaks at once (Eq. 6) or softens over a
// ConnectionFracture. A foot zone's connections have their axial and shear springs softened and
// their nodes' rotational inertia raised, so that they keep the stem's step. The foot is clamped (coppice stems) or held
// in place and turning on the root spring (single trees). A broken connection transmits nothing:
// the part above keeps moving as a free chain.
// Node state is kept as arrays over nodes so that a step is a few loops over contiguous memory.
#include <vector>

#include "libdem/BendingDamping.hpp"
#include "libdem/ConnectionBeam.hpp"
#include "libdem/ConnectionFracture.hpp"
#include "libdem/RigidBody.hpp"
#include "libdem/RootSpring.hpp"
#include "libdem/StableStep.hpp"
#include "libdem/StemLedger.hpp"
#include "libdem/StemParams.hpp"

namespace sylva::dem {

// Size of a stem: lengths in m, mass in kg.
struct StemGeometry {
    double height = 0;       // H_T, from the foot to the top
    double dbh = 0;          // diameter at breast height (1.3 m above the foot), m
    double crownLength = 0;  // L_C, measured down from the top
    double crownMass = 0;    // m_C
};

// Beech allometry (Eqs. 11-13, libstand/Allometry.hpp) for a stem of this DBH in cm.
// Throws InputError unless dbhCm > 0.
StemGeometry beechStem(double dbhCm);

enum class StemFoot { Clamped, RootSpring };

class Stem {
public:
    // A straight stem standing vertically (every node's local z up) on `foot`.
    // Throws InputError on out-of-range geometry or parameters.
    Stem(const StemGeometry& g, const StemParams& p, const Vec3& foot, StemFoot support);

    // Node state, world frame. Velocities are the leapfrog's mid-step values. Node 0 is the foot:
    // it never translates, and turns only on the root spring.
    std::vector<Vec3> position, velocity, angularVelocity;
    std::vector<Quat> orientation;
    StemLedger ledger;

    std::size_t nodeCount() const { return position.size(); }
    std::size_t connectionCount() const { return connections_.size(); }
    const std::vector<double>& mass() const { return mass_; }
    // Rotational inertia of each node about its centre, taken isotropic: that of its share of the
    // stem about a transverse axis, m (D^2/16 + L^2/12), L the share's length (raised in a foot zone:
    // docs/model-stems.md, "The foot zone").
    const std::vector<double>& inertia() const { return inertia_; }
    // Their reciprocals, which every step multiplies by (a division costs several multiplications).
    const std::vector<double>& inverseMass() const { return inverseMass_; }
    const std::vector<double>& inverseInertia() const { return inverseInertia_; }
    const StemGeometry& geometry() const { return geometry_; }
    StemFoot foot() const { return support_; }
    bool translates(std::size_t node) const { return node > 0; }
    bool rotates(std::size_t node) const { return node > 0 || support_ == StemFoot::RootSpring; }
    double restHeight(std::size_t node) const { return restHeight_[node]; }  // above the foot, unloaded
    double diameterAt(double heightAboveFoot) const;
    // The sphere a node touches the soil with, and the block once the connections on both sides of it
    // are broken (the top node: its one).
    double nodeRadius(std::size_t node) const { return 0.5 * diameterAt(restHeight(node)); }
    double connectionLength(std::size_t c) const { return connections_[c].length; }  // l, between nodes c and c+1
    double connectionDiameter(std::size_t c) const { return connections_[c].diameter; }  // D_con, between nodes c and c+1
    // Above the foot, of the connection's middle in the unloaded stem: where a break is said to be.
    double connectionHeight(std::size_t c) const { return 0.5 * (restHeight_[c] + restHeight_[c + 1]); }
    const ConnectionBeam& bending(std::size_t c) const { return connections_[c].bending; }
    bool broken(std::size_t c) const { return connections_[c].bending.broken(); }
    bool anyConnectionBroken() const { return !breakOrder_.empty(); }
    // How many connections have broken: a new break makes new pieces (and new pairs of them to touch).
    std::size_t breakCount() const { return breakOrder_.size(); }
    // The broken connections in the order they broke: a caller that knows the run's clock can tell
    // when each broke from which are new since it last looked (ForestMotion::integrate).
    const std::vector<std::uint32_t>& breakOrder() const { return breakOrder_; }
    // Rest height above the foot of the middle of the lowest broken connection (NaN if none): a
    // whipped top that snaps is not a stem broken at its foot.
    double lowestBreakHeight() const;
    const RootSpring& root() const { return root_; }

    // Lengthens the axial springs' rest lengths so that the straight stem, as built, carries its own
    // weight (gravity g, m/s^2, along -z) in static equilibrium: a tree standing still before the
    // block comes. Their stored energy counts from now in elasticEnergy().
    void carryOwnWeight(double gravity);

    // Brings every connection and the root spring to the current node configuration and adds their
    // forces and torques to `force` and `torque` (sized nodeCount()). The laws are incremental: call
    // once per step, dt being the step about to be taken (it weighs the viscous work).
    void updateConnections(std::vector<Vec3>& force, std::vector<Vec3>& torque, double dt);
    double elasticEnergy() const { return elasticEnergy_; }  // in all springs at the last update, J
    double kineticEnergy() const;  // from the current velocities, J
    // Largest stable explicit step, from bounds of the highest eigen-frequency and of the highest
    // damping rate of its springs and dashpots (Irons' element-by-element bound, Stem.cpp; StableStep).
    double stableTimeStep() const;
    StableStep stability() const;  // the two bounds, to which contacts add theirs

    // Where the stem is cut, from the foot up: the foot zone's equal connections at most half
    // StemParams::nodeSpacing long (docs/model-stems.md, "The foot zone"), then equal connections at
    // most nodeSpacing long up to the crown base (at least the struck zone's top), and at most
    // upperSpacingFactor times that above it (docs/model-stems.md, "A graded stem"). `footCount`, if
    // given, receives how many connections the foot zone has.
    static std::vector<double> connectionLengths(const StemGeometry& g, const StemParams& p, std::size_t* footCount = nullptr);

private:
    struct Connection {
        double length;    // l
        double diameter;  // D_con
        double axial, twist;  // N/m, N m/rad
        ConnectionBeam bending;  // bending and shear
        BendingDamping damping;  // of the bending (Eqs. 7-8 or wood's loss factor)
        double axialDamping = 0;  // N s/m: wood's loss factor in the axial spring (constant_loss only)
        double dashpotForce = 0, dashpotStretch = 0;  // N, m: its force at the last step, and the axial stretch then
        double weightCompression = 0;  // m: how much the weight above shortens the axial spring (carryOwnWeight)
        ConnectionFracture fracture{};  // once M_Rupt is reached, with a fracture energy
    };
    StemGeometry geometry_;
    StemParams params_;
    StemFoot support_;
    std::vector<double> restHeight_;
    Quat footRest_;
    Eigen::Vector3d rootAngle_ = Eigen::Vector3d::Zero();
    std::vector<double> mass_, inertia_, inverseMass_, inverseInertia_;
    std::vector<Connection> connections_;
    RootSpring root_;
    double elasticEnergy_ = 0;
    std::vector<std::uint32_t> breakOrder_;  // connections broken (updateConnections adds them as they break)
};

}  // namespace sylva::dem

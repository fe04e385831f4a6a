#pragma once
// What every contact law sees and keeps. A law turns the geometry of one contact (and the history
// it carried from the previous step) into the force on body A. Laws are small types registered in
// the ContactLawTable by the kinds of the two bodies; detection never needs to know which law runs.
#include "libdem/RigidBody.hpp"

namespace sylva::dem {

struct ContactGeometry {
    Vec3 normal = Vec3::UnitZ();  // unit, from body B to body A: a positive normal force pushes A away
    double overlap = 0;       // interpenetration U_n, > 0 while touching
    Vec3 point = Vec3::Zero();  // contact point (middle of the overlap)
    Vec3 relativeVelocity = Vec3::Zero();  // velocity of A's material point minus B's, at `point`
    double meanSpinNormal = 0;  // 0.5 (omega_A + omega_B) . normal: twist of the contact plane
    double radiusA = 0, radiusB = 0;  // local radii (sphere, or stem connection at the contact)
    // Reduced mass of the two bodies at the contact, kg, for laws whose dashpot is a fraction of the
    // critical one (Eq. 16); 0: the law's own reference mass (the block's).
    double movingMass = 0;
};

// State a contact carries from one step to the next, and across connections of a stem.
struct ContactHistory {
    Vec3 shearForce = Vec3::Zero();  // tangential force on A, world frame
    Vec3 normal = Vec3::Zero();      // normal at the previous step (zero: new contact)
    Vec3 dampingForce = Vec3::Zero();  // dashpot force applied at the previous step, for the energy audit
    // Overlap already there when the contact was first seen (a stem woken into a bent neighbour):
    // the spring starts from it instead of releasing energy no motion stored.
    double overlapOffset = 0;
    double plasticOverlap = 0;  // permanent dent of a crushing contact (BlockStemContact), m
};

// Work done by the dissipative parts of the contact laws, J (>= 0), for the energy audit.
struct DissipationLedger {
    double contactDamping = 0;  // normal dashpots (Eq. 14)
    double friction = 0;        // Coulomb sliding (Eq. 18)
    double crushing = 0;        // wood crushed under a block (BlockStemContact with a crushing strength)
};

class ContactLaw {
public:
    virtual ~ContactLaw() = default;
    // Force on A; updates the history and adds dissipated work to the ledger.
    virtual Vec3 force(const ContactGeometry& g, ContactHistory& h, double dt, DissipationLedger& ledger) const = 0;
    // Energy stored in the contact's springs (normal + tangential), for the energy audit.
    virtual double storedEnergy(const ContactGeometry& g, const ContactHistory& h) const = 0;
    // Normal stiffness and dashpot coefficient at this contact: they set the stable time step.
    virtual double normalStiffness(const ContactGeometry& g) const = 0;
    virtual double dampingCoefficient() const { return 0.0; }
    // The dashpot at this contact (a stem node's on the soil follows the node's mass: Eq. 16).
    virtual double dampingCoefficientAt(const ContactGeometry&) const { return dampingCoefficient(); }
    // The stiffest this law is anywhere, for the room a step leaves for contacts still to come.
    virtual double largestNormalStiffness() const { return normalStiffness(ContactGeometry{}); }

    // A contact found at the last step and not at this one ended in the step between (of length dt,
    // over which A's material point moved at relativeVelocity from B's). The leapfrog applied its
    // last forces over the half of that step after them, as it does at every step, and the law books
    // that half as it books any step, by the trapezoid rule with the force then zero: the dashpot's
    // work, and the shear spring's energy, which slips out entirely as the Coulomb cone closes with
    // the normal force. Unbooked, they were the block's largest energy imbalance: 2.2 % of a run,
    // first order in the step (docs/accuracy.md, "Energy audit").
    void end(const ContactGeometry& last, const Vec3& relativeVelocity, const ContactHistory& h, double dt,
             DissipationLedger& ledger) const;
};

// The incremental tangential spring with Coulomb limit shared by all laws (Eqs. 17-19):
// the stored shear force is first carried with the contact plane (rotated from the previous normal
// to the current one, then twisted by the mean spin about the normal), then incremented by
// -K_t dU_t and, if it exceeds F_n tan(phi), scaled back onto the Coulomb limit (Eq. 18); the work
// of that return is dissipated by friction.
Vec3 updateShearForce(const ContactGeometry& g, ContactHistory& h, double kt, double normalForce, double tanPhi,
                      double dt, DissipationLedger& ledger);

}  // namespace sylva::dem

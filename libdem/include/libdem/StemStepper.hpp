#pragma once
// Advances stems by one explicit step: connections and root spring at the current configuration ->
// gravity and the given loads -> energy at the step's start -> leapfrog (positions, and orientations
// turned by the isotropic nodes' angular velocities).
#include <vector>

#include "libdem/Stem.hpp"

namespace sylva::dem {

// External loads on the nodes (world frame): force in N, torque about the node's centre in N m.
// Empty vectors mean none; otherwise they are sized nodeCount().
struct StemLoads {
    std::vector<Vec3> force, torque;
};

// Mechanical energy of a stem at the start of a step, J (potential relative to height 0), and the
// energy that left it up to then: dissipated - StemLedger::unloadingGain - external work. The
// ledger's entries are of two kinds: the laws' (plasticity, rupture, gain, and the axial dashpot's
// work, booked once the step it acted over is made) are known exactly at the configuration of the
// step's start; the power terms (viscosity, relaxation, loads) are taken over
// the step about to be made, of which half belongs before its start (trapezoid rule).
// total() + netLoss is constant up to the integration's error.
struct StemEnergy {
    double kinetic = 0, elastic = 0, potential = 0;
    double netLoss = 0;
    double farthestMove = 0;  // m: the longest way a node went over the step
    double total() const { return kinetic + elastic + potential; }
};

// What a step starts from. A stem's velocities are the leapfrog's mid-step ones, half a step before
// the step's start; a stem at rest there (woken standing, or stopped by ForestMotion's rest) has zero
// velocity at the start itself, and its first kick is half a step's, as velocity Verlet starts. Kicked a
// whole step from rest instead, a stem stopped and set moving again at every step moves by dt^2 a
// per step, which diverges above dt = sqrt(2) / omega, where the leapfrog's limit is 2 / omega.
enum class StemStart { Moving, FromRest };

class StemStepper {
public:
    // relaxationRate (1/s) adds a force -rate m v (and torque -rate I omega) on every node: a
    // numerical damping to settle stems into static equilibrium (e.g. under their own weight before
    // a run); 0 for dynamics. Its work goes to StemLedger::relaxation.
    explicit StemStepper(const Vec3& gravity = Vec3(0, 0, -9.81), double relaxationRate = 0);

    // One step of dt (at most stem.stableTimeStep()). Returns the energy at the step's start, with the
    // velocities brought to that instant. Throws SimulationError if the state becomes NaN.
    StemEnergy step(Stem& stem, double dt, const StemLoads& loads = {}, StemStart start = StemStart::Moving);
    // The same account for a stem at rest that is not stepped (no velocity, no load): its state as
    // left by the last step or by carryOwnWeight.
    StemEnergy energyAtRest(const Stem& stem) const;

private:
    Vec3 gravity_;
    double relaxationRate_;
    std::vector<Vec3> force_, torque_;
};

}  // namespace sylva::dem

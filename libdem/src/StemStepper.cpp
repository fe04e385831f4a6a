#include "libdem/StemStepper.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "libdem/RotationVector.hpp"
#include "libdem/SimulationError.hpp"

namespace sylva::dem {

StemStepper::StemStepper(const Vec3& gravity, double relaxationRate)
    : gravity_(gravity), relaxationRate_(relaxationRate) {}

namespace {

// Energy that left the stem up to a step's start (StemEnergy::netLoss), the power terms by the
// trapezoid rule over the step from `before` to `after`.
double netLoss(const StemLedger& before, const StemLedger& after) {
    return after.bendingPlasticity + after.axialDamping + after.rootPlasticity + after.rupture - after.unloadingGain +
           0.5 * (before.bendingDamping + after.bendingDamping + before.relaxation + after.relaxation -
                  before.externalWork - after.externalWork);
}

}  // namespace

StemEnergy StemStepper::energyAtRest(const Stem& stem) const {
    StemEnergy e;
    e.elastic = stem.elasticEnergy();
    for (std::size_t i = 0; i < stem.nodeCount(); ++i) e.potential -= stem.mass()[i] * gravity_.dot(stem.position[i]);
    e.netLoss = netLoss(stem.ledger, stem.ledger);
    return e;
}

StemEnergy StemStepper::step(Stem& stem, double dt, const StemLoads& loads, StemStart start) {
    const std::size_t n = stem.nodeCount();
    const bool hasForce = !loads.force.empty(), hasTorque = !loads.torque.empty();
    if ((hasForce && loads.force.size() != n) || (hasTorque && loads.torque.size() != n))
        throw std::invalid_argument("StemLoads must be empty or sized to the stem's " + std::to_string(n) + " nodes");
    force_.assign(n, Vec3::Zero());
    torque_.assign(n, Vec3::Zero());
    const StemLedger before = stem.ledger;
    stem.updateConnections(force_, torque_, dt);

    StemEnergy e;
    e.elastic = stem.elasticEnergy();
    const std::vector<double>& mass = stem.mass();
    const std::vector<double>& inertia = stem.inertia();
    StemLedger& ledger = stem.ledger;
    const double rate = relaxationRate_;
    // From rest, the velocities half a step back are those that make the start's own zero: minus half
    // a kick (velocity Verlet's start), so that the step's kick leaves half a kick.
    const double backKick = start == StemStart::FromRest ? -0.5 * dt : 0.0;
    double farthest2 = 0;
    for (std::size_t i = 0; i < n; ++i) {
        e.potential -= mass[i] * gravity_.dot(stem.position[i]);
        if (stem.translates(i)) {
            Vec3& v = stem.velocity[i];
            Vec3 f = force_[i] + mass[i] * gravity_ - rate * mass[i] * v;
            if (hasForce) f += loads.force[i];
            if (backKick != 0) v = backKick * stem.inverseMass()[i] * f;
            // Leapfrog: v(t - dt/2) -> v(t + dt/2); the kinetic energy at t from their mean.
            const Vec3 before = v;
            v += dt * stem.inverseMass()[i] * f;
            e.kinetic += 0.125 * mass[i] * (before + v).squaredNorm();
            const Vec3 dx = dt * v;
            farthest2 = std::max(farthest2, dx.squaredNorm());
            if (hasForce) ledger.externalWork += loads.force[i].dot(dx);
            ledger.relaxation += rate * mass[i] * before.dot(dx);
            stem.position[i] += dx;
        }
        if (stem.rotates(i)) {
            Vec3& w = stem.angularVelocity[i];
            Vec3 t = torque_[i] - rate * inertia[i] * w;
            if (hasTorque) t += loads.torque[i];
            if (backKick != 0) w = backKick * stem.inverseInertia()[i] * t;
            const Vec3 before = w;
            w += dt * stem.inverseInertia()[i] * t;  // isotropic inertia: no gyroscopic term
            e.kinetic += 0.125 * inertia[i] * (before + w).squaredNorm();
            const Vec3 turn = dt * w;
            if (hasTorque) ledger.externalWork += loads.torque[i].dot(turn);
            ledger.relaxation += rate * inertia[i] * before.dot(turn);
            Quat& q = stem.orientation[i];
            q = fromRotationVector(turn) * q;
            // Back to unit length: both factors are unit to rounding, so |q|^2 = 1 + e with e ~ 1e-16,
            // and one Newton step for 1 / sqrt(|q|^2), (3 - |q|^2) / 2, leaves an error of order e^2
            // without the root and the division normalized() takes.
            q.coeffs() *= 0.5 * (3 - q.coeffs().squaredNorm());
        }
    }
    // One test for all the nodes: a NaN or infinite velocity makes the kinetic energy so, and finite
    // velocities (their squares finite, so under 1e154 m/s) move finite nodes to finite places.
    if (!std::isfinite(e.kinetic)) {
        std::size_t i = 0;
        while (i + 1 < n && stem.velocity[i].allFinite() && stem.angularVelocity[i].allFinite()) ++i;
        throw SimulationError("stem node " + std::to_string(i) + " became NaN (time step " + std::to_string(dt) +
                              " s; stable limit " + std::to_string(stem.stableTimeStep()) + " s)");
    }
    e.netLoss = netLoss(before, ledger);
    e.farthestMove = std::sqrt(farthest2);
    return e;
}

}  // namespace sylva::dem

// A stem that starts from rest (woken standing, or stopped by ForestMotion's rest and set moving
// again) takes half a kick first (StemStart::FromRest). The case that showed why: a broken stem the
// block came near and left, stopped and restarted at every step for 30 steps (MO1 A, seed 9, run 68,
// with the rest test's margin dropped), grew from 50 J to 160 kJ of elastic energy in 8 steps and
// stopped the run. Restarted with a whole kick, each step moves the nodes by dt^2 a, a descent that
// diverges above dt = sqrt(2) / omega; with half a kick, by dt^2 a / 2, which settles up to the
// leapfrog's own limit 2 / omega.
#include <gtest/gtest.h>

#include <random>

#include "libdem/Stem.hpp"
#include "libdem/StemParameterSet.hpp"
#include "libdem/StemStepper.hpp"

using namespace sylva::dem;

namespace {

// A 20 cm stem bent every which way (random velocities, stepped freely for 200 steps), then stopped
// and restarted at each of `steps` steps at 0.95 of its stable step, as ForestMotion rests a stem set
// moving at every step. Returns its elastic energy at the end over that at the first restart
// (infinity if it blew up).
double restartedGrowth(StemStart start, int steps) {
    Stem stem(beechStem(20), stemParameters(StemParameterSet::Calibrated), Vec3::Zero(), StemFoot::Clamped);
    std::mt19937 rng(3);
    std::normal_distribution<double> normal;
    for (std::size_t i = 1; i < stem.nodeCount(); ++i) {
        stem.velocity[i] = 0.05 * Vec3(normal(rng), normal(rng), normal(rng));
        stem.angularVelocity[i] = 0.05 * Vec3(normal(rng), normal(rng), normal(rng));
    }
    StemStepper stepper(Vec3::Zero());
    const double dt = 0.95 * stem.stableTimeStep();
    for (int k = 0; k < 200; ++k) stepper.step(stem, dt);
    double first = 0, last = 0;
    for (int k = 0; k < steps; ++k) {
        for (std::size_t i = 0; i < stem.nodeCount(); ++i) stem.velocity[i].setZero(), stem.angularVelocity[i].setZero();
        const StemEnergy e = stepper.step(stem, dt, {}, start);
        if (k == 0) first = e.elastic;
        last = e.elastic;
        if (!(last < 1e6 * first)) return INFINITY;
    }
    return last / first;
}

}  // namespace

// From half a kick every mode shrinks by |1 - u^2 / 2| < 1 per restart, so the energy can only fall
// (below 1); from a whole one the fastest modes grow by up to 2.61 per restart, far past 100 in 200.
TEST(StemStart, AStemStoppedAndRestartedAtEveryStepSettlesFromHalfAKickAndDivergesFromAWholeOne) {
    EXPECT_LT(restartedGrowth(StemStart::FromRest, 200), 1.0);
    EXPECT_GT(restartedGrowth(StemStart::Moving, 200), 100.0);
}

// Half a kick from rest is velocity Verlet's start: the kinetic energy it reports at the step's
// start is zero (the stem is at rest there), and a node under a constant force alone moves by
// a dt^2 / 2 over the first step, as x = a t^2 / 2 says.
TEST(StemStart, FromRestTheFirstStepIsVelocityVerlets) {
    StemParams p = stemParameters(StemParameterSet::Calibrated);
    Stem stem(beechStem(20), p, Vec3::Zero(), StemFoot::Clamped);
    StemStepper stepper(Vec3::Zero());
    StemLoads loads;
    loads.force.assign(stem.nodeCount(), Vec3::Zero());
    loads.torque.assign(stem.nodeCount(), Vec3::Zero());
    const std::size_t top = stem.nodeCount() - 1;
    loads.force[top] = Vec3(100, 0, 0);  // N, sideways on the top: the straight stem's springs are slack
    const Vec3 before = stem.position[top];
    const double dt = 1e-4;
    const StemEnergy e = stepper.step(stem, dt, loads, StemStart::FromRest);
    EXPECT_EQ(e.kinetic, 0.0);
    const double a = 100 * stem.inverseMass()[top];
    // The springs act only from the next step (they are slack at the start): the move is exact, but
    // for the rounding of a dt^2 product (1e-12 of it; a whole kick would be off by all of it).
    EXPECT_NEAR(stem.position[top].x() - before.x(), 0.5 * a * dt * dt, 1e-12 * a * dt * dt);
}

// The stem's stable time step: every mode excited (random node velocities), stepping at the bound
// keeps the energy bounded, while 3.5 times the bound blows up, with and without the bending
// viscosity and on both feet. The bound is a Gershgorin estimate summed over the spring kinds, so
// it must lie below the true limit; 3.5 is how much of the step we accept to give away for that.
#include <gtest/gtest.h>

#include <random>

#include "libdem/SimulationError.hpp"
#include "libdem/Stem.hpp"
#include "libdem/StemStepper.hpp"

using namespace sylva::dem;

namespace {

// Largest total energy over `steps` steps relative to the first one; infinity if the state became NaN.
double energyGrowth(double factor, double tau, StemFoot foot, int steps) {
    StemParams p;
    p.bending.tau = tau;
    Stem stem(beechStem(20), p, Vec3::Zero(), foot);
    std::mt19937 rng(3);
    std::normal_distribution<double> normal;
    const auto random = [&] { return Vec3(normal(rng), normal(rng), normal(rng)); };
    for (std::size_t i = 0; i < stem.nodeCount(); ++i) {
        if (stem.translates(i)) stem.velocity[i] = 1e-3 * random();
        if (stem.rotates(i)) stem.angularVelocity[i] = 1e-3 * random();
    }
    StemStepper stepper(Vec3::Zero());
    const double dt = factor * stem.stableTimeStep();
    double first = 0, largest = 0;
    try {
        for (int k = 0; k < steps; ++k) {
            const double e = stepper.step(stem, dt).total();
            if (k == 0) first = e;
            largest = std::max(largest, e);
            if (largest > 1e6 * first) break;
        }
    } catch (const SimulationError&) {
        return INFINITY;
    }
    return largest / first;
}

}  // namespace

TEST(StemTimeStep, StableAtTheBoundAndUnstableWellAboveIt) {
    for (const double tau : {0.0, 5e-4})
        for (const StemFoot foot : {StemFoot::Clamped, StemFoot::RootSpring}) {
            // A leapfrog oscillator at a stable step keeps its energy within (omega dt)^2 / 4 of
            // the start, at most 1 at the limit: 2x the first energy means growth.
            EXPECT_LT(energyGrowth(1.0, tau, foot, 20000), 2.0) << "tau " << tau << ", foot " << int(foot);
            EXPECT_GT(energyGrowth(3.5, tau, foot, 20000), 100.0) << "tau " << tau << ", foot " << int(foot);
        }
}

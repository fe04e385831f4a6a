// The stem's stable time step: every mode excited (random node velocities), stepping at the bound
// keeps the energy bounded, for both parameter sets, on both feet, with and without the paper's
// viscosity, at two spacings and three diameters; and the bound is tight: 1.6 times it blows up. The
// bound is Irons' element by element (Stem::stableTimeStep); the true limit lies above it, and how
// far above is the step it gives away.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "libdem/SimulationError.hpp"
#include "libdem/Stem.hpp"
#include "libdem/StemContact.hpp"
#include "libdem/StemParameterSet.hpp"
#include "libdem/StemStepper.hpp"

using namespace sylva::dem;

namespace {

struct Case {
    StemParameterSet set;
    double tau, spacing, dbhCm;
    StemFoot foot;
    std::string label() const {
        return std::string(name(set)) + ", tau " + std::to_string(tau) + ", spacing " + std::to_string(spacing) +
               ", DBH " + std::to_string(dbhCm) + ", foot " + std::to_string(int(foot));
    }
};

// Largest total energy over `steps` steps relative to the first one; infinity if the state became NaN.
double energyGrowth(const Case& c, double factor, int steps) {
    StemParams p;
    StemContactParams contact;
    apply(c.set, p, contact);
    p.bending.tau = c.tau;
    p.nodeSpacing = c.spacing;
    Stem stem(beechStem(c.dbhCm), p, Vec3::Zero(), c.foot);
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

std::vector<Case> cases() {
    std::vector<Case> all;
    for (const StemFoot foot : {StemFoot::Clamped, StemFoot::RootSpring}) {
        for (const double tau : {0.0, 5e-4}) all.push_back({StemParameterSet::Toe2018, tau, 0.5, 20, foot});
        for (const double spacing : {0.5, 0.25})
            for (const double dbh : {10.0, 20.0, 40.0}) all.push_back({StemParameterSet::Calibrated, 0, spacing, dbh, foot});
    }
    return all;
}

}  // namespace

TEST(StemTimeStep, StableAtTheBoundAndUnstableAboveIt) {
    for (const Case& c : cases()) {
        // Leapfrog conserves E~ = kinetic + (1 - (omega dt / 2)^2) potential of a mode, so the energy
        // measured at a step swings between E~ and E~ / (1 - (omega dt / 2)^2): at 0.8 of the limit (the
        // runs' integration.stem_safety) it stays within 1 / 0.36 = 2.8 of the start.
        EXPECT_LT(energyGrowth(c, 0.8, 10000), 2.8) << c.label();
        // At the limit itself that swing is unbounded but not exponential; above it the highest mode
        // grows by a factor per step and passes 1e6 well within the 10 000 steps.
        EXPECT_LT(energyGrowth(c, 1.0, 10000), 1e4) << c.label();
        // Tightness: the Gershgorin sum this bound replaced lay 1.1-2.9x below the true limit (a stem
        // stable at 2.9x). Bisected with this test's criterion the limit is 1.00-1.02x the bound for
        // the calibrated stems, 1.07-1.52x for the paper's (its viscosity's damping bound is the loose part).
        EXPECT_GT(energyGrowth(c, 1.6, 10000), 1e4) << c.label();
    }
}

// A woken stem must stand still: built straight and carrying its own weight (Stem::carryOwnWeight),
// the explicit step must leave it exactly where it is, which is what lets the forest skip stepping
// standing stems. Without the pre-compression the same stem sags and rings axially.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "libdem/Stem.hpp"
#include "libdem/StemStepper.hpp"

using namespace sylva::dem;

namespace {

constexpr double kGravity = 9.81;

// Largest node speed over `steps` steps at the stable step, m/s.
double largestSpeed(Stem& stem, int steps) {
    StemStepper stepper(Vec3(0, 0, -kGravity));
    const double dt = stem.stableTimeStep();
    double largest = 0;
    for (int k = 0; k < steps; ++k) {
        stepper.step(stem, dt);
        for (std::size_t i = 0; i < stem.nodeCount(); ++i) largest = std::max(largest, stem.velocity[i].norm());
    }
    return largest;
}

}  // namespace

TEST(StemOwnWeight, PreCompressedStemStandsStill) {
    for (const StemFoot foot : {StemFoot::Clamped, StemFoot::RootSpring}) {
        Stem stem(beechStem(25), StemParams{}, Vec3(3, 4, 100), foot);
        stem.carryOwnWeight(kGravity);
        const Vec3 top = stem.position.back();
        // Round-off only: coordinates near 100 m carry ~1e-14 m of rounding, which the axial springs
        // (~1e9 N/m) turn into ~1e-5 N on nodes of ~10 kg: at most a few 1e-7 m/s over these 0.3 s.
        const double speed = largestSpeed(stem, 5000);
        std::printf("foot %d: largest node speed %.3g m/s\n", int(foot), speed);
        EXPECT_LT(speed, 1e-7) << "foot " << int(foot);
        EXPECT_LT((stem.position.back() - top).norm(), 1e-10);
    }
    // The same stem without it settles by its weight's axial strain, a hundred times faster at least.
    Stem sagging(beechStem(25), StemParams{}, Vec3(3, 4, 100), StemFoot::Clamped);
    const double sag = largestSpeed(sagging, 5000);
    std::printf("without carryOwnWeight: %.3g m/s\n", sag);
    EXPECT_GT(sag, 1e-5);
}

TEST(StemOwnWeight, StoredEnergyIsTheAxialSpringsUnderTheWeightAbove) {
    const StemParams p;
    Stem stem(beechStem(30), p, Vec3::Zero(), StemFoot::RootSpring);
    stem.carryOwnWeight(kGravity);
    // Each connection's axial spring (k = MOE A / l) carries the weight W of the nodes above it:
    // energy W^2 / 2k.
    double expected = 0, above = 0;
    for (std::size_t c = stem.connectionCount(); c-- > 0;) {
        above += stem.mass()[c + 1] * kGravity;
        const double d = stem.connectionDiameter(c);
        const double k = p.bending.moe * M_PI * d * d / 4 / stem.connectionLength(c);
        expected += above * above / (2 * k);
    }
    EXPECT_NEAR(stem.elasticEnergy(), expected, 1e-12 * expected);
    // ... and the first step finds the same energy in the springs.
    StemStepper stepper(Vec3(0, 0, -kGravity));
    EXPECT_NEAR(stepper.step(stem, stem.stableTimeStep()).elastic, expected, 1e-9 * expected);
}

// The stem's energy account closes when it dissipates: a stem settled under its own weight is
// struck sideways hard enough to yield (bending plasticity, Eqs. 2-6, or the root spring, Eqs.
// 9-10), then swings with the bending viscosity (Eqs. 7-8). At every step kinetic + elastic +
// potential + dissipated - unloadingGain - external work keeps its initial value, up to an error
// of the integration that shrinks with the time step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "libdem/Stem.hpp"
#include "libdem/StemStepper.hpp"

using namespace sylva::dem;

namespace {

struct Budget {
    double worstGap = 0, input = 0;
    StemLedger ledger;
};

// Settles the stem under gravity, then pushes the node nearest `height` along x with `force` for
// `duration` and follows it up to 1 s, at `safety` times the stable step.
Budget strike(double dbhCm, StemFoot foot, double height, double force, double duration, double safety,
              const StemParams& params = StemParams{}) {
    Stem stem(beechStem(dbhCm), params, Vec3::Zero(), foot);
    const Vec3 gravity(0, 0, -9.81);
    const double dt = safety * stem.stableTimeStep();
    StemStepper settle(gravity, 6.0);
    for (double t = 0; t < 3; t += dt) settle.step(stem, dt);
    stem.ledger = StemLedger{};

    const std::size_t struck = static_cast<std::size_t>(std::lround(height / stem.connectionLength(0)));
    StemLoads loads;
    loads.force.assign(stem.nodeCount(), Vec3::Zero());
    StemStepper stepper(gravity);
    Budget b;
    double initial = 0;
    for (double t = 0; t < 1.0; t += dt) {
        loads.force[struck] = Vec3(t < duration ? force : 0.0, 0, 0);
        const StemEnergy e = stepper.step(stem, dt, loads);
        if (t == 0) initial = e.total() + e.netLoss;
        b.worstGap = std::max(b.worstGap, std::abs(e.total() + e.netLoss - initial));
    }
    b.ledger = stem.ledger;
    b.input = stem.ledger.externalWork;
    return b;
}

void print(const char* what, double safety, const Budget& b) {
    std::printf("  %s, dt = %.1f x limit: work in %.0f J; plastic %.0f, viscous %.0f, root %.0f, rupture %.0f, "
                "gain %.0f J; worst gap %.2e of the work in\n",
                what, safety, b.input, b.ledger.bendingPlasticity, b.ledger.bendingDamping, b.ledger.rootPlasticity,
                b.ledger.rupture, b.ledger.unloadingGain, b.worstGap / b.input);
}

}  // namespace

// 40 kN for 30 ms at 1.5 m on a clamped 20 cm beech: sections yield, the slender top may break.
// The ledger takes each work with the rotations at the steps' ends while the leapfrog applies the
// moments over the step: a mismatch of order omega dt for the fast modes that carry plasticity and
// viscosity. 1 % of the work put in at 0.9 of the stable limit; a third of the step must at least
// halve it, as a discretisation error does (a leak would not shrink).
TEST(StemEnergyBudget, ClosesWithBendingPlasticityAndViscosity) {
    const Budget coarse = strike(20, StemFoot::Clamped, 1.5, 40e3, 0.03, 0.9);
    const Budget fine = strike(20, StemFoot::Clamped, 1.5, 40e3, 0.03, 0.3);
    print("clamped", 0.9, coarse);
    print("clamped", 0.3, fine);
    ASSERT_GT(coarse.ledger.bendingPlasticity, 0.1 * coarse.input) << "the strike must yield the stem";
    ASSERT_GT(coarse.ledger.bendingDamping, 0.1 * coarse.input);
    EXPECT_LT(coarse.worstGap, 1e-2 * coarse.input);
    EXPECT_LT(fine.worstGap / fine.input, 0.5 * coarse.worstGap / coarse.input);
}

// 80 kN for 0.3 s at 3 m on a 35 cm beech on its root spring: the foot turns beyond M_a.
TEST(StemEnergyBudget, ClosesWithRootPlasticity) {
    const Budget b = strike(35, StemFoot::RootSpring, 3.0, 80e3, 0.3, 0.9);
    print("root spring", 0.9, b);
    ASSERT_GT(b.ledger.rootPlasticity, 0.1 * b.input) << "the strike must yield the root";
    EXPECT_LT(b.worstGap, 1e-2 * b.input);
}

// The same strike with wood's constant loss factor instead of Eqs. 7-8 (BendingDamping): its
// Maxwell branches store energy as well as dissipate it, and both must be in the account. Same
// bounds as with the viscous law, for the same reason.
TEST(StemEnergyBudget, ClosesWithTheConstantLossFactor) {
    StemParams p;
    p.bending.damping = StemDamping::ConstantLoss;
    p.bending.sections = 3;
    const Budget coarse = strike(20, StemFoot::Clamped, 1.5, 40e3, 0.03, 0.9, p);
    const Budget fine = strike(20, StemFoot::Clamped, 1.5, 40e3, 0.03, 0.3, p);
    print("constant loss", 0.9, coarse);
    print("constant loss", 0.3, fine);
    ASSERT_GT(coarse.ledger.bendingPlasticity, 0.1 * coarse.input) << "the strike must yield the stem";
    ASSERT_GT(coarse.ledger.bendingDamping, 0) << "the branches must dissipate";
    EXPECT_LT(coarse.worstGap, 1e-2 * coarse.input);
    EXPECT_LT(fine.worstGap / fine.input, 0.5 * coarse.worstGap / coarse.input);
}

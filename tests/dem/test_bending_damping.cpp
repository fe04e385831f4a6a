// The damping of a connection's bending (BendingDamping): the paper's dashpot (Eqs. 7-8) and wood's
// frequency-independent loss factor, checked against their closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "libdem/BendingDamping.hpp"

using namespace sylva::dem;

namespace {
constexpr double kPi = 3.14159265358979323846;

HingeCoefficients hinge(const BendingParams& p) { return bendingCoefficients(p, 0.25, 0.5); }

// Loss factor of the Maxwell branches in parallel with K_Elast at omega, in closed form: the
// imaginary over the real part of K (1 + sum g i w tau / (1 + i w tau)).
double exactLossFactor(double g, double omega) {
    double re = 1, im = 0;
    for (int b = 0; b < BendingDamping::kBranches; ++b) {
        const double x = omega * BendingDamping::relaxationTime(b);
        re += g * x * x / (1 + x * x);
        im += g * x / (1 + x * x);
    }
    return im / re;
}

// Drives the connection at theta = A sin(omega t) for `cycles` periods, 4000 steps each; returns the
// energy dissipated in the last period over 2 pi times the peak elastic energy K_Elast A^2 / 2
// (the definition of the loss factor, with the branches' own storage folded in below).
double measuredLossFactor(BendingDamping& d, double kElastic, double omega, int cycles, double* storedPeak) {
    const double amplitude = 1e-3, period = 2 * kPi / omega;
    const int steps = 4000;
    const double dt = period / steps;
    double lastCycle = 0;
    *storedPeak = 0;
    for (int c = 0; c < cycles; ++c) {
        lastCycle = 0;
        for (int i = 0; i < steps; ++i) {
            const double tMid = (c * steps + i + 0.5) * dt;
            const BendingDamping::Step s = d.advance(Vec2(amplitude * omega * std::cos(omega * tMid), 0), dt);
            lastCycle += s.dissipated;
            if (c == cycles - 1) *storedPeak = std::max(*storedPeak, d.storedEnergy());
        }
    }
    return lastCycle / (kPi * kElastic * amplitude * amplitude);
}
}  // namespace

// Eqs. 7-8 on a 25 cm connection of 0.5 m (Table 2's tau = 5e-4 s): M = tau K_Elast theta-dot, and
// the work of that moment over the step is dissipated.
TEST(BendingDamping, ViscousMomentIsTauKElastTimesTheRelativeRate) {
    const BendingParams p;
    const HingeCoefficients k = hinge(p);
    BendingDamping d(p, k);
    const Vec2 rate(0.7, -2.0);  // rad/s
    const BendingDamping::Step s = d.advance(rate, 1e-5);
    EXPECT_NEAR(s.moment.x(), 5e-4 * k.elastic * 0.7, 1e-12 * k.elastic);   // Eq. 7
    EXPECT_NEAR(s.moment.y(), -5e-4 * k.elastic * 2.0, 1e-12 * k.elastic);  // Eq. 8
    EXPECT_NEAR(s.dissipated, 5e-4 * k.elastic * rate.squaredNorm() * 1e-5, 1e-12 * s.dissipated);
    EXPECT_EQ(d.storedEnergy(), 0.0);
}

// Driven harmonically from 1 to 5000 rad/s (a stem's first mode to the bending waves an impact
// launches), the branches dissipate per cycle what the closed-form loss factor of K (1 + sum g i w tau
// / (1 + i w tau)) says, to 1e-3 (the rate is sampled 4000 times a period; 40 periods let the slowest
// branch's transient fade), and that loss factor is eta within 6 %: the ripple of one branch per decade.
TEST(BendingDamping, ConstantLossFactorAcrossTheBand) {
    BendingParams p;
    p.damping = StemDamping::ConstantLoss;
    p.lossFactor = 0.02;
    const HingeCoefficients k = hinge(p);
    BendingDamping probe(p, k);
    const double g = probe.addedStiffness() / BendingDamping::kBranches / k.elastic;
    for (const double omega : {1.0, 10.0, 100.0, 1e3, 5e3}) {
        BendingDamping d(p, k);
        double stored = 0;
        // Dissipated per cycle over pi K' A^2, K' the real part: K_Elast's and the branches' storage.
        double re = 1;
        for (int b = 0; b < BendingDamping::kBranches; ++b) {
            const double x = omega * BendingDamping::relaxationTime(b);
            re += g * x * x / (1 + x * x);
        }
        const double eta = measuredLossFactor(d, k.elastic, omega, 40, &stored) / re;
        const double exact = exactLossFactor(g, omega);
        EXPECT_NEAR(eta, exact, 1e-3 * exact) << "omega " << omega;
        EXPECT_NEAR(exact, p.lossFactor, 0.06 * p.lossFactor) << "omega " << omega;
        EXPECT_GT(stored, 0);
    }
}

// Rupture: the branches give back what they hold and transmit nothing after.
TEST(BendingDamping, ReleaseReturnsTheStoredEnergy) {
    BendingParams p;
    p.damping = StemDamping::ConstantLoss;
    const HingeCoefficients k = hinge(p);
    BendingDamping d(p, k);
    for (int i = 0; i < 100; ++i) d.advance(Vec2(3, -1), 1e-4);
    const double held = d.storedEnergy();
    ASSERT_GT(held, 0);
    EXPECT_DOUBLE_EQ(d.release(), held);
    EXPECT_EQ(d.storedEnergy(), 0.0);
    EXPECT_EQ(d.advance(Vec2(3, -1), 1e-4).moment.norm(), 0.0);
}

// The work done on the branches is stored or dissipated, and dissipation is never negative, on a
// path with reversals and rates four decades apart. The work is taken independently of the ledger,
// by the trapezoid rule on the moments the branches return at the steps' ends: 1e-4 is that rule's
// error at 2e-6 s steps on the fastest (2e-5 s) branch.
TEST(BendingDamping, WorkIsStoredOrDissipated) {
    BendingParams p;
    p.damping = StemDamping::ConstantLoss;
    BendingDamping d(p, hinge(p));
    double work = 0, dissipated = 0;
    const double dt = 2e-6;
    Vec2 previous = Vec2::Zero();
    for (int i = 0; i < 100000; ++i) {
        const double t = (i + 0.5) * dt;
        const Vec2 rate(std::sin(30 * t) + 0.05 * std::sin(5000 * t), std::cos(400 * t));
        const BendingDamping::Step s = d.advance(rate, dt);
        ASSERT_GE(s.dissipated, -1e-12);
        dissipated += s.dissipated;
        work += 0.5 * (previous + s.moment).dot(rate) * dt;
        previous = s.moment;
    }
    ASSERT_GT(dissipated, 0);
    EXPECT_NEAR(work, dissipated + d.storedEnergy(), 1e-4 * work);
}

// A stem connection as a force-based beam element (ConnectionBeam): with one section it is the
// paper's hinge (BendingLaw, checked against Fig. 3's closed form in test_bending_law.cpp); with 3 or
// 5 sections its elastic response is the Euler-Bernoulli (+ shear) element's in closed form, yield
// starts at the more loaded end, and whatever the path the work done on it is stored or dissipated.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "libdem/ConnectionBeam.hpp"

using namespace sylva::dem;

namespace {

const double kPi = std::acos(-1.0);
constexpr double kDiameter = 0.2, kLength = 0.5;
const double kShear = 3.3e9 * kPi * kDiameter * kDiameter / 4 / kLength;  // G A / l, N/m

double secondMoment() { return kPi * std::pow(kDiameter, 4) / 64; }

// Generalised force times deformation, summed by the trapezoid rule along a path.
struct WorkMeter {
    Vec2 moment = Vec2::Zero(), shear = Vec2::Zero(), theta = Vec2::Zero(), stretch = Vec2::Zero();
    double work = 0;
    // The shear force acts on node a; the stretch is b's displacement from a: the connection does
    // -shear . d(stretch) on the nodes' relative motion, i.e. the nodes do +shear . d(stretch) on it.
    void step(const ConnectionBeam& c, const Vec2& theta2, const Vec2& stretch2) {
        work += 0.5 * (moment + c.moment()).dot(theta2 - theta) + 0.5 * (shear + c.shearForce()).dot(stretch2 - stretch);
        moment = c.moment();
        shear = c.shearForce();
        theta = theta2;
        stretch = stretch2;
    }
};

}  // namespace

// One section, at the middle, with the connection's mean diameter: the moment, the dissipated and
// the created energy are the paper's hinge's along a random path to rupture (both readings); the
// shear force is the shear spring's. Same arithmetic in another order: 1e-9.
TEST(ConnectionBeam, OneSectionIsThePapersHinge) {
    for (const BendingReading reading : {BendingReading::Isotropic, BendingReading::PerAxis}) {
        BendingParams p;
        p.reading = reading;
        BendingLaw law(bendingCoefficients(p, kDiameter, kLength), reading);
        ConnectionBeam beam(p, kDiameter, kDiameter, kShear, kLength, 1);
        const double thetaYield = law.coefficients().yieldMoment / law.coefficients().elastic;
        std::mt19937 rng(3);
        std::normal_distribution<double> noise(0, 0.05 * thetaYield);
        Vec2 theta = Vec2::Zero();
        HingeWork a, b;
        int steps = 0;
        for (; steps < 50000 && !law.broken(); ++steps) {
            const Vec2 d(noise(rng) + 0.002 * thetaYield, noise(rng));  // drifts to rupture about x
            theta += d;
            const Vec2 stretch(noise(rng) * kLength, noise(rng) * kLength);
            const HingeWork wa = law.rotate(d), wb = beam.deform(theta, stretch);
            a.dissipated += wa.dissipated;
            b.dissipated += wb.dissipated;
            a.created += wa.created;
            b.created += wb.created;
            ASSERT_EQ(law.broken(), beam.broken()) << "step " << steps;
            ASSERT_LT((law.moment() - beam.moment()).norm(), 1e-9 * law.coefficients().ruptureMoment) << "step " << steps;
            if (!beam.broken()) {
                ASSERT_LT((beam.shearForce() - kShear * stretch).norm(), 1e-9 * kShear * stretch.norm());
            }
        }
        EXPECT_TRUE(beam.broken()) << "the path must reach rupture";
        EXPECT_NEAR(b.dissipated, a.dissipated, 1e-9 * a.dissipated);
        EXPECT_NEAR(b.created, a.created, 1e-9 * a.created);
    }
}

// Elastic, uniform: theta alone gives M = E I / l theta and no change along the connection; a
// transverse stretch alone gives the Timoshenko element's shear force s / (l^3 / (12 E I) + 1 / k_s),
// exactly (both rules integrate xi^2 exactly).
TEST(ConnectionBeam, ElasticSectionsAreTheBeamElement) {
    const BendingParams p;
    const double ei = p.moe * secondMoment();
    for (const int sections : {3, 5}) {
        ConnectionBeam bending(p, kDiameter, kDiameter, kShear, kLength, sections);
        bending.deform(Vec2(1e-4, -2e-4), Vec2::Zero());
        EXPECT_NEAR(bending.moment().x(), ei / kLength * 1e-4, 1e-9 * ei / kLength * 1e-4);
        EXPECT_NEAR(bending.moment().y(), -ei / kLength * 2e-4, 1e-9 * ei / kLength * 2e-4);
        EXPECT_NEAR(bending.shearForce().norm(), 0, 1e-9 * ei / kLength * 1e-4);

        ConnectionBeam shear(p, kDiameter, kDiameter, kShear, kLength, sections);
        const Vec2 s(1e-5, 3e-5);
        shear.deform(Vec2::Zero(), s);
        const double stiffness = 1 / (std::pow(kLength, 3) / (12 * ei) + 1 / kShear);
        EXPECT_LT((shear.shearForce() - stiffness * s).norm(), 1e-9 * stiffness * s.norm()) << sections;
        // The shear force changes the moment along the connection by l V: half of it each side.
        EXPECT_NEAR((shear.sectionMoment(sections - 1) - shear.sectionMoment(0)).norm(), kLength * stiffness * s.norm(),
                    1e-9 * kLength * stiffness * s.norm());
        EXPECT_NEAR(shear.storedEnergy(), 0.5 * stiffness * s.squaredNorm(), 1e-9 * stiffness * s.squaredNorm());
    }
}

// Loaded so that the moment at the middle is M and at the ends M -+ dM with dM = M / 2: the end
// carrying 1.5 M yields when 1.5 M = M_Elast, i.e. when the middle is at 2/3 of it, where one section
// (the paper's hinge) stays elastic up to M = M_Elast. The drive is proportional and elastic until
// then, so the first plastic work appears within one increment of the predicted one.
TEST(ConnectionBeam, YieldStartsAtTheMoreLoadedEnd) {
    const BendingParams p;
    const double ei = p.moe * secondMoment(), yield = bendingCoefficients(p, kDiameter, kLength).yieldMoment;
    for (const int sections : {1, 3, 5}) {
        ConnectionBeam c(p, kDiameter, kDiameter, kShear, kLength, sections);
        // Elastic deformations for M = 1 N m and dM = 0.5 N m about y (the moment vector's y part
        // pairs with eps_y = -(2 / l) s_x).
        const double flexChange = kLength / (3 * ei) + 4 / (kLength * kLength * kShear);
        const double theta = kLength / ei, eps = 0.5 * (sections == 1 ? 4 / (kLength * kLength * kShear) : flexChange);
        const int n = 2000;
        const double top = 1.2 * yield;  // mean moment at the end of the drive
        double firstPlastic = -1;
        for (int i = 1; i <= n && firstPlastic < 0; ++i) {
            const double m = top * i / n;
            if (c.deform(Vec2(0, m * theta), Vec2(-0.5 * kLength * m * eps, 0)).dissipated > 0) firstPlastic = m;
        }
        const double expected = sections == 1 ? yield : yield / 1.5;
        EXPECT_NEAR(firstPlastic, expected, 1.5 * top / n) << sections << " sections";
    }
}

// Along any path, with the plastic flows of several sections coupled, unloading and reversal: the
// work the nodes do on the connection (trapezoid rule on small increments) is what it stores plus
// what it dissipates less what the law creates at first yield, up to rupture. The noise turns
// loading into unloading at most increments, so the path kinks at nearly every one and the trapezoid
// rule's error is first order overall (measured: 1.5e-4, 8.2e-5, 4.2e-5, 2.1e-5 of the work as the
// increments halve from twice these); at ~1/500 of the yield rotation it stays below 1e-4.
TEST(ConnectionBeam, WorkDoneOnItIsStoredOrDissipated) {
    for (const int sections : {3, 5}) {
        for (const BendingReading reading : {BendingReading::Isotropic, BendingReading::PerAxis}) {
            BendingParams p;
            p.reading = reading;
            ConnectionBeam c(p, 0.22, 0.18, kShear, kLength, sections);  // tapered
            const HingeCoefficients k = c.coefficients();
            const double thetaYield = k.yieldMoment / k.elastic;
            std::mt19937 rng(11);
            std::normal_distribution<double> noise(0, 0.002 * thetaYield);
            WorkMeter meter;
            Vec2 theta = Vec2::Zero(), stretch = Vec2::Zero();
            HingeWork sum;
            double balance = 0, worst = 0;
            int reversals = 0;
            double lastPhase = 0;
            for (int i = 0; i < 200000 && !c.broken(); ++i) {
                const double phase = std::sin(i * 2e-4);  // loading cycles of growing amplitude
                reversals += (phase > 0) != (lastPhase > 0);
                lastPhase = phase;
                theta += Vec2(noise(rng) + 5e-4 * thetaYield * phase * (1 + i * 1e-5), noise(rng));
                stretch += Vec2(noise(rng), noise(rng) + 2e-4 * thetaYield * phase) * 0.05 * kLength;  // dM ~ M / 3
                const HingeWork w = c.deform(theta, stretch);
                ASSERT_GE(w.dissipated, 0);
                if (c.broken()) break;
                sum.dissipated += w.dissipated;
                sum.created += w.created;
                meter.step(c, theta, stretch);
                balance = meter.work - (c.storedEnergy() + sum.dissipated - sum.created);
                worst = std::max(worst, std::abs(balance) / std::max(meter.work, 1.0));
            }
            std::printf("  %d sections, %s: %d reversals, work %.1f J, dissipated %.1f J, created %.1f J, worst gap %.1e\n",
                        sections, reading == BendingReading::Isotropic ? "isotropic" : "per axis", reversals, meter.work,
                        sum.dissipated, sum.created, worst);
            ASSERT_TRUE(c.broken()) << "the path must reach rupture";
            ASSERT_GE(reversals, 2) << "and be loaded both ways on the way";
            ASSERT_GT(sum.dissipated, 0.3 * meter.work) << "yielding much";
            EXPECT_LT(worst, 1e-4);
        }
    }
}

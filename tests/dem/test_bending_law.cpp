// The trilinear bending law of a stem connection (Fig. 3, Eqs. 2-6) and its viscous moment
// (Eqs. 7-8): moments along a loading / plastic / unloading / reloading / rupture path against the
// closed-form trilinear path, the energy it dissipates against the areas under that path, and the
// two readings of the law on the two bending axes.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "libdem/BendingLaw.hpp"

using namespace sylva::dem;

namespace {

const double kPi = std::acos(-1.0);
// The law is piecewise linear and splits each increment exactly at the yield point, so it must
// reproduce the closed form to rounding; 1e-9 of the rupture moment leaves room for the sums of
// a few hundred increments.
constexpr double kRel = 1e-9;

// A 25 cm connection of 0.5 m with Table 2's beech, per axis or isotropic.
HingeCoefficients beechHinge() { return bendingCoefficients(BendingParams{}, 0.25, 0.5); }

// Closed-form moment of Fig. 3 along a path that loads to thetaMax (beyond the yield rotation)
// and then stays between the unloading line and thetaMax: the envelope up to the largest rotation
// reached, the unloading line of slope K_Unld below it.
struct TrilinearPath {
    HingeCoefficients k;
    double thetaElast() const { return k.yieldMoment / k.elastic; }
    double envelope(double theta) const {
        return theta <= thetaElast() ? k.elastic * theta : k.yieldMoment + k.plastic * (theta - thetaElast());
    }
    double thetaRupt() const { return thetaElast() + (k.ruptureMoment - k.yieldMoment) / k.plastic; }
    // Moment at theta once the largest rotation reached is thetaMax (>= theta_Elast).
    double after(double thetaMax, double theta) const {
        if (theta >= thetaMax) return envelope(theta);
        return envelope(thetaMax) - k.unloading * (thetaMax - theta);
    }
};

// Drives a law about x from `from` to `to` in `n` equal increments.
void driveX(BendingLaw& law, double from, double to, int n, HingeWork& sum) {
    for (int i = 0; i < n; ++i) {
        const HingeWork w = law.rotate(Vec2((to - from) / n, 0));
        sum.dissipated += w.dissipated;
        sum.created += w.created;
        sum.released += w.released;
    }
}

}  // namespace

TEST(BendingLaw, CoefficientsFollowEqs2To6WithTable2InPascals) {
    const double d = 0.3, l = 0.5;
    const HingeCoefficients k = bendingCoefficients(BendingParams{}, d, l);
    const double secondMoment = kPi * std::pow(d, 4) / 64;  // 3.976e-4 m^4
    EXPECT_NEAR(k.elastic, 8.7e9 * secondMoment / l, 1e-6 * k.elastic);
    EXPECT_NEAR(k.plastic, 2.1e9 * secondMoment / l, 1e-6 * k.plastic);
    EXPECT_NEAR(k.unloading, 5.3e9 * secondMoment / l, 1e-6 * k.unloading);
    // sigma I 2 / D is sigma times the section modulus pi D^3 / 32: 98.1 kN m at 37 MPa for 30 cm.
    EXPECT_NEAR(k.yieldMoment, 37e6 * kPi * d * d * d / 32, 1e-6 * k.yieldMoment);
    EXPECT_NEAR(k.yieldMoment, 98.07e3, 0.01e3);
    EXPECT_NEAR(k.ruptureMoment, 94e6 * kPi * d * d * d / 32, 1e-6 * k.ruptureMoment);
    EXPECT_NEAR(k.viscosity, 5e-4 * k.elastic, 1e-9 * k.viscosity);
}

TEST(BendingLaw, LoadingPlasticUnloadingReloadingAndRuptureFollowTheTrilinearPath) {
    for (const BendingReading reading : {BendingReading::PerAxis, BendingReading::Isotropic}) {
        const TrilinearPath path{beechHinge()};
        BendingLaw law(path.k, reading);
        const double tol = kRel * path.k.ruptureMoment;
        const double thetaMax = path.thetaElast() + 0.4 * (path.thetaRupt() - path.thetaElast());
        // Unload past zero moment into reversed bending, staying inside the elastic domain.
        const double thetaLow = thetaMax - 1.6 * path.envelope(thetaMax) / path.k.unloading;
        ASSERT_GT(path.after(thetaMax, thetaLow), -path.envelope(thetaMax));
        ASSERT_LT(path.after(thetaMax, thetaLow), 0.0);

        const std::vector<double> legs = {0.0, thetaMax, thetaLow, thetaMax, path.thetaRupt() - 1e-6};
        const int n = 200;
        double theta = 0, reached = 0;
        for (std::size_t leg = 1; leg < legs.size(); ++leg) {
            const double step = (legs[leg] - legs[leg - 1]) / n;
            for (int i = 0; i < n; ++i) {
                law.rotate(Vec2(step, 0));
                theta += step;
                reached = std::max(reached, theta);
                const double expected = reached <= path.thetaElast() ? path.envelope(theta) : path.after(reached, theta);
                ASSERT_NEAR(law.moment().x(), expected, tol) << "leg " << leg << ", theta = " << theta;
                ASSERT_NEAR(law.moment().y(), 0.0, tol);
                ASSERT_FALSE(law.broken()) << "theta = " << theta;
            }
        }
        // Crossing theta_Rupt breaks the connection for good.
        law.rotate(Vec2(2e-6, 0));
        EXPECT_TRUE(law.broken());
        EXPECT_EQ(law.moment().norm(), 0.0);
        law.rotate(Vec2(-0.05, 0.02));
        EXPECT_EQ(law.moment().norm(), 0.0);
    }
}

TEST(BendingLaw, OneLargeIncrementLandsOnThePathToo) {
    const TrilinearPath path{beechHinge()};
    BendingLaw law(path.k, BendingReading::PerAxis);
    const double theta = 0.5 * (path.thetaElast() + path.thetaRupt());
    law.rotate(Vec2(theta, 0));  // elastic and plastic in one increment
    EXPECT_NEAR(law.moment().x(), path.envelope(theta), kRel * path.k.ruptureMoment);
    law.rotate(Vec2(path.thetaRupt() - theta + 1e-3, 0));
    EXPECT_TRUE(law.broken());
}

// Work put into the hinge along the closed-form path (areas under it) against the law's account:
// work in = energy still stored + dissipated - created.
TEST(BendingLaw, DissipationIsTheAreaOfTheHysteresisLoop) {
    const TrilinearPath path{beechHinge()};
    const HingeCoefficients& k = path.k;
    BendingLaw law(k, BendingReading::Isotropic);
    const double thetaMax = path.thetaElast() + 0.5 * (path.thetaRupt() - path.thetaElast());
    const double mMax = path.envelope(thetaMax);
    const double thetaZero = thetaMax - mMax / k.unloading;  // moment back to zero
    HingeWork sum;
    driveX(law, 0, thetaMax, 300, sum);
    driveX(law, thetaMax, thetaZero, 300, sum);
    EXPECT_NEAR(law.moment().x(), 0.0, kRel * k.ruptureMoment);

    const double workIn = 0.5 * k.yieldMoment * path.thetaElast() +
                          0.5 * (k.yieldMoment + mMax) * (thetaMax - path.thetaElast());
    const double workBack = 0.5 * mMax * mMax / k.unloading;
    // The only source: at the first yield the recoverable energy switches from K_Elast to K_Unld.
    const double created = 0.5 * k.yieldMoment * k.yieldMoment * (1 / k.unloading - 1 / k.elastic);
    EXPECT_NEAR(sum.created, created, 1e-9 * created);
    EXPECT_NEAR(sum.dissipated - sum.created, workIn - workBack, 1e-9 * workIn);
    EXPECT_NEAR(law.storedEnergy(), 0.0, 1e-12 * workIn);
    EXPECT_GT(sum.dissipated, 0.0);

    // Driven on to rupture: everything put in is dissipated, released with the break or created.
    driveX(law, thetaZero, path.thetaRupt() + 1e-4, 600, sum);
    ASSERT_TRUE(law.broken());
    const double toRupture = workIn - workBack + 0.5 * mMax * mMax / k.unloading +
                             0.5 * (mMax + k.ruptureMoment) * (path.thetaRupt() - thetaMax);
    EXPECT_NEAR(sum.released, 0.5 * k.ruptureMoment * k.ruptureMoment / k.unloading, 1e-9 * toRupture);
    EXPECT_NEAR(sum.dissipated + sum.released - sum.created, toRupture, 1e-6 * toRupture);
}

// The isotropic reading does not depend on the bending direction; per axis, a diagonal bending
// yields and breaks sqrt(2) times later than along an axis.
TEST(BendingLaw, ReadingsDifferOnlyOffTheAxes) {
    const TrilinearPath path{beechHinge()};
    const double tol = kRel * path.k.ruptureMoment;
    for (const double angle : {0.0, 0.3, kPi / 4, 2.0}) {
        const Vec2 dir(std::cos(angle), std::sin(angle));
        BendingLaw law(path.k, BendingReading::Isotropic);
        double theta = 0;
        const double step = path.thetaRupt() / 400;
        for (int i = 0; i < 399; ++i) {
            law.rotate(step * dir);
            theta += step;
            ASSERT_NEAR(law.moment().norm(), path.envelope(theta), tol) << "angle " << angle;
            ASSERT_NEAR(law.moment().normalized().dot(dir), 1.0, 1e-12);
        }
        law.rotate(2 * step * dir);
        EXPECT_TRUE(law.broken()) << "angle " << angle;
    }

    BendingLaw perAxis(path.k, BendingReading::PerAxis);
    const Vec2 diagonal = Vec2(1, 1).normalized();
    // Just below theta_Elast on each axis: still elastic per axis, whereas |M| is already
    // 1.41 M_Elast, far beyond the isotropic yield.
    const double belowYield = 0.999 * std::sqrt(2.0) * path.thetaElast();
    perAxis.rotate(belowYield * diagonal);
    EXPECT_NEAR(perAxis.moment().norm(), 0.999 * std::sqrt(2.0) * path.k.yieldMoment, tol);
    const double axisTheta = 0.999 * path.thetaElast();
    EXPECT_NEAR(perAxis.storedEnergy(), 2 * 0.5 * path.k.elastic * axisTheta * axisTheta, 1e-9 * perAxis.storedEnergy());
    const double atYield = belowYield;
    perAxis.rotate((std::sqrt(2.0) * path.thetaRupt() - atYield - 1e-6) * diagonal);
    EXPECT_FALSE(perAxis.broken());
    EXPECT_NEAR(perAxis.moment().norm(), std::sqrt(2.0) * (path.k.ruptureMoment - path.k.plastic * 1e-6 / std::sqrt(2.0)),
                1e-6 * path.k.ruptureMoment);
    perAxis.rotate(2e-6 * diagonal);
    EXPECT_TRUE(perAxis.broken());
}

// Isotropic hardening: after yielding one way, reversed bending stays elastic (K_Unld) down to
// minus the largest moment reached, then follows K_Plast again.
TEST(BendingLaw, ReversedBendingYieldsAtTheLargestMomentReached) {
    const TrilinearPath path{beechHinge()};
    const HingeCoefficients& k = path.k;
    BendingLaw law(k, BendingReading::PerAxis);
    const double thetaMax = path.thetaElast() * 1.5;
    const double mMax = path.envelope(thetaMax);
    law.rotate(Vec2(thetaMax, 0));
    const double toReverseYield = 2 * mMax / k.unloading;
    law.rotate(Vec2(-toReverseYield, 0));
    EXPECT_NEAR(law.moment().x(), -mMax, kRel * k.ruptureMoment);
    law.rotate(Vec2(-1e-3, 0));
    EXPECT_NEAR(law.moment().x(), -mMax - k.plastic * 1e-3, kRel * k.ruptureMoment);
}

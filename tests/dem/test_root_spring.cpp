// The root spring of single trees (Eqs. 9-10): elastic with K_Root up to M_a, perfectly plastic at
// M_a, elastic unloading, plastic work M_a times the plastic rotation; the twist held elastically.
#include <gtest/gtest.h>

#include <cmath>

#include "libdem/RootSpring.hpp"

using namespace sylva::dem;

namespace {
// Linear pieces split exactly at M_a: the closed form holds to rounding (1e-9 of M_a).
constexpr double kTol = 1e-9 * 200e3;
}  // namespace

TEST(RootSpring, ElasticThenPerfectlyPlasticThenElasticUnloading) {
    const RootSpringParams p;  // K_Root = 7.5e6 N m/rad, M_a = 200e3 N m (model-notes.md)
    RootSpring root(p, BendingReading::Isotropic);
    const double thetaA = p.yieldMoment / p.stiffness;  // 26.7 mrad
    const int n = 100;
    double theta = 0, dissipated = 0;
    for (int i = 0; i < n; ++i) {  // up to 3 theta_a
        const double d = 3 * thetaA / n;
        dissipated += root.rotate(Eigen::Vector3d(0, d, 0));
        theta += d;
        const double expected = std::min(p.stiffness * theta, p.yieldMoment);
        ASSERT_NEAR(root.moment().y(), expected, kTol) << "theta = " << theta;
        ASSERT_NEAR(root.moment().x(), 0.0, kTol);
    }
    EXPECT_NEAR(dissipated, p.yieldMoment * 2 * thetaA, 1e-9 * p.yieldMoment * thetaA);
    EXPECT_NEAR(root.storedEnergy(), 0.5 * p.yieldMoment * thetaA, 1e-9 * p.yieldMoment * thetaA);

    // Unloading with K_Root through zero (residual rotation 2 theta_a) down to -M_a, then the plateau.
    for (int i = 0; i < n; ++i) {
        const double d = -3 * thetaA / n;
        dissipated += root.rotate(Eigen::Vector3d(0, d, 0));
        theta += d;
        const double expected = std::max(p.yieldMoment - p.stiffness * (3 * thetaA - theta), -p.yieldMoment);
        ASSERT_NEAR(root.moment().y(), expected, kTol) << "theta = " << theta;
    }
    // 2 theta_a elastic swing, then theta_a of reversed plastic rotation.
    EXPECT_NEAR(dissipated, p.yieldMoment * 3 * thetaA, 1e-9 * p.yieldMoment * thetaA);
}

TEST(RootSpring, TwistIsElasticWithKRoot) {
    const RootSpringParams p;
    RootSpring root(p, BendingReading::Isotropic);
    const double twist = 0.2;  // far beyond M_a / K_Root: no limit on the twist
    EXPECT_EQ(root.rotate(Eigen::Vector3d(0, 0, twist)), 0.0);
    EXPECT_NEAR(root.moment().z(), p.stiffness * twist, 1e-9 * p.stiffness * twist);
    EXPECT_NEAR(root.storedEnergy(), 0.5 * p.stiffness * twist * twist, 1e-9 * p.stiffness * twist * twist);
}

// M_Root limited to M_a: on the moment vector (isotropic) or per axis, where a diagonal rotation
// holds sqrt(2) M_a.
TEST(RootSpring, DiagonalLimitDependsOnTheReading) {
    const RootSpringParams p;
    const Eigen::Vector3d diagonal = Eigen::Vector3d(1, 1, 0).normalized() * 0.1;
    RootSpring iso(p, BendingReading::Isotropic), perAxis(p, BendingReading::PerAxis);
    iso.rotate(diagonal);
    perAxis.rotate(diagonal);
    EXPECT_NEAR(iso.moment().head<2>().norm(), p.yieldMoment, kTol);
    EXPECT_NEAR(iso.moment().x(), iso.moment().y(), kTol);
    EXPECT_NEAR(perAxis.moment().head<2>().norm(), std::sqrt(2.0) * p.yieldMoment, kTol);
}

// With a failure rotation the plate lets go: up to it the law is unchanged; there the root has taken
// exactly the work done on it, M_a (theta_f - theta_a / 2) (the elastic triangle plus the plateau),
// booked as dissipated, and from then on it carries no moment, bending or twist, and stores nothing.
TEST(RootSpring, PlateLetsGoAtTheFailureRotation) {
    RootSpringParams p;
    p.failureRotation = 0.2;  // rad, 7.5 theta_a
    RootSpring root(p, BendingReading::Isotropic);
    const double thetaA = p.yieldMoment / p.stiffness;
    const int n = 1000;
    const double d = 0.3 / n;  // past the failure rotation
    double theta = 0, dissipated = 0, work = 0;
    for (int i = 0; i < n; ++i) {
        const double before = root.moment().y();
        dissipated += root.rotate(Eigen::Vector3d(0, d, 0.01 * d));
        theta += d;
        if (!root.failed()) {
            work += 0.5 * (before + root.moment().y()) * d;
            ASSERT_NEAR(root.moment().y(), std::min(p.stiffness * theta, p.yieldMoment), kTol) << "theta = " << theta;
        }
    }
    ASSERT_TRUE(root.failed());
    EXPECT_EQ(root.moment(), Eigen::Vector3d::Zero());
    EXPECT_EQ(root.storedEnergy(), 0.0);
    // Failure is detected at the end of the increment that crosses it: one increment's plateau late.
    const double expected = p.yieldMoment * (p.failureRotation - 0.5 * thetaA);
    EXPECT_NEAR(dissipated, expected + 0.5 * p.stiffness * std::pow(0.01 * p.failureRotation, 2), p.yieldMoment * d);
    EXPECT_NEAR(work, expected, p.yieldMoment * d);
    EXPECT_EQ(root.rotate(Eigen::Vector3d(0, -0.1, 0)), 0.0);  // nothing left to unload
}

// The failure rotation is the foot's tilt. It used to be M_a / K_Root plus the plastic rotation
// summed over every swing, so a foot rocking on the plateau between -2 and +2 degrees let go at a
// "failure rotation" of 5 degrees it never reached, and a plate could not let go below its yield
// rotation (a failure rotation of 1 degree acted at 1.53).
TEST(RootSpring, ThePlateLetsGoWhenTheFootLeansAsFarAsTheFailureRotation) {
    const double degree = std::acos(-1.0) / 180;
    RootSpringParams p;
    p.failureRotation = 5 * degree;
    RootSpring rocking(p, BendingReading::Isotropic);
    const int n = 200;
    const double swing = 2 * degree;  // past M_a / K_Root = 1.53 degrees: the plateau each way
    rocking.rotate(Eigen::Vector3d(0, swing, 0));
    for (int cycle = 0; cycle < 10; ++cycle)
        for (double sign : {-1.0, 1.0})
            for (int i = 0; i < n; ++i) rocking.rotate(Eigen::Vector3d(0, sign * 2 * swing / n, 0));
    EXPECT_FALSE(rocking.failed()) << "20 swings of 4 degrees on the plateau, never beyond 2";
    EXPECT_NEAR(std::abs(rocking.moment().y()), p.yieldMoment, kTol);

    p.failureRotation = 0.999 * degree;  // below the yield rotation: the elastic root lets go there
    RootSpring stiff(p, BendingReading::Isotropic);
    for (int i = 0; i < n && !stiff.failed(); ++i) {
        stiff.rotate(Eigen::Vector3d(0, degree / n, 0));
        EXPECT_EQ(stiff.failed(), i == n - 1) << i;
    }
}

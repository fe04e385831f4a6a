// The stem's stable time step (Stem::stableTimeStep, Irons' element-by-element bound). Against the
// whole stem's highest frequency, from the eigenvalues of its stiffness differentiated numerically
// (an independent reference: the connections' forces themselves, not the closed forms the bound
// uses): never above it, and within a few per cent for wood's loss factor, whose axial dashpot is
// the only damping on the stem's fastest mode. Then in time: every mode excited (random node
// velocities), stepping at the bound keeps the energy bounded, while just above it blows up.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdio>

#include "StemEnergyGrowth.hpp"
#include "libdem/RotationVector.hpp"
#include "libdem/Stem.hpp"
#include "libdem/StemParameterSet.hpp"

using namespace sylva::dem;

namespace {

// How much the stem's energy grew over `steps` steps at `factor` times its bound (StemEnergyGrowth.hpp).
double energyGrowth(const StemParams& p, double factor, StemFoot foot, int steps) {
    return sylva::dem::testing::stemEnergyGrowth(Stem(beechStem(20), p, Vec3::Zero(), foot),
                                                 [factor](int, double bound) { return factor * bound; }, steps, 3);
}

StemParams viscous(double tau) {
    StemParams p;
    p.bending.tau = tau;
    return p;
}

StemParams calibrated() { return stemParameters(StemParameterSet::Calibrated); }

// The calibrated stems without their foot zone.
StemParams uniform() {
    StemParams p = calibrated();
    p.footZone = 0;
    return p;
}

// ... and with wood's own axial stiffness (stem.axial_softening = 1), whose axial element is then the
// stem's fastest mode.
StemParams woodAxial() {
    StemParams p = uniform();
    p.axialSoftening = 1;
    return p;
}

// Undamped stable limit 2 / omega_max of the whole stem at rest: the stiffness of its connections
// and root spring by central differences of updateConnections (translations, and small turns applied
// on the left as the stepper turns nodes), against its lumped masses and inertias.
double wholeStemLimit(const Stem& rest) {
    const std::size_t n = rest.nodeCount();
    const auto forces = [&](const Stem& s) {
        Stem copy = s;  // updateConnections advances the laws' history
        std::vector<Vec3> f(n, Vec3::Zero()), t(n, Vec3::Zero());
        copy.updateConnections(f, t, 1e-6);
        Eigen::VectorXd out(6 * n);
        for (std::size_t i = 0; i < n; ++i) out.segment<3>(6 * i) = f[i], out.segment<3>(6 * i + 3) = t[i];
        return out;
    };
    std::vector<int> free;
    std::vector<double> inertia;
    for (std::size_t i = 0; i < n; ++i)
        for (int d = 0; d < 6; ++d)
            if (d < 3 ? rest.translates(i) : rest.rotates(i)) {
                free.push_back(static_cast<int>(6 * i + d));
                inertia.push_back(d < 3 ? rest.mass()[i] : rest.inertia()[i]);
            }
    const int m = static_cast<int>(free.size());
    Eigen::MatrixXd k(m, m);
    const double h = 1e-7;  // m or rad: the springs are linear to 1e-9 relative over it
    for (int col = 0; col < m; ++col) {
        Stem plus = rest, minus = rest;
        const std::size_t i = static_cast<std::size_t>(free[col] / 6);
        const int d = free[col] % 6;
        if (d < 3) {
            plus.position[i][d] += h;
            minus.position[i][d] -= h;
        } else {
            Vec3 turn = Vec3::Zero();
            turn[d - 3] = h;
            plus.orientation[i] = fromRotationVector(turn) * plus.orientation[i];
            minus.orientation[i] = fromRotationVector(-turn) * minus.orientation[i];
        }
        const Eigen::VectorXd df = (forces(plus) - forces(minus)) / (2 * h);
        for (int row = 0; row < m; ++row) k(row, col) = -df[free[row]] / std::sqrt(inertia[row] * inertia[col]);
    }
    const Eigen::MatrixXd symmetric = 0.5 * (k + k.transpose());
    const double largest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(symmetric, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
    return 2 / std::sqrt(largest);
}

}  // namespace

// The calibrated stems, uniform, with wood's axial stiffness: the axial wave, l sqrt(rho / MOE), sets
// the limit, which the axial element gives exactly for a uniform chain; a tapered stem's neighbouring
// nodes differ a little, and wood's loss factor takes 1-2 % more (its axial dashpot, a damping ratio
// of eta / 2 = 1 % at the top of the axial band, and the bending branches' added stiffness): within
// 5 %, and never above. With the softened axial springs (stem.axial_softening) the axial wave is
// slower, and where the bending or the root's element sets the step instead (the thicker stems, the
// finer spacing) the bound is as loose as the hinge's: measured 0.86-0.99, never above; the default,
// foot-zoned stems alike (0.86-0.99: Irons' split by the wood is not exact where the connections
// change length).
// The paper's hinge (one section), undamped: its shear spring, in series with nothing, makes a beam
// element stiffer than the chain's modes use, within 20 %. With Eqs. 7-8's dashpot, which the
// reference leaves out, the bound is lower still.
TEST(StemTimeStep, BoundNeverExceedsTheWholeStemsLimitAndIsWithinTwentyPerCentOfIt) {
    for (const double dbh : {10.0, 20.0, 35.0})
        for (const double spacing : {0.5, 0.25})
            for (const StemFoot foot : {StemFoot::Clamped, StemFoot::RootSpring}) {
                StemParams wood = woodAxial(), p = uniform(), zone = calibrated(), hinge = viscous(0), paper = viscous(5e-4);
                wood.nodeSpacing = p.nodeSpacing = zone.nodeSpacing = hinge.nodeSpacing = paper.nodeSpacing = spacing;
                Stem woodStem(beechStem(dbh), wood, Vec3::Zero(), foot), stem(beechStem(dbh), p, Vec3::Zero(), foot);
                woodStem.carryOwnWeight(9.81);
                stem.carryOwnWeight(9.81);
                const Stem hingeStem(beechStem(dbh), hinge, Vec3::Zero(), foot);
                const double woodLimit = wholeStemLimit(woodStem), woodBound = woodStem.stableTimeStep();
                const double limit = wholeStemLimit(stem), bound = stem.stableTimeStep();
                const double hingeLimit = wholeStemLimit(hingeStem), hingeBound = hingeStem.stableTimeStep();
                const double paperBound = Stem(beechStem(dbh), paper, Vec3::Zero(), foot).stableTimeStep();
                // The default's foot zone, its scaled springs and inertia, and Irons' split by the wood where
                // its connections change length: still a bound.
                ASSERT_EQ(zone.footZone, 1.0);
                Stem zoned(beechStem(dbh), zone, Vec3::Zero(), foot);
                zoned.carryOwnWeight(9.81);
                const double zoneLimit = wholeStemLimit(zoned), zoneBound = zoned.stableTimeStep();
                std::printf("  %2.0f cm, %.2f m, %s: foot zone %.3e s of %.3e (%.3f)\n", dbh, spacing,
                            foot == StemFoot::Clamped ? "clamped" : "root   ", zoneBound, zoneLimit, zoneBound / zoneLimit);
                EXPECT_LE(zoneBound, zoneLimit * (1 + 1e-6));
                EXPECT_GT(zoneBound, 0.8 * zoneLimit);
                std::printf("  %2.0f cm, %.2f m, %s: wood's axial %.3e s of %.3e (%.3f); uniform %.3e s of %.3e (%.3f); "
                            "hinge %.3e of %.3e (%.3f); Eqs. 7-8 %.3e (%.3f)\n", dbh, spacing,
                            foot == StemFoot::Clamped ? "clamped" : "root   ", woodBound, woodLimit, woodBound / woodLimit,
                            bound, limit, bound / limit, hingeBound, hingeLimit, hingeBound / hingeLimit, paperBound,
                            paperBound / hingeLimit);
                EXPECT_LE(woodBound, woodLimit * (1 + 1e-6));
                EXPECT_GT(woodBound, 0.95 * woodLimit);
                EXPECT_LE(bound, limit * (1 + 1e-6));
                EXPECT_GT(bound, 0.8 * limit);
                EXPECT_GE(bound, woodBound);  // softer springs, a longer step
                EXPECT_LE(hingeBound, hingeLimit * (1 + 1e-6));
                EXPECT_GT(hingeBound, 0.8 * hingeLimit);
                EXPECT_LE(paperBound, hingeBound);
            }
}

// Every mode excited: at the bound nothing grows; 10 % above the uniform calibrated stems' bound
// (within 5 % of their limit, above, for this 20 cm stem at 0.5 m, whose axial element sets its step
// with wood's axial springs and with the softened ones), 20 % above the default's foot-zoned one (0.86-
// 0.99 of its limit, above; 0.915 for this stem on its root spring) and 30 % above the hinge's (within
// 20 %) some mode is past its limit and blows up. Eqs. 7-8's bound takes the largest damping rate and the highest frequency as if one mode
// had both, which leaves more margin: only 3.5 times it must blow up.
TEST(StemTimeStep, StableAtTheBoundAndUnstableJustAboveIt) {
    for (const StemFoot foot : {StemFoot::Clamped, StemFoot::RootSpring}) {
        const int f = static_cast<int>(foot);
        EXPECT_LT(energyGrowth(uniform(), 1.0, foot, 20000), 1.5) << "uniform, foot " << f;
        EXPECT_GT(energyGrowth(uniform(), 1.1, foot, 20000), 100.0) << "uniform, foot " << f;
        EXPECT_LT(energyGrowth(calibrated(), 1.0, foot, 20000), 1.5) << "foot zone, foot " << f;
        EXPECT_GT(energyGrowth(calibrated(), 1.2, foot, 20000), 100.0) << "foot zone, foot " << f;
        EXPECT_LT(energyGrowth(woodAxial(), 1.0, foot, 20000), 1.5) << "wood's axial springs, foot " << f;
        EXPECT_GT(energyGrowth(woodAxial(), 1.1, foot, 20000), 100.0) << "wood's axial springs, foot " << f;
        EXPECT_LT(energyGrowth(viscous(0), 1.0, foot, 20000), 1.5) << "undamped hinge, foot " << f;
        EXPECT_GT(energyGrowth(viscous(0), 1.3, foot, 20000), 100.0) << "undamped hinge, foot " << f;
        EXPECT_LT(energyGrowth(viscous(5e-4), 1.0, foot, 20000), 1.5) << "Eqs. 7-8, foot " << f;
        EXPECT_GT(energyGrowth(viscous(5e-4), 3.5, foot, 20000), 100.0) << "Eqs. 7-8, foot " << f;
    }
}

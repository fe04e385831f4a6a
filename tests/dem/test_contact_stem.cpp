// Block/stem and stem/stem contacts (Eqs. 20-23) and the segment geometry they use.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "libdem/SegmentGeometry.hpp"
#include "libdem/StemContact.hpp"

using namespace sylva::dem;

TEST(ContactStem, NormalStiffnessFollowsEqs22And23) {
    const StemContactParams p;  // Table 2: E_r = 1.5e3 MPa, E_b = 80e3 MPa
    ContactGeometry g;
    g.radiusA = 0.1985;  // a block sphere of the 0.5 m^3 cube
    g.radiusB = 0.1;     // a 20 cm connection
    // Eq. 22 by hand: 2 * 1.5e9 * 0.1 * 80e9 * 0.1985 / (80e9 * 0.1985 + 1.5e9 * 0.1)
    EXPECT_NEAR(BlockStemContact(p).normalStiffness(g), 4.764e18 / (1.588e10 + 1.5e8), 1e3);
    g.radiusA = 0.05;
    // Eq. 23: 2 * 1.5e9 * 0.05 * 0.1 / 0.15 = 1e8 N/m
    EXPECT_NEAR(StemStemContact(p).normalStiffness(g), 1e8, 1e-3);
}

TEST(ContactStem, ElasticNormalForceStoresAndReturnsItsWork) {
    const BlockStemContact law{StemContactParams{}};
    ContactGeometry g;
    g.radiusA = 0.2;
    g.radiusB = 0.1;
    g.normal = Vec3::UnitX();
    ContactHistory h;
    DissipationLedger ledger;
    const double k = law.normalStiffness(g);
    g.overlap = 2e-3;
    const Vec3 f = law.force(g, h, 1e-5, ledger);
    EXPECT_NEAR(f.x(), k * 2e-3, 1e-6 * k * 2e-3);  // Eq. 20: no dashpot
    EXPECT_NEAR(law.storedEnergy(g, h), 0.5 * k * 4e-6, 1e-9 * k);
    EXPECT_EQ(ledger.contactDamping, 0.0);
}

// Crushing (tree_contact.crushing_strength_pa): a 100 kg mass driven head-on into the stem at 2 m/s
// along the normal, integrated by leapfrog at 1e-6 s, against the closed forms of a linear loading
// envelope k_c and elastic unloading K (Walton & Braun 1986): deepest overlap v0 sqrt(m / k_c),
// rebound speed v0 sqrt(k_c / K), crushing work the kinetic energy lost, a dent U_max (1 - k_c / K)
// left. 1e-3: the leapfrog's error at ~1500 steps per contact.
TEST(ContactStem, CrushingLoadsOnTheEnvelopeAndUnloadsElastically) {
    StemContactParams p;
    p.crushingStrength = 3.7e6;
    const BlockStemContact law(p);
    ContactGeometry g;
    g.radiusA = 0.2;
    g.radiusB = 0.1;
    g.normal = -Vec3::UnitX();  // force on the block A along -x: it moves along +x into the stem
    const double k = law.normalStiffness(g), kc = law.crushingStiffness(g);
    ASSERT_NEAR(kc, 2 * M_PI * 3.7e6 * std::sqrt(0.02), 1e-6 * kc);
    ASSERT_LT(kc, 0.1 * k);
    const double m = 100, v0 = 2, dt = 1e-6;
    ContactHistory h;
    DissipationLedger ledger;
    double x = 0, v = v0, deepest = 0;
    for (int i = 0; i < 10000000 && x >= 0; ++i) {
        g.overlap = x;
        g.relativeVelocity = Vec3(v, 0, 0);
        const Vec3 f = x > 0 ? law.force(g, h, dt, ledger) : Vec3::Zero();
        v += f.x() / m * dt;
        x += v * dt;
        deepest = std::max(deepest, x);
        if (x <= h.plasticOverlap && v < 0) break;  // left the dent: contact over
    }
    EXPECT_NEAR(deepest, v0 * std::sqrt(m / kc), 1e-3 * deepest);
    EXPECT_NEAR(-v, v0 * std::sqrt(kc / k), 1e-3 * v0 * std::sqrt(kc / k));
    EXPECT_NEAR(ledger.crushing, 0.5 * m * (v0 * v0 - v * v), 1e-3 * 0.5 * m * v0 * v0);
    EXPECT_NEAR(h.plasticOverlap, deepest * (1 - kc / k), 1e-3 * deepest);
    // Without a crushing strength the contact is Eq. 20's elastic spring: nothing is crushed.
    EXPECT_FALSE(BlockStemContact(StemContactParams{}).crushingStiffness(g) < k);
}

TEST(ContactStem, StemsSlideOnEachOtherWithoutFriction) {
    const StemStemContact law{StemContactParams{}};  // phi^t-t = 0
    ContactGeometry g;
    g.radiusA = g.radiusB = 0.1;
    g.normal = Vec3::UnitX();
    g.overlap = 1e-3;
    g.relativeVelocity = Vec3(0, 1, 0);
    ContactHistory h;
    DissipationLedger ledger;
    for (int i = 0; i < 10; ++i) EXPECT_NEAR(law.force(g, h, 1e-4, ledger).y(), 0.0, 1e-12);
}

TEST(SegmentGeometry, ClosestPointsMatchABruteForceSearch) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    auto rnd = [&] { return Vec3(u(rng), u(rng), u(rng)); };
    for (int trial = 0; trial < 200; ++trial) {
        const Vec3 a0 = rnd(), a1 = rnd(), b0 = rnd(), b1 = trial % 5 == 0 ? b0 + 0.5 * (a1 - a0) : rnd();  // some parallel pairs
        const auto [s, t] = closestBetweenSegments(a0, a1, b0, b1);
        const double got = (a0 + s * (a1 - a0) - b0 - t * (b1 - b0)).norm();
        double best = 1e9;
        for (int i = 0; i <= 200; ++i)
            for (int j = 0; j <= 200; ++j)
                best = std::min(best, (a0 + i / 200.0 * (a1 - a0) - b0 - j / 200.0 * (b1 - b0)).norm());
        // The grid search is within half a grid cell (0.005 of a segment <= 2 * sqrt(3)) of the optimum.
        EXPECT_LE(got, best + 1e-12);
        EXPECT_GE(got, best - 0.02);
        const Vec3 p = rnd();
        const double tp = closestOnSegment(p, a0, a1);
        for (int i = 0; i <= 100; ++i) EXPECT_LE((a0 + tp * (a1 - a0) - p).norm(), (a0 + i / 100.0 * (a1 - a0) - p).norm() + 1e-12);
    }
}

// Block/stem and stem/stem contacts (Eqs. 20-23), the segment geometry they use and the stem/stem
// narrow phase.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <vector>

#include "libdem/ConnectionTouch.hpp"
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

namespace {

struct FoundTouch {
    std::size_t ca, cb;
    ConnectionTouch touch;
};

// B planted at `footB`; A at the origin, where it stands. A stem lying across A was planted 10 m
// away unless said otherwise: no stool's stump.
std::vector<FoundTouch> allTouches(const Stem& A, const Stem& B, const Vec3& footB = Vec3(10, 0, 0)) {
    const Vec3 footA = Vec3::Zero();
    std::vector<FoundTouch> out;
    for (std::size_t ca = 0; ca < A.connectionCount(); ++ca)
        for (std::size_t cb = 0; cb < B.connectionCount(); ++cb) {
            if (fusedAtRest({A, footA}, ca, {B, footB}, cb)) continue;  // ignored, as ForestMotion does
            if (const auto t = touchConnections({A, footA}, ca, {B, footB}, cb)) out.push_back({ca, cb, *t});
        }
    return out;
}

// A 10 cm stem lying along y at height z with its connection `middle` centred on y = 0, x = x.
Stem lyingAcross(double x, double z, std::size_t middle) {
    Stem B(beechStem(10), StemParams{}, Vec3::Zero(), StemFoot::Clamped);
    for (std::size_t i = 0; i < B.nodeCount(); ++i)
        B.position[i] = Vec3(x, B.restHeight(i) - 0.5 * (B.restHeight(middle) + B.restHeight(middle + 1)), z);
    return B;
}

}  // namespace

// A node of one stem pressed against another stem is one contact, not one per connection that
// holds it: both connections find it, at their ends, and counted twice it pushed twice as hard.
TEST(ConnectionTouch, ANodeAgainstAStemTouchesItOnce) {
    Stem A(beechStem(20), StemParams{}, Vec3::Zero(), StemFoot::Clamped);
    const std::size_t k = 4;  // 2 m up: bent 5 cm towards the lying stem, both its connections end nearest there
    A.position[k].x() += 0.05;
    const double overlap = 0.004;
    const double rA = 0.5 * A.connectionDiameter(k - 1);
    const Stem B0 = lyingAcross(0, 0, 3);
    const double rBmid = 0.5 * B0.connectionDiameter(3);
    const Stem B = lyingAcross(A.position[k].x() + rA + rBmid - overlap, A.position[k].z(), 3);
    const auto found = allTouches(A, B);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].ca, k - 1);  // the thicker connection below the node owns it
    EXPECT_EQ(found[0].cb, 3u);
    EXPECT_DOUBLE_EQ(found[0].touch.s, 1.0);
    EXPECT_NEAR(found[0].touch.geometry.overlap, overlap, 1e-12);
    EXPECT_NEAR(found[0].touch.geometry.normal.x(), -1.0, 1e-12);  // from B to A

    // A node of the lying stem against the standing one: the same from B's side.
    Stem C(beechStem(10), StemParams{}, Vec3::Zero(), StemFoot::Clamped);
    const std::size_t j = 3;
    const double rC = 0.5 * C.connectionDiameter(j - 1), zA = 0.5 * (A.restHeight(1) + A.restHeight(2));
    const double rAmid = 0.5 * A.connectionDiameter(1);
    A.position[k].x() -= 0.05;  // straight again
    for (std::size_t i = 0; i < C.nodeCount(); ++i)
        C.position[i] = Vec3(rAmid + rC - overlap + 0.02, C.restHeight(i) - C.restHeight(j), zA);
    C.position[j].x() -= 0.02;  // bent towards A at node j, into it by `overlap`; 16 mm clear elsewhere
    const auto fromB = allTouches(A, C);
    ASSERT_EQ(fromB.size(), 1u);
    EXPECT_EQ(fromB[0].ca, 1u);
    EXPECT_EQ(fromB[0].cb, j - 1);
    EXPECT_DOUBLE_EQ(fromB[0].touch.t, 1.0);
    EXPECT_NEAR(fromB[0].touch.geometry.overlap, overlap, 1e-12);
}

// A stool's other stem, broken and lying across this one at a node (both planted at the same foot):
// the connection below the node is fused with it at rest and takes no touch, so the connection above
// keeps the node's. Handed down, the push was lost.
TEST(ConnectionTouch, ANodeAboveAFusedStumpKeepsItsTouch) {
    Stem A(beechStem(20), StemParams{}, Vec3::Zero(), StemFoot::Clamped);
    const std::size_t k = 4;
    A.position[k].x() += 0.05;  // bent towards the lying stem
    const Stem B0 = lyingAcross(0, 0, 0);
    // B's highest connection that ends below node k: level with A's connection below k, not above it.
    std::size_t cb = 0;
    while (B0.restHeight(cb + 2) < A.restHeight(k) - 1e-3) ++cb;
    const Vec3 foot = Vec3::Zero();
    ASSERT_TRUE(fusedAtRest({A, foot}, k - 1, {B0, foot}, cb));
    ASSERT_FALSE(fusedAtRest({A, foot}, k, {B0, foot}, cb));
    const double overlap = 0.004, rA = 0.5 * A.connectionDiameter(k), rB = 0.5 * B0.connectionDiameter(cb);
    const Stem B = lyingAcross(A.position[k].x() + rA + rB - overlap, A.position[k].z(), cb);
    const auto found = allTouches(A, B, foot);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].ca, k);
    EXPECT_EQ(found[0].cb, cb);
    EXPECT_DOUBLE_EQ(found[0].touch.s, 0.0);
    EXPECT_NEAR(found[0].touch.geometry.overlap, overlap, 1e-12);
}

// Touches away from the nodes are all found: a connection's lower node is only given up to an intact
// connection below it.
TEST(ConnectionTouch, ATouchInsideAConnectionOrAtTheFootIsKept) {
    const Stem A(beechStem(20), StemParams{}, Vec3::Zero(), StemFoot::Clamped);
    const double overlap = 0.003, rA = 0.5 * A.connectionDiameter(2);
    const Stem B0 = lyingAcross(0, 0, 2);
    const Stem B = lyingAcross(rA + 0.5 * B0.connectionDiameter(2) - overlap, 0.5 * (A.restHeight(2) + A.restHeight(3)), 2);
    const auto found = allTouches(A, B);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].ca, 2u);
    EXPECT_NEAR(found[0].touch.s, 0.5, 1e-9);
    EXPECT_NEAR(found[0].touch.geometry.overlap, overlap, 1e-12);
    // At the foot there is no connection below: the first one keeps its lower node.
    const Stem atFoot = lyingAcross(0.5 * A.connectionDiameter(0) + 0.5 * B0.connectionDiameter(2) - overlap, 0, 2);
    const auto foot = allTouches(A, atFoot);
    ASSERT_EQ(foot.size(), 1u);
    EXPECT_EQ(foot[0].ca, 0u);
    EXPECT_DOUBLE_EQ(foot[0].touch.s, 0.0);
}

// Above a break the node is the lowest of its piece: the connection above it keeps its touch.
TEST(ConnectionTouch, ATouchAboveABreakIsKept) {
    Stem A(beechStem(20), StemParams{}, Vec3::Zero(), StemFoot::Clamped);
    const std::size_t k = 4;
    // The stem folded at connection k - 1 (past the angle at which a connection is broken whatever
    // its law), the piece above turned as one body so that no other connection bends.
    for (std::size_t i = k; i < A.nodeCount(); ++i) A.orientation[i] = Quat(Eigen::AngleAxisd(2.0, Vec3::UnitY()));
    std::vector<Vec3> force(A.nodeCount(), Vec3::Zero()), torque(A.nodeCount(), Vec3::Zero());
    A.updateConnections(force, torque, 1e-5);
    ASSERT_TRUE(A.broken(k - 1));
    for (std::size_t c = 0; c < A.connectionCount(); ++c) {
        if (c != k - 1) {
            ASSERT_FALSE(A.broken(c)) << c;
        }
    }
    const double overlap = 0.004, rA = 0.5 * A.connectionDiameter(k);
    const Stem B0 = lyingAcross(0, 0, 3);
    const Stem B = lyingAcross(rA + 0.5 * B0.connectionDiameter(3) - overlap, A.restHeight(k), 3);
    const auto found = allTouches(A, B);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].ca, k);
    EXPECT_DOUBLE_EQ(found[0].touch.s, 0.0);
    EXPECT_NEAR(found[0].touch.geometry.overlap, overlap, 1e-12);
}

// A fracture energy G_f (ConnectionFracture): once a connection has reached M_Rupt, breaking it costs
// G_f per m^2 of its section whatever its length, the crack band's promise; and the energy balance
// of the softening closes (docs/model-stems.md, "A fracture energy").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "libdem/ConnectionFracture.hpp"
#include "libdem/Stem.hpp"

using namespace sylva::dem;

namespace {

const double kPi = std::acos(-1.0);

struct Softening {
    double total = 0;       // work put into the stem until its foot connection broke, J
    double afterRupture = 0;  // of it, from the step M_Rupt was reached, J
    double booked = 0;      // dissipated less created, as the stem's ledger has it, J
    double section = 0;     // A of the connection's section, m^2
    double length = 0;      // l, m
    bool turnedBack = false;  // the stem was turned back past rupture, as asked
};

// The foot connection of a clamped 20 cm beech bent alone, quasi-statically, by turning the stem above
// it rigidly about y: node 1 at R(alpha / 2) (0, 0, l) and every node above it turned by alpha keeps
// the connection's chord on its middle frame (no shear, no stretch) and every other connection as
// built. The work is the trapezoid of the nodes' forces and torques over the imposed motion, computed
// from the forces, not from the ledger. Past rupture by `reverseAfter` (rad), the stem is turned back.
Softening bendFootConnection(double spacing, double fractureEnergy,
                             double reverseAfter = std::numeric_limits<double>::infinity(), int sections = 1) {
    StemParams p;
    p.nodeSpacing = spacing;
    p.bending.sections = sections;  // 1: M_Rupt at the connection's own D_con, exactly
    p.bending.fractureEnergy = fractureEnergy;
    Stem stem(beechStem(20), p, Vec3::Zero(), StemFoot::Clamped);
    const std::vector<Vec3> rest = stem.position;
    const std::size_t n = stem.nodeCount();
    const auto pose = [&](double alpha) {
        const Quat turn(Eigen::AngleAxisd(alpha, Vec3::UnitY()));
        const Vec3 second = Quat(Eigen::AngleAxisd(0.5 * alpha, Vec3::UnitY())) * rest[1];
        for (std::size_t j = 1; j < n; ++j) {
            stem.position[j] = second + turn * (rest[j] - rest[1]);
            stem.orientation[j] = turn;
        }
    };
    Softening s;
    std::vector<Vec3> force(n, Vec3::Zero()), torque(n, Vec3::Zero());
    const double dt = 1;  // the nodes stand still: no viscous moment, no axial dashpot
    stem.updateConnections(force, torque, dt);

    s.length = stem.connectionLength(0);
    s.section = kPi * std::pow(stem.connectionDiameter(0), 2) / 4;
    // 4 000 increments over the softening's theta_f at 5e4 J/m^2 (0.04 rad here): the trapezoid's and
    // the damage's lag of one increment are then below 1e-3 of the work.
    double dAlpha = 16 * 5e4 / (p.bending.sigmaRupt * stem.connectionDiameter(0)) / 4000;
    double alpha = 0, alphaAtRupture = 0;
    while (!stem.broken(0) && std::abs(alpha) < 1) {
        const std::vector<Vec3> position = stem.position, f0 = force, t0 = torque;
        const bool ruptured = stem.bending(0).ruptureReached();
        if (ruptured && dAlpha > 0 && alpha - alphaAtRupture > reverseAfter) {
            dAlpha = -dAlpha;
            s.turnedBack = true;
        }
        alpha += dAlpha;
        pose(alpha);
        for (std::size_t j = 0; j < n; ++j) force[j].setZero(), torque[j].setZero();
        stem.updateConnections(force, torque, dt);
        double work = 0;  // by whoever turns the stem, against the connections' forces on the nodes
        for (std::size_t j = 1; j < n; ++j)
            work -= 0.5 * (f0[j] + force[j]).dot(stem.position[j] - position[j]) +
                    0.5 * (t0[j] + torque[j]).dot(dAlpha * Vec3::UnitY());
        s.total += work;
        if (ruptured || stem.bending(0).ruptureReached()) s.afterRupture += work;
        if (!ruptured) alphaAtRupture = alpha;
    }
    EXPECT_TRUE(stem.broken(0)) << "not broken at " << alpha << " rad";
    for (std::size_t c = 1; c < stem.connectionCount(); ++c) EXPECT_FALSE(stem.broken(c)) << "connection " << c;
    const StemLedger& l = stem.ledger;
    s.booked = l.bendingPlasticity + l.bendingDamping + l.axialDamping + l.rupture - l.unloadingGain + stem.elasticEnergy();
    return s;
}

// At 0.5 and 0.25 m, 5e4 J/m^2: the work from M_Rupt to broken is G_f A within `tolerance` (relative),
// and all the work put in is booked (continuum damage's balance: nothing stored once broken).
void expectBreakingCostsGfA(const char* how, double tolerance, double reverseAfter, int sections) {
    const double gf = 5e4;
    for (const double spacing : {0.5, 0.25}) {
        const Softening s = bendFootConnection(spacing, gf, reverseAfter, sections);
        std::printf("  l = %.3f m, %s: %.1f J from M_Rupt to broken, G_f A = %.1f J; %.1f J in all, %.1f J booked\n",
                    s.length, how, s.afterRupture, gf * s.section, s.total, s.booked);
        EXPECT_EQ(s.turnedBack, std::isfinite(reverseAfter)) << "l = " << s.length;
        EXPECT_NEAR(s.afterRupture, gf * s.section, tolerance * gf * s.section) << "l = " << s.length;
        EXPECT_NEAR(s.booked, s.total, 2e-3 * s.total) << "l = " << s.length;
    }
}

const double kNever = std::numeric_limits<double>::infinity();

}  // namespace

// 1 %: the increments' lag (1e-3, above) and the step that reaches M_Rupt, which hardens on past it by
// its own flow (ConnectionBeam), a few 1e-3 of the softening at these increments.
TEST(StemFracture, BreakingAConnectionCostsItsSectionsFractureEnergyWhateverItsLength) {
    expectBreakingCostsGfA("one way", 0.01, kNever, 1);
}

// A whipped stem bends one way, then the other: the crack opened with |theta| past its value at
// rupture, and a hinge turned back flowed at -M_Rupt unopened, taking 11.9 kJ against G_f A = 1.8 kJ.
// Turned back, the hinge unloads and reloads elastically to -M_Rupt, storing and returning the same
// (1 - d) psi0: the one-way tolerance.
TEST(StemFracture, ACrackBentBackCostsNoMoreThanOneBentOneWay) {
    const double thetaF = 16 * 5e4 / (94e6 * 0.2);  // about: the foot's D_con is near the DBH
    expectBreakingCostsGfA("bent back", 0.01, 0.25 * thetaF, 1);
}

// With three sections (the calibrated set's) one end reaches M_Rupt first while the others still
// harden: their work opens the crack too, and the intact moment, hence psi0, still grows a little
// after rupture, released at the break. That costs more than G_f A: 2.3 % at 0.5 m, 0.5 % at 0.25 m
// (a measured residual of the law, docs/model-stems.md), so 3 % here; a doubling would fail.
TEST(StemFracture, WithThreeSectionsTheCostStaysNearGfA) {
    expectBreakingCostsGfA("3 sections", 0.03, kNever, 3);
}

// Eq. 6 as the paper has it: nothing more to pay once M_Rupt is reached, whatever the length.
TEST(StemFracture, WithoutAFractureEnergyTheConnectionBreaksAtOnce) {
    for (const double spacing : {0.5, 0.25}) {
        const Softening s = bendFootConnection(spacing, 0);
        EXPECT_NEAR(s.afterRupture, 0, 1e-3 * s.total) << "l = " << s.length;
        EXPECT_NEAR(s.booked, s.total, 2e-3 * s.total) << "l = " << s.length;
    }
}

TEST(ConnectionFracture, TheHingeOpensItLinearlyOverThetaF) {
    const double gf = 2e4, sigma = 94e6, d = 0.2;
    ConnectionFracture f(gf, d);
    const double thetaF = 16 * gf / (sigma * d);  // 2 G_f A / M_Rupt, A = pi d^2 / 4, M_Rupt = sigma pi d^3 / 32
    const double mRupt = sigma * kPi * d * d * d / 32, opening = mRupt * thetaF;  // the plastic work that opens it
    EXPECT_NEAR(f.openingWork(), opening, 1e-12 * opening);
    EXPECT_FALSE(f.started());
    const double psi0 = 800;  // J stored by the intact springs
    // The step that reaches M_Rupt: its flow, partly below M_Rupt, is Eq. 6's hardening, not the crack's.
    EXPECT_DOUBLE_EQ(f.advance(0.3 * opening, Vec2::Zero(), psi0), 0);
    EXPECT_TRUE(f.started());
    EXPECT_DOUBLE_EQ(f.carried(), 1);
    EXPECT_NEAR(f.advance(0.25 * opening, Vec2::Zero(), psi0), 0.25 * psi0, 1e-9 * psi0);
    EXPECT_NEAR(f.carried(), 0.75, 1e-12);
    // Unloading is elastic: a crack that closes does not heal, nor release anything.
    EXPECT_DOUBLE_EQ(f.advance(0, Vec2::Zero(), psi0), 0);
    EXPECT_NEAR(f.carried(), 0.75, 1e-12);
    EXPECT_NEAR(f.advance(2 * opening, Vec2::Zero(), psi0), 0.75 * psi0, 1e-9 * psi0);
    EXPECT_TRUE(f.through());
    EXPECT_DOUBLE_EQ(f.carried(), 0);
}

// The shear softens with the bending: faces slid apart by half the section let go, whatever the
// hinge's rotation (without it a node slid 2.2 m along a half-broken connection and the run stopped).
TEST(ConnectionFracture, FacesSlidApartByHalfTheSectionLetGo) {
    const double d = 0.2;
    ConnectionFracture f(5e4, d);
    const Vec2 atRupture(0.01, -0.02);
    f.advance(0, atRupture, 100);
    f.advance(0, atRupture + Vec2(0.49 * d, 0), 100);
    EXPECT_FALSE(f.through());
    EXPECT_DOUBLE_EQ(f.carried(), 1);
    EXPECT_DOUBLE_EQ(f.advance(0, atRupture + Vec2(0, 0.51 * d), 100), 100);
    EXPECT_TRUE(f.through());
}

TEST(ConnectionFracture, WithoutAFractureEnergyItNeverSoftens) {
    const ConnectionFracture f;
    EXPECT_FALSE(f.started());
    EXPECT_DOUBLE_EQ(f.carried(), 1);
    EXPECT_FALSE(f.through());
}

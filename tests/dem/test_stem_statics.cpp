// A clamped conical stem under a small tip load, relaxed to rest, against beam theory for the
// truncated cone: w'' = P (L - z) / (E I(z)) integrated twice on a fine grid (plus the shear
// strain P / (G A(z)) of the model's shear springs), an independent computation. The node
// spacing is refined to show second-order convergence. The same on the root spring adds the rigid
// rotation P L / K_Root.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "libdem/Stem.hpp"
#include "libdem/StemStepper.hpp"

using namespace sylva::dem;

namespace {

const double kPi = std::acos(-1.0);

// A 20 cm beech truncated at 4 cm: a tip load on a cone tapering to (nearly) nothing would bend
// its last centimetres without bound (M ~ (L - z), E I ~ (L - z)^4). No viscosity: the viscous
// moment vanishes at rest, and without it the stable step is 2-5 times longer.
StemParams params(double spacing) {
    StemParams p;
    p.nodeSpacing = spacing;
    p.tipDiameter = 0.04;
    p.bending.tau = 0;
    return p;
}

// Beam-theory deflection at heights zs of a clamped truncated cone (diameter through dbh at 1.3 m
// and tip at L) under a tip load P: slope and deflection by the trapezoid rule on 2e5 intervals
// (error ~1e-9 relative), plus the shear deflection int P / (G A).
std::vector<double> beamDeflection(double dbh, double tip, double length, const StemParams& p, double load,
                                   const std::vector<double>& zs) {
    const double e = p.bending.moe, g = e / (2 * (1 + p.poisson));
    const auto diameter = [&](double z) { return tip + (dbh - tip) * (length - z) / (length - 1.3); };
    const auto curvature = [&](double z) { return load * (length - z) / (e * kPi * std::pow(diameter(z), 4) / 64); };
    const auto shearStrain = [&](double z) { return load / (g * kPi * diameter(z) * diameter(z) / 4); };
    const int n = 200000;
    const double h = length / n;
    std::vector<double> w(n + 1, 0.0);
    double slope = 0;
    for (int i = 1; i <= n; ++i) {
        const double z0 = (i - 1) * h, z1 = i * h;
        const double slopeBefore = slope;
        slope += 0.5 * h * (curvature(z0) + curvature(z1));
        w[i] = w[i - 1] + 0.5 * h * (slopeBefore + slope);
    }
    std::vector<double> out;
    for (double z : zs) {
        const int i = static_cast<int>(std::lround(z / h));
        // Shear deflection int_0^z P / (G A), trapezoid on 1000 intervals (error ~1e-7 of it, itself
        // ~1e-4 of the bending part).
        double s = 0;
        for (int k = 1; k <= 1000; ++k) {
            const double za = z * (k - 1) / 1000, zb = z * k / 1000;
            s += 0.5 * (zb - za) * (shearStrain(za) + shearStrain(zb));
        }
        out.push_back(w[i] + s);
    }
    return out;
}

struct Relaxed {
    std::vector<double> heights, deflection;
    std::vector<Vec2> footEnd, topEnd;  // each connection's moment at its two end sections
    double plasticWork = 0, speed = 0;
};

// This stem's first mode: omega_1 ~ 2.9 rad/s (0.46 Hz, tip load / tip deflection = 200 N/m on ~24 kg of modal mass).
constexpr double kOmega1 = 2.9;

// Tip load along x, no gravity, relaxation damping 6/s ~ critical for the first mode: after 6 s
// its amplitude is down to e^-17 (1 + 17) ~ 5e-7, the faster modes' (decay 3/s) to e^-18.
Relaxed relax(const StemGeometry& g, const StemParams& p, StemFoot foot, double load) {
    Stem stem(g, p, Vec3::Zero(), foot);
    StemStepper stepper(Vec3::Zero(), 6.0);
    StemLoads loads;
    loads.force.assign(stem.nodeCount(), Vec3::Zero());
    loads.force.back() = Vec3(load, 0, 0);
    const double dt = 0.9 * stem.stableTimeStep();
    for (double t = 0; t < 6.0; t += dt) stepper.step(stem, dt, loads);
    Relaxed r;
    for (std::size_t i = 0; i < stem.nodeCount(); ++i) {
        r.heights.push_back(stem.restHeight(i));
        r.deflection.push_back(stem.position[i].x());
        r.speed = std::max(r.speed, stem.velocity[i].norm());
    }
    for (std::size_t c = 0; c < stem.connectionCount(); ++c) {
        const ConnectionBeam& b = stem.bending(c);
        r.footEnd.push_back(b.sectionMoment(0));
        r.topEnd.push_back(b.sectionMoment(b.sectionCount() - 1));
    }
    r.plasticWork = stem.ledger.bendingPlasticity + stem.ledger.rootPlasticity;
    return r;
}

// Largest gap between model and beam theory over the nodes, relative to the beam's tip deflection.
double relativeGap(const Relaxed& r, const std::vector<double>& beam) {
    double gap = 0;
    for (std::size_t i = 0; i < beam.size(); ++i) gap = std::max(gap, std::abs(r.deflection[i] - beam[i]));
    return gap / beam.back();
}

}  // namespace

TEST(StemStatics, ClampedConeDeflectsAsBeamTheoryAndConvergesWithNodeSpacing) {
    const StemGeometry g = beechStem(20);
    // N: tip deflection ~1 cm (tip rotation ~1 mrad: the geometric non-linearity, ~theta^2, stays
    // ~1e-6), moments far below M_Elast everywhere (the run checks no plastic work).
    const double load = 2;
    std::vector<double> gaps;
    for (const double spacing : {1.0, 0.5, 0.25}) {
        const StemParams p = params(spacing);
        const Relaxed r = relax(g, p, StemFoot::Clamped, load);
        const std::vector<double> beam = beamDeflection(g.dbh, p.tipDiameter, g.height, p, load, r.heights);
        ASSERT_EQ(r.plasticWork, 0.0) << "the load must stay in the elastic range";
        // The motion left (amplitude speed / omega_1) must be far below the gaps measured.
        ASSERT_LT(r.speed / kOmega1, 1e-5 * r.deflection.back()) << "not relaxed";
        gaps.push_back(relativeGap(r, beam));
        std::printf("  spacing %.2f m: tip %.6f m (beam %.6f m), largest gap %.3e of the tip deflection\n", spacing,
                    r.deflection.back(), beam.back(), gaps.back());
    }
    // Each connection is a hinge at its middle with the stiffness of the middle's section: the
    // midpoint rule of the double integral, whose error falls as l^2 (a factor 4 per halving).
    // Factor 3 leaves room for the higher-order terms at 1 m spacing. At 0.25 m the default
    // spacing's error must be under 0.1 % (the paper's stems are far less certain than that).
    EXPECT_GT(gaps[0] / gaps[1], 3.0);
    EXPECT_GT(gaps[1] / gaps[2], 3.0);
    EXPECT_LT(gaps[2], 1e-3);
}

TEST(StemStatics, RootSpringAddsTheRigidRotationOfTheFoot) {
    const StemGeometry g = beechStem(20);
    const StemParams p = params(0.25);
    const double load = 2;
    const Relaxed r = relax(g, p, StemFoot::RootSpring, load);
    std::vector<double> expected = beamDeflection(g.dbh, p.tipDiameter, g.height, p, load, r.heights);
    for (std::size_t i = 0; i < expected.size(); ++i) expected[i] += load * g.height / p.root.stiffness * r.heights[i];
    ASSERT_EQ(r.plasticWork, 0.0);
    ASSERT_LT(r.speed / kOmega1, 1e-5 * r.deflection.back());
    // Same discretisation and bound as the finest clamped case: the foot's rotation adds no error.
    EXPECT_LT(relativeGap(r, expected), 1e-3);
    std::printf("  root spring: tip %.6f m, expected %.6f m\n", r.deflection.back(), expected.back());
}

// With sections along each connection (ConnectionBeam), the end sections carry the cantilever's
// moment P (L - z) at their own heights, the statics a connection's middle alone cannot show; and
// the deflection is the beam's to the relaxation's floor already at 0.5 m: the sections integrate
// the cone's flexibility with Simpson's rule, where one hinge per connection is the midpoint rule
// (6.5e-4 of the tip deflection at 0.5 m, the test above).
TEST(StemStatics, SectionsCarryTheCantileverMomentAtTheirHeights) {
    const StemGeometry g = beechStem(20);
    StemParams p = params(0.5);
    p.bending.sections = 3;
    const double load = 2;
    const Relaxed r = relax(g, p, StemFoot::Clamped, load);
    ASSERT_EQ(r.plasticWork, 0.0);
    ASSERT_LT(r.speed / kOmega1, 1e-5 * r.deflection.back());
    const double l = r.heights[1];
    for (std::size_t c = 0; c < r.footEnd.size(); ++c) {
        // Bending towards +x turns the stem about +y. The moment arm changes with the deflection by
        // ~w^2 / L ~ 1e-5 m: 1e-4 of P L bounds it and the relaxation's residue (~5e-7).
        EXPECT_NEAR(r.footEnd[c].y(), load * (g.height - c * l), 1e-4 * load * g.height) << "connection " << c;
        EXPECT_NEAR(r.topEnd[c].y(), load * (g.height - (c + 1) * l), 1e-4 * load * g.height) << "connection " << c;
        EXPECT_NEAR(r.footEnd[c].x(), 0, 1e-4 * load * g.height);
    }
    const std::vector<double> beam = beamDeflection(g.dbh, p.tipDiameter, g.height, p, load, r.heights);
    const double gap = relativeGap(r, beam);
    std::printf("  3 sections at 0.5 m: largest gap %.3e of the tip deflection\n", gap);
    EXPECT_LT(gap, 1e-4);
}

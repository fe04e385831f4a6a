// Free flight of the block: closed forms for translation under gravity and torque-free rotation.
#include <gtest/gtest.h>

#include <cmath>

#include "libdem/BlockShape.hpp"

using namespace sylva::dem;

TEST(RigidBody, CubeOfEq1HasTheTrueCubesMassAndInertia) {
    const RigidBody b = makeBlock(BlockSpec{});
    const double d = std::cbrt(0.5);  // 0.7937 m: Table 2's D1 = 0.794 m, given to 3 decimals
    EXPECT_DOUBLE_EQ(b.mass(), 2700 * 0.5);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(b.principalInertia()[i], b.mass() * d * d / 6, 1e-9);
    ASSERT_EQ(b.spheres().size(), 27u);
    double extent = 0;
    for (const auto& s : b.spheres()) {
        EXPECT_DOUBLE_EQ(s.radius, d / 4);  // Eq. 1
        extent = std::max(extent, s.offset.x() + s.radius);
    }
    EXPECT_NEAR(2 * extent, d, 1e-12);  // the clump spans exactly D1
}

TEST(RigidBody, CuboidSpansItsEdgesAndSphereHasSolidInertia) {
    BlockSpec c;
    c.shape = BlockShapeKind::Cuboid;
    c.d1 = 1.2, c.d2 = 0.8, c.d3 = 0.4;
    const RigidBody b = makeBlock(c);
    Vec3 hi = Vec3::Zero();
    for (const auto& s : b.spheres()) hi = hi.cwiseMax(s.offset + Vec3::Constant(s.radius));
    EXPECT_NEAR(hi.x(), 0.6, 1e-12);
    EXPECT_NEAR(hi.y(), 0.4, 1e-12);
    EXPECT_NEAR(hi.z(), 0.2, 1e-12);
    EXPECT_NEAR(b.principalInertia().x(), b.mass() / 12 * (0.64 + 0.16), 1e-9);
    BlockSpec s;
    s.shape = BlockShapeKind::Sphere;
    const RigidBody sb = makeBlock(s);
    const double r = sb.spheres()[0].radius;
    EXPECT_NEAR(4.0 / 3 * M_PI * r * r * r, 0.5, 1e-12);
    EXPECT_NEAR(sb.principalInertia().x(), 0.4 * sb.mass() * r * r, 1e-9);
}

TEST(RigidBody, FreeFlightFollowsTheLeapfrogParabola) {
    RigidBody b = makeBlock(BlockSpec{});
    const Vec3 v0(12, -3, 4), g(0, 0, -9.81);
    b.velocity = v0;
    const double dt = 1e-3;
    const int n = 3000;
    for (int i = 0; i < n; ++i) b.advance(dt, b.mass() * g, Vec3::Zero());
    const double t = n * dt;
    // Leapfrog with the start velocity taken as v(-dt/2) is exact up to the known offset g t dt / 2;
    // what remains is round-off.
    const Vec3 expected = v0 * t + 0.5 * g * t * t + 0.5 * g * t * dt;
    EXPECT_LT((b.position - expected).norm(), 1e-9);
}

TEST(RigidBody, TorqueFreeSpinConservesEnergyAndConvergesAtSecondOrder) {
    BlockSpec spec;
    spec.shape = BlockShapeKind::Cuboid;
    spec.d1 = 1.5, spec.d2 = 0.9, spec.d3 = 0.4;  // three distinct moments: the spin precesses
    auto spin = [&](double dt, double T) {
        RigidBody b = makeBlock(spec);
        b.setAngularVelocity(Vec3(0.3, 4.0, 0.5));  // near the unstable intermediate axis
        const double e0 = b.kineticEnergy();
        const Vec3 l0 = b.angularMomentum;
        const int n = static_cast<int>(std::lround(T / dt));
        for (int i = 0; i < n; ++i) b.advance(dt, Vec3::Zero(), Vec3::Zero());
        EXPECT_EQ(b.angularMomentum, l0);  // no torque: exactly unchanged
        return std::make_pair(b.orientation, std::abs(b.kineticEnergy() - e0) / e0);
    };
    const double T = 2.0;
    const auto ref = spin(1e-5, T);
    const auto coarse = spin(4e-3, T), fine = spin(2e-3, T);
    // Energy: the scheme keeps |q| = 1 exactly; the energy error is the orientation error, O(dt^2).
    EXPECT_LT(coarse.second, 1e-3);
    const double e1 = coarse.first.angularDistance(ref.first), e2 = fine.first.angularDistance(ref.first);
    const double order = std::log2(e1 / e2);
    RecordProperty("rotation_order", std::to_string(order));
    // Omelyan's scheme is second order; 1.7 allows for the reference's own error and round-off.
    EXPECT_GT(order, 1.7) << "errors " << e1 << " " << e2;
}

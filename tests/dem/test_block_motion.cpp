// The block on the slope: friction angle, energy conservation, convergence, robustness.
#include <gtest/gtest.h>

#include <cmath>

#include "DemTestScenes.hpp"
#include "libdem/BlockMotion.hpp"
#include "libdem/SimulationError.hpp"
#include "libcommon/InputError.hpp"

using namespace sylva::dem;
using namespace sylva::dem::testing;

namespace {

// A block resting flat on a straight slope of fine soil spheres (close to a plane),
// followed for 3 s. Returns the block's displacement along x and its acceleration along the slope
// over the last 2 s, and its largest spin about y (tumbling).
struct SlopeOutcome {
    double dx, acceleration, maxSpin;
};

SlopeOutcome restOnSlope(double slopeDeg, std::vector<std::string> keys, double roughness) {
    keys.push_back("terrain.roughness_m=" + std::to_string(roughness));
    const Scene scene(straightSlopeScene(slopeDeg, 40, 10, keys));
    const double theta = slopeDeg * M_PI / 180, x = 10;
    double half = 0;  // half-thickness of the block along its body z
    for (const auto& s : scene.blockTemplate().spheres()) half = std::max(half, s.offset.z() + s.radius);
    const Vec3 n(std::sin(theta), 0, std::cos(theta));
    const Vec3 surface(x, 5, scene.soil().surfaceHeight(x, 5));
    BlockMotion m(scene, Release{surface + n * (half + 2e-3), Quat(Eigen::AngleAxisd(theta, Vec3::UnitY()))});
    double spin = 0;
    while (m.time() < 1.0) m.step();  // settle on the springs
    const double x1 = m.block().position.x(), t1 = m.time(), v1 = m.block().velocity.x();
    while (m.time() < 3.0) {
        m.step();
        spin = std::max(spin, std::abs(m.block().angularVelocity().y()));
    }
    const double t = m.time() - t1;
    return {m.block().position.x() - x1, (m.block().velocity.x() - v1) / t / std::cos(theta), spin};
}

}  // namespace

TEST(BlockOnSlope, SlabStaysBelowTheFrictionAngleAndSlidesAboveIt) {
    // A 1.6 x 1.6 x 0.8 m slab of 0.2 m spheres cannot tip before 56 deg, so only friction decides.
    // On a 1 mm-rough bed its spheres sit in hollows whose walls lean by asin((d/2)/(R+r)) = 2.4 deg:
    // at rest the bed adds up to that much to the friction angle where a plane would not.
    const std::vector<std::string> slab = {"block.shape=cuboid", "block.d1_m=1.6", "block.d2_m=1.6", "block.d3_m=0.8",
                                           "soil.friction_deg=30"};
    const auto below = restOnSlope(25, slab, 0.001);
    EXPECT_LT(std::abs(below.dx), 0.01) << "a block below the friction angle must not slide";
    const auto above = restOnSlope(40, slab, 0.001);
    EXPECT_GT(above.dx, 0.1) << "a block above the friction angle must slide";

    // How fast it slides is Coulomb's law once the dashpots are off: with Table 2's damping every
    // bump the slab rides over is damped with alpha from the whole block's mass (Eq. 16), a viscous
    // drag that belongs to the model but is not what this checks.
    const auto undamped = [](int friction) {
        return std::vector<std::string>{"block.shape=cuboid", "block.d1_m=1.6", "block.d2_m=1.6", "block.d3_m=0.8",
                                        "soil.friction_deg=" + std::to_string(friction), "soil.damping_ratio=0"};
    };
    // Coulomb: a = g (sin theta - tan phi cos theta), at two friction angles so that the friction
    // coefficient itself is what is checked (a tan phi 6 % off moves Coulomb's a by 13 % at 30 deg, 20 % at 33).
    // Measured +1.4 % and +0.2 %: on the bed of spheres the slab rides on springs and its velocity,
    // read at two instants, carries that bounce; 3 % bounds it.
    const double theta = 40 * M_PI / 180;
    for (const int phi : {30, 33}) {
        const double coulomb = 9.81 * (std::sin(theta) - std::tan(phi * M_PI / 180) * std::cos(theta));
        const double a = restOnSlope(40, undamped(phi), 0.001).acceleration;
        std::printf("slab at 40 deg, phi %d: %.4f m/s2 against Coulomb's %.4f\n", phi, a, coulomb);
        EXPECT_NEAR(a, coulomb, 0.03 * coulomb) << "phi " << phi;
    }
}

TEST(BlockOnSlope, TwentySevenSphereCubeTipsAtTheAngleItsSpheresAllow) {
    // The clump's outer spheres touch the ground R_b = D1/4 inside the cube's edges, under a centre of
    // mass D1/2 high: it tips when tan(slope) > (D1/4)/(D1/2), at 26.6 deg, not at the true cube's
    // 45 deg. On a 5 mm-rough bed the contact normals lean by up to asin((d/2)/(R+r)) = 5.8 deg,
    // which narrows the support further: "below" is taken 6 deg under 26.6. High friction (45 deg)
    // rules sliding out.
    const auto below = restOnSlope(20, {"soil.friction_deg=45"}, 0.005);
    EXPECT_LT(std::abs(below.dx), 0.01);
    EXPECT_LT(below.maxSpin, 0.5);  // rocking while it settles, far below tumbling
    const auto above = restOnSlope(31, {"soil.friction_deg=45"}, 0.005);
    EXPECT_GT(above.maxSpin, 1.0) << "the cube should tumble";
}

TEST(BlockOnSlope, EnergyIsConservedWithoutDampingOrFriction) {
    auto imbalance = [](double safety) {
        const Scene scene(straightSlopeScene(20, 60, 10,
                                             {"soil.damping_ratio=0", "soil.friction_deg=0", "block.shape=sphere",
                                              "integration.safety=" + std::to_string(safety), "release.x_m=10",
                                              "release.y_m=5", "release.orientation=fixed"}));
        BlockMotion m(scene, drawRelease(scene, 1));
        while (m.time() < 4.0) m.step();
        EXPECT_EQ(m.energy().contactDamping, 0.0);
        EXPECT_EQ(m.energy().friction, 0.0);
        return m.energy().imbalance;
    };
    const double coarse = imbalance(0.2), fine = imbalance(0.1), finer = imbalance(0.05);
    std::printf("energy imbalance at safety 0.2/0.1/0.05: %.3g %.3g %.3g\n", coarse, fine, finer);
    // The leapfrog's energy error is O((omega dt)^2) while a contact lasts, but a contact starts and
    // ends between two steps, and the spring energy of that part of the step is missed: overall
    // the error is first order. We require it small (0.6 % of the energy converted at safety 0.2)
    // and falling at least about as fast as dt (order > 0.8).
    EXPECT_LT(coarse, 6e-3);
    EXPECT_GT(std::log2(coarse / fine), 0.8);
    EXPECT_GT(std::log2(fine / finer), 0.8);
}

// Compared after 1 s, while the block's first impacts decide its path: later, which soil sphere
// a corner meets next flips with the step (at 3 s the errors at safety 0.15, 0.075 and 0.0375 are
// 0.069, 0.084 and 0.092 m: no order can be read), a sensitivity of the path, not an error.
TEST(BlockOnSlope, ResultsConvergeAsTheTimeStepShrinks) {
    auto endPoint = [](double safety) {
        const Scene scene(straightSlopeScene(33, 120, 20, {"integration.safety=" + std::to_string(safety),
                                                           "release.x_m=10", "release.y_m=10"}));
        BlockMotion m(scene, drawRelease(scene, 7));
        while (m.time() < 1.0) m.step();
        return m.block().position;
    };
    const Vec3 ref = endPoint(0.3 / 64);
    const double e1 = (endPoint(0.3) - ref).norm(), e2 = (endPoint(0.15) - ref).norm(), e3 = (endPoint(0.075) - ref).norm();
    const double order = std::log2(e2 / e3);
    RecordProperty("errors_m", std::to_string(e1) + " " + std::to_string(e2) + " " + std::to_string(e3));
    RecordProperty("order", std::to_string(order));
    std::printf("position error after 1 s at safety 0.3/0.15/0.075: %.4g %.4g %.4g m; observed orders %.2f %.2f\n", e1, e2,
                e3, std::log2(e1 / e2), order);
    EXPECT_LT(e3, e2);
    EXPECT_LT(e2, e1);
    // The viscous term uses the half-step-old velocity (as Yade does): first order overall.
    EXPECT_GT(std::log2(e1 / e2), 0.7);
    EXPECT_GT(order, 0.7);
}

TEST(BlockOnSlope, ForcedStepAboveTheStableLimitIsRefused) {
    const Scene scene(straightSlopeScene(30, 60, 10, {"integration.dt_s=0.05", "release.x_m=10", "release.y_m=5"}));
    BlockMotion m(scene, drawRelease(scene, 1));
    EXPECT_THROW(
        {
            while (m.time() < 5) m.step();
        },
        SimulationError);
}

TEST(BlockOnSlope, BlockReleasedInsideTheSoilIsAnInputError) {
    const Scene scene(straightSlopeScene(30, 60, 10, {"release.fall_height_m=0.1", "release.x_m=10", "release.y_m=5"}));
    EXPECT_THROW(BlockMotion(scene, drawRelease(scene, 1)), sylva::InputError);
}

TEST(BlockOnSlope, ReleaseOutsideTheTerrainIsAnInputError) {
    const Scene scene(straightSlopeScene(30, 60, 10, {"release.x_m=100", "release.y_m=5"}));
    EXPECT_THROW(drawRelease(scene, 1), sylva::InputError);
}

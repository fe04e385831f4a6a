// The narrow phase every contact kind shares (touchSpheres): where two spheres touch, how deep,
// and along which normal; a contact law trusts these to store and release the same energy.
#include <gtest/gtest.h>

#include "libdem/SphereContact.hpp"

using namespace sylva::dem;

TEST(ContactSpheres, OverlapNormalAndPointInTheMiddleOfTheOverlap) {
    ContactGeometry g;
    // A (r 0.5) at (0, 0, 1.2) above B (r 0.8) at the origin: 0.1 m deep along +z.
    ASSERT_TRUE(touchSpheres(Vec3(0, 0, 1.2), 0.5, Vec3::Zero(), 0.8, g));
    EXPECT_NEAR(g.overlap, 0.1, 1e-15);
    EXPECT_TRUE(g.normal.isApprox(Vec3::UnitZ(), 1e-15)) << "from B to A: a positive normal force pushes A away";
    // Middle of the lens: B's surface at 0.8 and A's at 0.7 along the normal.
    EXPECT_TRUE(g.point.isApprox(Vec3(0, 0, 0.75), 1e-15));
    EXPECT_EQ(g.radiusA, 0.5);
    EXPECT_EQ(g.radiusB, 0.8);
    // Swapping the bodies turns the normal, not the point.
    ContactGeometry h;
    ASSERT_TRUE(touchSpheres(Vec3::Zero(), 0.8, Vec3(0, 0, 1.2), 0.5, h));
    EXPECT_TRUE(h.normal.isApprox(-Vec3::UnitZ(), 1e-15));
    EXPECT_TRUE(h.point.isApprox(g.point, 1e-15));
}

TEST(ContactSpheres, ApartTheyReportHowFarSoCallersCanLookAhead) {
    ContactGeometry g;
    EXPECT_FALSE(touchSpheres(Vec3(3, 4, 0), 1, Vec3::Zero(), 1.5, g));
    EXPECT_NEAR(g.overlap, -2.5, 1e-15);
    EXPECT_FALSE(touchSpheres(Vec3(2.5, 0, 0), 1, Vec3::Zero(), 1.5, g)) << "just touching is not a contact";
    // Coinciding centres have no normal: not a contact, whatever the overlap.
    EXPECT_FALSE(touchSpheres(Vec3(1, 2, 3), 1, Vec3(1, 2, 3), 1, g));
}

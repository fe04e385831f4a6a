// Beech allometry, Eqs. 11-13, against values worked out by hand from the paper's coefficients and
// against the anchors of model-notes.md (H_T(0.20 m) ~ 13.9 m, m_C(20 cm) ~ 40 kg).
#include <gtest/gtest.h>

#include "libstand/Allometry.hpp"

using namespace sylva::stand;

// Hand arithmetic is exact to the digits written; 1e-9 m only absorbs floating-point rounding.
constexpr double kRounding = 1e-9;

TEST(Allometry, HeightUsesDiameterInMetres) {
    // Eq. 11 with D = 0.20 m: 1.3 + 73.805*0.20 - 54.734*0.04 = 1.3 + 14.761 - 2.18936
    EXPECT_NEAR(treeHeightM(20.0), 13.87164, kRounding);
    // D = 0.05 m: 1.3 + 3.69025 - 0.136835
    EXPECT_NEAR(treeHeightM(5.0), 4.853415, kRounding);
    // D = 0.50 m: 1.3 + 36.9025 - 13.6835
    EXPECT_NEAR(treeHeightM(50.0), 24.519, kRounding);
    // model-notes.md: "H_T(0.20 m) ~ 13.9 m"; the note rounds to 0.1 m
    EXPECT_NEAR(treeHeightM(20.0), 13.9, 0.05);
}

TEST(Allometry, HeightIsHeldAtTheParabolaVertexForThickerStems) {
    // Vertex of Eq. 11 at D* = 73.805 / (2 * 54.734) m, where H = 1.3 + 73.805^2 / (4 * 54.734) = 26.18023 m.
    const double vertexHeight = 1.3 + 73.805 * 73.805 / (4 * 54.734);
    EXPECT_NEAR(treeHeightM(100 * 73.805 / (2 * 54.734)), vertexHeight, kRounding);
    EXPECT_NEAR(treeHeightM(84.5), vertexHeight, kRounding);   // largest DBH of the inventories
    EXPECT_NEAR(treeHeightM(200.0), vertexHeight, kRounding);  // Eq. 11 itself would give -72.7 m here
    double previous = 0;
    for (double d = 1.0; d <= 150.0; d += 0.5) {
        EXPECT_GE(treeHeightM(d), previous) << "at " << d << " cm";
        previous = treeHeightM(d);
    }
}

TEST(Allometry, CrownLengthIsAFixedShareOfHeight) {
    EXPECT_NEAR(crownLengthM(20.0), 8.1284, kRounding);  // Eq. 12: 0.40642 * 20
    EXPECT_NEAR(crownLengthM(treeHeightM(20.0)), 0.40642 * 13.87164, kRounding);
}

TEST(Allometry, CrownMassUsesDiameterInCentimetres) {
    // Eq. 13 with D = 10 cm: 0.0031 * 10^3.161 = 3.1 * 10^0.161 = 3.1 * 1.44877185
    EXPECT_NEAR(crownMassKg(10.0), 4.49119274, 1e-7);  // 10^0.161 is quoted to 9 digits
    // Doubling D multiplies m_C by 2^3.161 = 8.944495; model-notes.md quotes m_C(20 cm) ~ 40 kg
    EXPECT_NEAR(crownMassKg(20.0) / crownMassKg(10.0), 8.944495, 1e-6);  // 2^3.161 quoted to 7 digits
    EXPECT_NEAR(crownMassKg(20.0), 40.0, 0.5);  // the note rounds to the kilogram
}

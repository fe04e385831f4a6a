// Soil types over a terrain (libdem SoilZones): the zoned law is, at each contact point, exactly the
// law of the zone under it, and its step-setting values are the stiffest zone's.
#include <gtest/gtest.h>

#include <stdexcept>

#include "libcommon/InputError.hpp"
#include "libdem/SoilZones.hpp"

using namespace sylva::dem;

namespace {

// Two zones on a 2 x 1 grid of 10 m cells centred at x = 0 and x = 10: soft scree-like soil in the
// west, a stiffer, more damped, rougher one in the east.
std::shared_ptr<SoilZones> twoZones() {
    auto z = std::make_shared<SoilZones>();
    z->x0 = 0;
    z->y0 = 0;
    z->cell = 10;
    z->columns = 2;
    z->rows = 1;
    z->zone = {0, 1};
    z->names = {"west", "east"};
    SoilContactParams west, east;
    east.kn = 4e6;
    east.dampingRatio = 0.8;
    east.frictionDeg = 40;
    z->params = {west, east};
    return z;
}

ContactGeometry approachingAt(double x) {
    ContactGeometry g;
    g.point = Vec3(x, 0, 0);
    g.overlap = 0.01;
    g.relativeVelocity = Vec3(1.0, 0, -2.0);  // sliding and pressing in: spring, dashpot and shear all act
    return g;
}

}  // namespace

TEST(SoilZones, NearestCellDecidesAndTheEdgesExtend) {
    const auto z = twoZones();
    EXPECT_EQ(z->at(4.9, 0), 0u);
    EXPECT_EQ(z->at(5.1, 0), 1u);
    EXPECT_EQ(z->at(-100, 50), 0u);  // beyond the grid: the nearest edge cell's
    EXPECT_EQ(z->at(100, -50), 1u);
}

TEST(SoilZones, EachContactTakesTheLawOfItsZone) {
    const auto z = twoZones();
    const double mass = 1350;
    const ZonedSoilContact zoned(z, mass);
    for (double x : {2.0, 8.0}) {
        const SoilContact own(z->params[z->at(x, 0)], mass);
        ContactHistory hz, ho;
        DissipationLedger lz, lo;
        const ContactGeometry g = approachingAt(x);
        const Vec3 fz = zoned.force(g, hz, 1e-4, lz), fo = own.force(g, ho, 1e-4, lo);
        EXPECT_EQ(fz, fo) << "at x = " << x;  // the same law, so the same floating-point operations
        EXPECT_EQ(lz.contactDamping, lo.contactDamping);
        EXPECT_EQ(zoned.normalStiffness(g), own.normalStiffness(g));
        EXPECT_EQ(zoned.storedEnergy(g, hz), own.storedEnergy(g, ho));
    }
    // The stable step is taken for the stiffest, most damped zone.
    EXPECT_EQ(zoned.largestNormalStiffness(), 4e6);
    EXPECT_EQ(zoned.dampingCoefficient(), SoilContact(z->params[1], mass).dampingCoefficient());
}

TEST(SoilZones, BadZonesAreRefused) {
    auto z = twoZones();
    z->params[1].frictionDeg = 95;
    try {
        ZonedSoilContact(z, 1000);
        FAIL() << "a friction angle of 95 degrees was accepted";
    } catch (const sylva::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("soil type 'east'"), std::string::npos) << e.what();
    }
    z = twoZones();
    z->zone = {0, 2};
    EXPECT_THROW(ZonedSoilContact(z, 1000), std::invalid_argument);
    z = twoZones();
    z->zone = {0};
    EXPECT_THROW(ZonedSoilContact(z, 1000), std::invalid_argument);
}

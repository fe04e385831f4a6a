// The calibrated tree against what winching tests measured on real ones (docs/model-stems.md,
// "Calibration data"; the data and their sources: data/calibration/anchorage-winching.csv).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "libdem/Stem.hpp"
#include "libdem/StemParameterSet.hpp"
#include "libcommon/CsvTable.hpp"

using namespace sylva::dem;

namespace {

const double kPi = std::acos(-1.0);
const std::string kWinching = std::string(SYLVAROCK_DATA) + "/calibration/anchorage-winching.csv";

StemParams calibrated() { return stemParameters(StemParameterSet::Calibrated); }

// Volume of the stem's cone from its taper, by Simpson's rule on 200 slices (the taper is linear, so
// the integrand is a quadratic and the rule exact): independent of how the stem lumps its mass.
double coneVolume(const Stem& stem) {
    const double h = stem.geometry().height;
    const int n = 200;
    const auto area = [&](double z) { return kPi / 4 * std::pow(stem.diameterAt(z), 2); };
    double sum = area(0) + area(h);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * area(h * i / n);
    return sum * h / (3 * n);
}

}  // namespace

// Winching tests give the critical turning moment as C_reg times the stem's weight, each species'
// C_reg with the green density it was computed with. The model's and the data's densities differ (1 200
// against 616-1 002 kg/m3), so the quantity both sides share is the moment per cubic metre of stem.
// For beeches of DBH 10-50 cm the model's M_a per m3 must lie within the range that the species
// actually pulled over span, whatever their soil and rooting depth (fgr's beech, oak and birch values
// are estimates from other species, not pulled trees: printed beside, not a bound). No tolerance: the
// band is the data's.
TEST(TreeCalibration, AnchorageWithinTheWinchingData) {
    const sylva::CsvTable t = sylva::CsvTable::read(kWinching);
    const std::size_t cMin = t.require("creg_min"), cMax = t.require("creg_max"),
                      cRho = t.require("green_density_kg_m3"), cN = t.require("pulled_trees"),
                      cSpecies = t.require("species");
    double low = std::numeric_limits<double>::infinity(), high = 0, beechLow = 0, beechHigh = 0;
    int measured = 0;
    for (std::size_t r = 0; r < t.rows(); ++r) {
        const double lo = t.number(r, cMin) * t.number(r, cRho), hi = t.number(r, cMax) * t.number(r, cRho);
        if (t.text(r, cSpecies) == "Beech") beechLow = lo, beechHigh = hi;
        if (t.integer(r, cN) == 0) continue;
        ++measured;
        low = std::min(low, lo);
        high = std::max(high, hi);
    }
    ASSERT_GE(measured, 10) << "the winching table lost its measured species";
    std::printf("  winching data, M_crit per m3 of stem: %.0f-%.0f kN m/m3 over %d pulled species "
                "(fgr's beech estimate %.0f-%.0f)\n",
                low / 1e3, high / 1e3, measured, beechLow / 1e3, beechHigh / 1e3);

    const StemParams p = calibrated();
    for (double dbh = 10; dbh <= 50; dbh += 5) {
        const Stem stem(beechStem(dbh), p, Vec3::Zero(), StemFoot::RootSpring);
        const double volume = coneVolume(stem);
        const double ma = stem.root().yieldMoment();
        std::printf("  DBH %2.0f cm: stem %.3f m3, M_a %.1f kN m = %.0f kN m/m3; data %.1f-%.1f kN m\n", dbh, volume,
                    ma / 1e3, ma / volume / 1e3, low * volume / 1e3, high * volume / 1e3);
        EXPECT_GE(ma / volume, low) << dbh << " cm";
        EXPECT_LE(ma / volume, high) << dbh << " cm";
    }
}

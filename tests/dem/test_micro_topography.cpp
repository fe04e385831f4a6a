// Relief added to a DTM (libdem MicroTopography): the field has the standard deviation and the
// exponential correlation asked for, is drawn from its seed alone, leaves NODATA alone, and the soil
// bed of a scene on a DTM is laid on it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "libcommon/InputError.hpp"
#include "libdem/MicroTopography.hpp"
#include "libdem/Scene.hpp"

using namespace sylva::dem;

namespace {

// A 40 % plane of 400 x 400 cells of 2 m: the added field is the difference from it.
ElevationGrid plane(double noDataAt = -1) {
    const int n = 400;
    std::vector<double> z(static_cast<std::size_t>(n) * n);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) z[static_cast<std::size_t>(r) * n + c] = 100 - 0.4 * 2 * c;
    if (noDataAt >= 0) z[static_cast<std::size_t>(noDataAt)] = std::nan("");
    return ElevationGrid::fromValues(n, n, 0, 0, 2.0, std::move(z), "plane");
}

std::vector<double> field(const ElevationGrid& with, const ElevationGrid& without) {
    std::vector<double> f(with.values().size());
    for (std::size_t i = 0; i < f.size(); ++i) f[i] = with.values()[i] - without.values()[i];
    return f;
}

// Correlation of the field with itself `lag` cells along x (dc = 1) or y (dr = 1).
double correlation(const std::vector<double>& f, int n, int lag, bool alongX) {
    double sab = 0, saa = 0;
    long count = 0;
    for (int r = 0; r + (alongX ? 0 : lag) < n; ++r)
        for (int c = 0; c + (alongX ? lag : 0) < n; ++c) {
            const double a = f[static_cast<std::size_t>(r) * n + c];
            const double b = f[static_cast<std::size_t>(alongX ? r : r + lag) * n + (alongX ? c + lag : c)];
            sab += a * b;
            saa += a * a;
            ++count;
        }
    return sab / saa;
}

}  // namespace

// 160 000 cells with a correlation length of 3 cells: ~4 400 independent patches, so the sample
// standard deviation is within ~1 % of sigma and a correlation within ~0.015 of its value (one
// standard error); the tolerances are ~3 of those.
TEST(MicroTopography, FieldHasItsStandardDeviationAndCorrelation) {
    const ElevationGrid base = plane();
    const ElevationGrid rough = withMicroTopography(base, {0.5, 6.0, 7});
    const std::vector<double> f = field(rough, base);
    double sum = 0, sq = 0;
    for (double v : f) {
        sum += v;
        sq += v * v;
    }
    const double mean = sum / f.size(), sd = std::sqrt(sq / f.size() - mean * mean);
    EXPECT_NEAR(sd, 0.5, 0.5 * 0.04);
    EXPECT_NEAR(mean, 0, 0.03);
    for (bool alongX : {true, false}) {
        EXPECT_NEAR(correlation(f, 400, 1, alongX), std::exp(-2.0 / 6.0), 0.05) << (alongX ? "x" : "y");
        EXPECT_NEAR(correlation(f, 400, 3, alongX), std::exp(-1.0), 0.05) << (alongX ? "x" : "y");
    }
}

TEST(MicroTopography, SeedAloneDrawsTheFieldAndNoDataStays) {
    const ElevationGrid base = plane(1234);
    const ElevationGrid a = withMicroTopography(base, {0.4, 6.0, 3}), b = withMicroTopography(base, {0.4, 6.0, 3}),
                        c = withMicroTopography(base, {0.4, 6.0, 4});
    EXPECT_EQ(a.values()[10], b.values()[10]);
    EXPECT_NE(a.values()[10], c.values()[10]);
    EXPECT_TRUE(std::isnan(a.values()[1234]));
    EXPECT_EQ(a.noDataCells(), 1);
    EXPECT_EQ(withMicroTopography(base, {0.0, 6.0, 3}).values()[10], base.values()[10]);
    EXPECT_THROW(withMicroTopography(base, {-0.1, 6.0, 3}), sylva::InputError);
    EXPECT_THROW(withMicroTopography(base, {0.1, 0.0, 3}), sylva::InputError);
}

// A scene on a DTM lays its soil bed on the relief (terrain.microtopography_m); a profile carries
// its own and refuses it.
TEST(MicroTopography, SceneLaysItsBedOnTheRelief) {
    const ElevationGrid base = plane();
    SceneConfig flat = sceneFromOverrides({"terrain.microtopography_m=0"}), rough = sceneFromOverrides({"terrain.microtopography_m=0.5"});
    const Scene smooth(flat, base), relief(rough, base);
    double largest = 0;
    for (double x = 100; x < 700; x += 7.3) largest = std::max(largest, std::fabs(relief.soil().surfaceHeight(x, 400) - smooth.soil().surfaceHeight(x, 400)));
    EXPECT_GT(largest, 0.5);  // ~80 points of a field with sd 0.5 m: its largest departure is well above 1 sd
    EXPECT_LT(largest, 5 * 0.5);
    SceneConfig profile = sceneFromOverrides({"terrain.profile=" + std::string(SYLVAROCK_DATA) + "/slopes/standin-s0.4.csv", "terrain.microtopography_m=0.4"});
    EXPECT_THROW(Scene{profile}, sylva::InputError);
}

// Pearson's r and the ranks of Fig. 11-12 against published and hand-computed values.
#include <gtest/gtest.h>

#include <cmath>

#include "libassess/Correlation.hpp"

namespace {

using sylva::assess::ascendingRanks;
using sylva::assess::pearson;
using sylva::assess::pearsonPValue;

TEST(Correlation, AnscombesFirstSetHasThePublishedCoefficient) {
    // Anscombe (1973), data set I: r = 0.816 as published (3 decimals, hence the 5e-4 tolerance).
    const std::vector<double> x{10, 8, 13, 9, 11, 14, 6, 4, 12, 7, 5};
    const std::vector<double> y{8.04, 6.95, 7.58, 8.81, 8.33, 9.96, 7.24, 4.26, 10.84, 4.82, 5.68};
    EXPECT_NEAR(pearson(x, y), 0.816, 5e-4);
}

TEST(Correlation, ExactLinesGivePlusOrMinusOne) {
    const std::vector<double> g{26.8, 32.7, 40.9, 43.9};
    std::vector<double> up, down;
    for (double v : g) {
        up.push_back(0.1 + 0.01 * v);
        down.push_back(2 - 0.03 * v);
    }
    // Rounding of the sums only: a few ulps.
    EXPECT_NEAR(pearson(g, up), 1.0, 1e-12);
    EXPECT_NEAR(pearson(g, down), -1.0, 1e-12);
}

TEST(Correlation, UndefinedWithoutSpreadOrPairs) {
    EXPECT_TRUE(std::isnan(pearson({1.0}, {2.0})));
    EXPECT_TRUE(std::isnan(pearson({1, 2, 3}, {5, 5, 5})));
    EXPECT_THROW(pearson({1, 2}, {1, 2, 3}), std::invalid_argument);
}

// Student's t table: with 6 degrees of freedom the two-sided 5 % critical value is 2.446912 and the
// 1 % one 3.707428 (Abramowitz & Stegun, Table 26.10, 6 digits: hence tolerances of 1e-5 on p).
TEST(Correlation, PValueMatchesStudentsTable) {
    const auto rFor = [](double t, double dof) { return t / std::sqrt(t * t + dof); };
    EXPECT_NEAR(pearsonPValue(rFor(2.446912, 6), 8), 0.05, 1e-5);
    EXPECT_NEAR(pearsonPValue(-rFor(3.707428, 6), 8), 0.01, 1e-5);
    EXPECT_NEAR(pearsonPValue(0, 8), 1, 1e-12);
    EXPECT_EQ(pearsonPValue(1, 5), 0);
    EXPECT_TRUE(std::isnan(pearsonPValue(0.9, 2)));  // no degree of freedom left
    EXPECT_TRUE(std::isnan(pearsonPValue(std::nan(""), 8)));
}

TEST(Correlation, RanksAscendWithTiesSharingTheLowest) {
    EXPECT_EQ(ascendingRanks({0.45, 0.30, 0.52, 0.30}), (std::vector<int>{3, 1, 4, 1}));
    EXPECT_TRUE(ascendingRanks({}).empty());
}

}  // namespace

// The PF50 interval (libassess/Bootstrap.hpp) on synthetic run-outs whose population medians are
// known, so the true PF50 (Eq. 26) is known and the interval's coverage can be counted.
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>

#include "libassess/Bootstrap.hpp"
#include "libassess/ProtectionIndex.hpp"

namespace {

using sylva::assess::bootstrapProtectionIndex;
using sylva::assess::BootstrapSettings;

struct Synthetic {
    double forestMedian = 60, baselineMedian = 100;  // m; true PF50 = 1 - 60/100 = 0.4
    double runSd = 10;          // block-to-block spread, m
    double realisationSd = 0;   // forest-to-forest spread of a realisation's median, m
    int realisations = 1, runs = 60, baselineRuns = 60;
};

// Coverage of the true PF50 over `repetitions` synthetic campaigns, each with its own data and interval.
// poolRealisations: hand the bootstrap all runs as one realisation (a bootstrap of the runs only).
double coverage(const Synthetic& s, int repetitions, int replicates, bool poolRealisations = false) {
    std::unique_ptr<gsl_rng, decltype(&gsl_rng_free)> rng(gsl_rng_alloc(gsl_rng_mt19937), &gsl_rng_free);
    gsl_rng_set(rng.get(), 12345);
    // Gaussian run-outs: the median of the pooled population (a Gaussian mixture symmetric about
    // forestMedian) is forestMedian, whatever the realisation spread.
    const double truth = 1 - s.forestMedian / s.baselineMedian;
    int covered = 0;
    for (int rep = 0; rep < repetitions; ++rep) {
        std::vector<std::vector<double>> forest(s.realisations);
        for (auto& runs : forest) {
            const double centre = s.forestMedian + gsl_ran_gaussian(rng.get(), s.realisationSd);
            for (int i = 0; i < s.runs; ++i) runs.push_back(centre + gsl_ran_gaussian(rng.get(), s.runSd));
        }
        std::vector<double> baseline;
        for (int i = 0; i < s.baselineRuns; ++i) baseline.push_back(s.baselineMedian + gsl_ran_gaussian(rng.get(), s.runSd));
        if (poolRealisations) {
            for (std::size_t k = 1; k < forest.size(); ++k) forest[0].insert(forest[0].end(), forest[k].begin(), forest[k].end());
            forest.resize(1);
        }
        BootstrapSettings b;
        b.replicates = replicates;
        b.seed = 1000 + rep;
        const auto ci = bootstrapProtectionIndex(forest, baseline, b);
        if (ci.low <= truth && truth <= ci.high) ++covered;
    }
    return static_cast<double>(covered) / repetitions;
}

// Binomial standard deviation of a coverage of 0.95 counted over n repetitions.
double coverageSd(int n) { return std::sqrt(0.95 * 0.05 / n); }

TEST(Bootstrap, OneRealisationCoversTheTruePf50AtTheNominalRate) {
    // One forest: the interval is the ordinary bootstrap of the runs, consistent for a median.
    const int n = 300;
    const double c = coverage(Synthetic{}, n, 500);
    RecordProperty("coverage", std::to_string(c));
    // 4 binomial standard deviations (0.05 at n = 300): a correct 95 % interval fails this once in ~10^4.
    EXPECT_NEAR(c, 0.95, 4 * coverageSd(n));
}

TEST(Bootstrap, RealisationSpreadIsCoveredNotIgnored) {
    // Five forests whose medians differ (sd 4 m) besides the run spread (sd 10 m over 20 runs each).
    // By the delta method the forest-to-forest part is more than half of PF50's variance, so an
    // interval that resampled only the runs would be ~0.66 times too narrow and cover ~80 %.
    Synthetic s;
    s.realisations = 5;
    s.runs = 20;
    s.realisationSd = 4;
    const int n = 300;
    const double twoStage = coverage(s, n, 500), runsOnly = coverage(s, n, 500, true);
    RecordProperty("coverage", std::to_string(twoStage));
    RecordProperty("coverage_runs_only", std::to_string(runsOnly));
    // The two-stage bootstrap is documented as conservative when runs dominate and slightly narrow when
    // forests dominate with few realisations, so the bound is nominal minus 4 binomial sd (0.05)...
    EXPECT_GE(twoStage, 0.95 - 4 * coverageSd(n));
    // ...and the same data resampled as runs only falls below it: the test sees the realisations.
    EXPECT_LT(runsOnly, 0.95 - 4 * coverageSd(n));
}

TEST(Bootstrap, SameSeedSameIntervalAndItHoldsTheEstimate) {
    const std::vector<std::vector<double>> forest{{50, 52, 55, 58, 61, 63, 70}, {48, 51, 57, 59, 60, 66, 72}};
    const std::vector<double> baseline{95, 97, 99, 100, 101, 104, 108};
    BootstrapSettings b;
    b.seed = 7;
    const auto a = bootstrapProtectionIndex(forest, baseline, b), again = bootstrapProtectionIndex(forest, baseline, b);
    EXPECT_EQ(a.low, again.low);
    EXPECT_EQ(a.high, again.high);
    std::vector<double> pooled;
    for (const auto& r : forest) pooled.insert(pooled.end(), r.begin(), r.end());
    const double pf = sylva::assess::protectionIndex(pooled, baseline);
    EXPECT_LE(a.low, pf);
    EXPECT_GE(a.high, pf);
    EXPECT_LT(a.low, a.high);
}

TEST(Bootstrap, RefusesEmptySamples) {
    EXPECT_THROW(bootstrapProtectionIndex({}, {100}, {}), std::invalid_argument);
    EXPECT_THROW(bootstrapProtectionIndex({{50}, {}}, {100}, {}), std::invalid_argument);
    EXPECT_THROW(bootstrapProtectionIndex({{50}}, {}, {}), std::invalid_argument);
}

}  // namespace

// The report's label: a 99.5 % interval is not "100 %", a 97.5 % one not "98 %".
TEST(Bootstrap, TheConfidenceIsPrintedAsGiven) {
    EXPECT_EQ(sylva::assess::confidencePercent(0.95), "95");
    EXPECT_EQ(sylva::assess::confidencePercent(0.995), "99.5");
    EXPECT_EQ(sylva::assess::confidencePercent(0.975), "97.5");
    EXPECT_EQ(sylva::assess::confidencePercent(0.9999), "99.99");
}


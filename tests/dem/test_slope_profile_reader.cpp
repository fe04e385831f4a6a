// Slope profiles: the CSV reader and its errors, the profile's geometry against 3-4-5 triangles,
// and the stand-in slope files of data/slopes/ against what the issue asks of them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "libdem/SlopeProfile.hpp"
#include "libcommon/InputError.hpp"

using sylva::InputError;
using sylva::dem::SlopeProfile;

namespace {

const std::string kDir = std::string(SYLVAROCK_TEST_DATA) + "/dem/";
const std::string kSlopes = std::string(SYLVAROCK_DATA) + "/slopes/";

// The error that reading `file` (from tests/data/dem) must raise.
InputError readError(const std::string& file) {
    try {
        SlopeProfile::readCsv(kDir + file);
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << file << " was accepted";
    return InputError("");
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// profile_ok.csv: (0,10) (3,6) (6,6) (10,9): segments of length 5, 3 and 5 m.
SlopeProfile okProfile() { return SlopeProfile::readCsv(kDir + "profile_ok.csv"); }

}  // namespace

TEST(SlopeProfileReader, ReadsXAndZAndIgnoresOtherColumns) {
    const SlopeProfile p = okProfile();
    EXPECT_EQ(p.xs(), (std::vector<double>{0, 3, 6, 10}));
    EXPECT_EQ(p.zs(), (std::vector<double>{10, 6, 6, 9}));
    EXPECT_EQ(p.xmin(), 0.0);
    EXPECT_EQ(p.xmax(), 10.0);
}

TEST(SlopeProfileReader, MissingColumnNamesFileAndHeader) {
    const InputError e = readError("profile_missing_z.csv");
    EXPECT_EQ(e.file(), kDir + "profile_missing_z.csv");
    EXPECT_EQ(e.line(), 1);
    EXPECT_TRUE(contains(e.what(), "missing column 'z'")) << e.what();
}

TEST(SlopeProfileReader, NonNumericValueNamesLineAndText) {
    const InputError e = readError("profile_not_numeric.csv");
    EXPECT_EQ(e.line(), 4);
    EXPECT_TRUE(contains(e.what(), "'abc'")) << e.what();
}

TEST(SlopeProfileReader, XNotIncreasingNamesBothLines) {
    const InputError e = readError("profile_not_increasing.csv");
    EXPECT_EQ(e.line(), 5);  // line 4 is blank
    EXPECT_TRUE(contains(e.what(), "line 3")) << e.what();
    EXPECT_TRUE(contains(e.what(), "increase")) << e.what();
}

// profile_rising.csv ends 3 m above its start: every block would leave by its top edge and report a
// negative run-out.
TEST(SlopeProfileReader, AProfileRisingAlongXIsRefused) {
    const InputError e = readError("profile_rising.csv");
    EXPECT_EQ(e.line(), 4);
    EXPECT_TRUE(contains(e.what(), "rises along x (z 5 m at x = 0 m, 8 m at x = 20 m)")) << e.what();
}

// A NODATA value left in a profile: -9999 lies within Earth's relief, and read as ground it made a
// pit 10 km deep, run-outs of 10 km and 8 million soil spheres; 5e30 lies beyond it.
TEST(SlopeProfileReader, ANodataValueLeftInTheProfileIsRefused) {
    InputError e = readError("profile_nodata_point.csv");
    EXPECT_EQ(e.line(), 4);
    EXPECT_TRUE(contains(e.what(), "z = -9999 m at x = 300 m, beside z = 300 m at x = 200 m (line 3): a step no terrain has")) << e.what();
    e = readError("profile_off_earth.csv");
    EXPECT_EQ(e.line(), 3);
    EXPECT_TRUE(contains(e.what(), "z = 5e30 m is beyond Earth's relief")) << e.what();
    // The marker as the first point is the one named, not the ground after it.
    e = readError("profile_nodata_first.csv");
    EXPECT_EQ(e.line(), 2);
    EXPECT_TRUE(contains(e.what(), "z = -9999 m at x = 0 m, beside z = 400 m at x = 2 m (line 3)")) << e.what();
}

// A vertical cliff drawn with x barely increasing, as x must, is terrain.
TEST(SlopeProfileReader, ACliffDrawnWithATinyStepInXIsRead) {
    const SlopeProfile p = SlopeProfile::readCsv(kDir + "profile_cliff.csv");
    EXPECT_DOUBLE_EQ(p.height(100.01), 250);
}

TEST(SlopeProfileReader, OnePointIsNotAProfile) {
    const InputError e = readError("profile_one_point.csv");
    EXPECT_EQ(e.line(), 3);
    EXPECT_TRUE(contains(e.what(), "at least 2 points")) << e.what();
}

TEST(SlopeProfileReader, HeaderOnlyIsNotAProfile) {
    const InputError e = readError("profile_header_only.csv");
    EXPECT_EQ(e.file(), kDir + "profile_header_only.csv");
    EXPECT_TRUE(contains(e.what(), "at least 2 points")) << e.what();
}

TEST(SlopeProfileReader, MissingFileIsAnInputError) {
    const InputError e = readError("no_such_profile.csv");
    EXPECT_TRUE(contains(e.what(), "cannot open")) << e.what();
}

TEST(SlopeProfile, ConstructorRejectsUnusableProfiles) {
    EXPECT_THROW(SlopeProfile({0, 1, 2}, {0, 1}), InputError);
    EXPECT_THROW(SlopeProfile({0}, {0}), InputError);
    EXPECT_THROW(SlopeProfile({0, 1, 1}, {0, 1, 2}), InputError);
    EXPECT_THROW(SlopeProfile({0, 2, 1}, {0, 1, 2}), InputError);
    EXPECT_THROW(SlopeProfile({0, std::numeric_limits<double>::quiet_NaN()}, {0, 1}), InputError);
    EXPECT_THROW(SlopeProfile({0, 1}, {0, std::numeric_limits<double>::infinity()}), InputError);
}

// Expected values follow from the 3-4-5 triangles of profile_ok.csv; the only rounding is in
// divisions of small integers, hence 1e-12.
TEST(SlopeProfile, HeightInterpolatesAndExtendsTheEndSegments) {
    const SlopeProfile p = okProfile();
    EXPECT_NEAR(p.height(1.5), 8.0, 1e-12);
    EXPECT_NEAR(p.height(4.0), 6.0, 1e-12);
    EXPECT_NEAR(p.height(8.0), 7.5, 1e-12);
    EXPECT_NEAR(p.height(-3.0), 14.0, 1e-12);  // first segment falls 4 m per 3 m
    EXPECT_NEAR(p.height(14.0), 12.0, 1e-12);  // last segment rises 3 m per 4 m
}

TEST(SlopeProfile, SlopeIsPositiveDownhillAndAVertexBelongsToTheSegmentAfterIt) {
    const SlopeProfile p = okProfile();
    const double deg = 180.0 / std::acos(-1.0);
    EXPECT_NEAR(p.slopeDeg(1.0), std::atan2(4.0, 3.0) * deg, 1e-12);
    EXPECT_NEAR(p.slopeDeg(3.0), 0.0, 1e-12);
    EXPECT_NEAR(p.slopeDeg(7.0), -std::atan2(3.0, 4.0) * deg, 1e-12);
    EXPECT_NEAR(p.slopeDeg(-50.0), std::atan2(4.0, 3.0) * deg, 1e-12);
}

// segmentAt looks in equal bins along x: it must name the segment a search of every vertex names,
// on vertices, next to them, outside the profile, and where vertices crowd into one bin.
TEST(SlopeProfile, BinnedLookupFindsTheSegmentAFullSearchFinds) {
    std::vector<double> x{-3.0, 0.0, 1e-9, 2e-9, 0.5, 0.5000001, 7.0, 7.25, 100.0, 100.0 + 1e-7, 1000.0};
    const SlopeProfile p(x, std::vector<double>(x.size(), 0.0));
    const auto search = [&](double q) {
        const auto past = std::upper_bound(x.begin(), x.end(), q);
        const std::size_t i = past == x.begin() ? 0 : static_cast<std::size_t>(past - x.begin()) - 1;
        return std::min(i, x.size() - 2);
    };
    std::vector<double> queries{-1e9, 2e9, std::nan("")};
    for (const double v : x)
        for (const double q : {v, std::nextafter(v, -1e300), std::nextafter(v, 1e300), v - 1e-6, v + 1e-6}) queries.push_back(q);
    for (int i = 0; i <= 20000; ++i) queries.push_back(-10.0 + 1020.0 * i / 20000);
    for (const double q : queries) EXPECT_EQ(p.segmentAt(q), search(q)) << q;
}

TEST(SlopeProfile, AbscissaIsTheArcLength) {
    const SlopeProfile p = okProfile();
    EXPECT_NEAR(p.abscissa(0.0), 0.0, 1e-12);
    EXPECT_NEAR(p.abscissa(1.5), 2.5, 1e-12);
    EXPECT_NEAR(p.abscissa(3.0), 5.0, 1e-12);
    EXPECT_NEAR(p.abscissa(6.0), 8.0, 1e-12);
    EXPECT_NEAR(p.abscissa(10.0), 13.0, 1e-12);
    EXPECT_NEAR(p.length(), 13.0, 1e-12);
    EXPECT_NEAR(p.abscissa(-3.0), -5.0, 1e-12);
    EXPECT_NEAR(p.abscissa(14.0), 18.0, 1e-12);
}

namespace {

const char* const kCandidates[] = {"standin-s0.4.csv", "standin-s0.6.csv", "standin-s0.8.csv", "standin-s1.0.csv"};
const double kSigmas[] = {0.4, 0.6, 0.8, 1.0};
constexpr double kRelease = 100.0;

// z of a candidate minus z of the smooth mean shape, at x >= the release point.
std::vector<double> residualBelowRelease(const SlopeProfile& noisy, const SlopeProfile& smooth) {
    std::vector<double> r;
    for (std::size_t i = 0; i < noisy.xs().size(); ++i)
        if (noisy.xs()[i] >= kRelease) r.push_back(noisy.zs()[i] - smooth.zs()[i]);
    return r;
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace

TEST(StandinSlope, EveryFileIs630MetresAt2MetreResolution) {
    for (const std::string name : {"standin-smooth.csv", "standin-s0.4.csv", "standin-s0.6.csv", "standin-s0.8.csv",
                                   "standin-s1.0.csv"}) {
        const SlopeProfile p = SlopeProfile::readCsv(kSlopes + name);
        ASSERT_EQ(p.xs().size(), 316u) << name;
        for (std::size_t i = 0; i < p.xs().size(); ++i) EXPECT_EQ(p.xs()[i], 2.0 * i) << name;
    }
}

// The issue asks for a 38-40 deg upper talus, a ~30-32 deg middle slope, a ~25 deg lower slope
// and a 10-15 deg foot, falling monotonically, release on the talus.
TEST(StandinSlope, SmoothShapeHasTheRequestedSegments) {
    const SlopeProfile p = SlopeProfile::readCsv(kSlopes + "standin-smooth.csv");
    struct Band {
        double lo, hi;
    };
    std::vector<Band> sections;  // angle bands met in order down the slope
    for (std::size_t i = 0; i + 1 < p.xs().size(); ++i) {
        const double a = p.slopeDeg(p.xs()[i]);
        ASSERT_GT(a, 0.0) << "x = " << p.xs()[i];
        const Band band = a >= 38.0 && a <= 40.0   ? Band{38, 40}
                          : a >= 30.0 && a <= 32.0 ? Band{30, 32}
                          : a >= 24.0 && a <= 26.0 ? Band{24, 26}
                          : a >= 10.0 && a <= 15.0 ? Band{10, 15}
                                                   : Band{0, 0};
        ASSERT_GT(band.hi, 0.0) << "x = " << p.xs()[i] << ": " << a << " deg is in none of the requested bands";
        if (sections.empty() || sections.back().lo != band.lo) sections.push_back(band);
        if (p.xs()[i] < 130.0) {
            EXPECT_EQ(band.lo, 38.0) << "release and forest edge lie on the upper talus";
        }
    }
    ASSERT_EQ(sections.size(), 4u) << "upper talus, middle, lower slope and foot, in that order";
    EXPECT_EQ(sections[0].lo, 38.0);
    EXPECT_EQ(sections[1].lo, 30.0);
    EXPECT_EQ(sections[2].lo, 24.0);
    EXPECT_EQ(sections[3].lo, 10.0);
}

TEST(StandinSlope, NoPitAboveTheReleasePoint) {
    const SlopeProfile smooth = SlopeProfile::readCsv(kSlopes + "standin-smooth.csv");
    for (const char* name : kCandidates) {
        const SlopeProfile p = SlopeProfile::readCsv(kSlopes + name);
        EXPECT_EQ(p.zs().front(), smooth.zs().front()) << name << ": the noise is tapered to 0 at the top";
        for (std::size_t i = 1; p.xs()[i] <= kRelease; ++i)
            EXPECT_LT(p.zs()[i], p.zs()[i - 1]) << name << ": z rises at x = " << p.xs()[i];
    }
}

// AR(1) with correlation length 6 m sampled every 2 m: lag-1 correlation rho = exp(-1/3).
// 266 values from x = 100 m: the standard error of the lag-1 correlation is about
// sqrt((1 - rho^2) / n) = 0.043, and that of the sample s.d. about 8 % of sigma (effective sample
// n (1 - rho^2) / (1 + rho^2) = 85 for a variance); the bounds are 3 standard errors.
TEST(StandinSlope, MicroTopographyHasTheRequestedSigmaAndCorrelation) {
    const SlopeProfile smooth = SlopeProfile::readCsv(kSlopes + "standin-smooth.csv");
    const double rho = std::exp(-2.0 / 6.0);
    for (std::size_t c = 0; c < 4; ++c) {
        const auto r = residualBelowRelease(SlopeProfile::readCsv(kSlopes + kCandidates[c]), smooth);
        double mean = 0.0;
        for (double v : r) mean += v / r.size();
        double var = 0.0, cov = 0.0;
        for (std::size_t i = 0; i < r.size(); ++i) {
            var += (r[i] - mean) * (r[i] - mean);
            if (i + 1 < r.size()) cov += (r[i] - mean) * (r[i + 1] - mean);
        }
        const double sd = std::sqrt(var / r.size());
        EXPECT_NEAR(sd / kSigmas[c], 1.0, 0.25) << kCandidates[c];
        EXPECT_NEAR(cov / var, rho, 0.13) << kCandidates[c];
    }
}

// The candidates share one noise pattern scaled by sigma, so that sigma is the only thing the
// calibration changes. Each residual carries two roundings to 1 mm (at most 1e-3 m together):
// residual / sigma may differ by 1e-3 / 0.4 + 1e-3 / 1.0 = 3.5e-3 between two files.
TEST(StandinSlope, CandidatesDifferOnlyBySigma) {
    const SlopeProfile smooth = SlopeProfile::readCsv(kSlopes + "standin-smooth.csv");
    const auto base = residualBelowRelease(SlopeProfile::readCsv(kSlopes + kCandidates[0]), smooth);
    for (std::size_t c = 1; c < 4; ++c) {
        const auto r = residualBelowRelease(SlopeProfile::readCsv(kSlopes + kCandidates[c]), smooth);
        ASSERT_EQ(r.size(), base.size());
        for (std::size_t i = 0; i < r.size(); ++i)
            EXPECT_NEAR(r[i] / kSigmas[c], base[i] / kSigmas[0], 3.5e-3) << kCandidates[c] << " point " << i;
    }
}

// The generator must rebuild the committed files byte for byte (README's commands).
TEST(StandinSlope, GeneratorRebuildsTheFilesExactly) {
    if (std::system("python3 -c 'import sys' > /dev/null 2>&1") != 0) GTEST_SKIP() << "python3 not available";
    const std::string out = ::testing::TempDir() + "standin-rebuilt.csv";
    const std::vector<std::pair<std::string, std::string>> files = {
        {"0", "standin-smooth.csv"}, {"0.4", "standin-s0.4.csv"}, {"0.6", "standin-s0.6.csv"},
        {"0.8", "standin-s0.8.csv"}, {"1.0", "standin-s1.0.csv"}};
    for (const auto& [sigma, name] : files) {
        const std::string cmd = "python3 '" + kSlopes + "make_standin.py' --sigma " + sigma + " --seed 1 --out '" + out + "'";
        ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
        EXPECT_TRUE(slurp(out) == slurp(kSlopes + name)) << name << " differs from: " << cmd;
    }
    const std::string cmd = "python3 '" + kSlopes + "make_standin.py' --dtm --out '" + out + "'";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    EXPECT_TRUE(slurp(out) == slurp(kSlopes + "example-dtm.asc")) << "example-dtm.asc differs from: " << cmd;
    std::remove(out.c_str());
}

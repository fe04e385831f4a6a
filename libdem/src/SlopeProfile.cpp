#include "libdem/SlopeProfile.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "libcommon/CsvTable.hpp"
#include "libcommon/InputError.hpp"
#include "libdem/EarthRelief.hpp"

namespace sylva::dem {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Index of the first point whose x is not greater than the previous one, or 0 if x increases
// strictly (index 0 can never be the culprit). Shared by the constructor and the reader so that
// both apply the same rule; the reader turns the index into a line number.
std::size_t firstNonIncreasing(const std::vector<double>& x) {
    for (std::size_t i = 1; i < x.size(); ++i)
        if (!(x[i] > x[i - 1])) return i;
    return 0;
}

std::string str(double v) {
    std::ostringstream os;
    os << std::setprecision(12) << v;
    return os.str();
}

}  // namespace

SlopeProfile::SlopeProfile(std::vector<double> x, std::vector<double> z) : x_(std::move(x)), z_(std::move(z)) {
    if (x_.size() != z_.size())
        throw InputError("slope profile: " + std::to_string(x_.size()) + " x values but " +
                         std::to_string(z_.size()) + " z values");
    if (x_.size() < 2)
        throw InputError("slope profile: needs at least 2 points, has " + std::to_string(x_.size()));
    for (std::size_t i = 0; i < x_.size(); ++i)
        if (!std::isfinite(x_[i]) || !std::isfinite(z_[i]))
            throw InputError("slope profile: point " + std::to_string(i) + " is not finite");
    if (const std::size_t i = firstNonIncreasing(x_))
        throw InputError("slope profile: x must increase strictly, but point " + std::to_string(i) + " (x = " +
                         str(x_[i]) + ") follows x = " + str(x_[i - 1]));
    s_.resize(x_.size());
    s_[0] = 0.0;
    for (std::size_t i = 1; i < x_.size(); ++i) s_[i] = s_[i - 1] + std::hypot(x_[i] - x_[i - 1], z_[i] - z_[i - 1]);
    const std::size_t segments = x_.size() - 1;
    binsPerMetre_ = 2.0 * static_cast<double>(segments) / (x_.back() - x_.front());
    bin_.resize(2 * segments + 2);
    for (std::size_t b = 0; b < bin_.size(); ++b) {
        const double start = x_.front() + static_cast<double>(b) / binsPerMetre_;
        const auto past = static_cast<std::size_t>(std::upper_bound(x_.begin(), x_.end(), start) - x_.begin());
        bin_[b] = past >= 2 ? past - 2 : 0;
    }
}

SlopeProfile SlopeProfile::readCsv(const std::string& path) {
    const CsvTable t = CsvTable::read(path);
    const std::size_t cx = t.require("x"), cz = t.require("z");
    std::vector<double> x, z;
    x.reserve(t.rows());
    z.reserve(t.rows());
    for (std::size_t r = 0; r < t.rows(); ++r) {
        x.push_back(t.number(r, cx));
        z.push_back(t.number(r, cz));
    }
    if (t.rows() == 1) t.fail(0, "a slope profile needs at least 2 points, the file has only this one");
    if (t.rows() == 0) throw InputError(path, 0, "a slope profile needs at least 2 points, the file has none");
    if (const std::size_t i = firstNonIncreasing(x))
        t.fail(i, cx,
               "x = " + t.text(i, cx) + " does not increase (previous point, line " + std::to_string(t.lineOf(i - 1)) +
                   ", has x = " + t.text(i - 1, cx) + "); x must increase strictly");
    for (std::size_t i = 0; i < z.size(); ++i)
        if (!onEarth(z[i])) t.fail(i, cz, "z = " + t.text(i, cz) + " m is beyond " + kEarthsRelief + ": a NODATA value left in the profile? Remove the point");
    for (std::size_t i = 1; i < z.size(); ++i)
        if (impossibleStep(z[i] - z[i - 1], x[i] - x[i - 1])) {
            const std::size_t low = z[i] < z[i - 1] ? i : i - 1, other = low == i ? i - 1 : i;  // the marker is the lower
            t.fail(low, cz,
                   "z = " + t.text(low, cz) + " m at x = " + t.text(low, cx) + " m, beside z = " + t.text(other, cz) + " m at x = " +
                       t.text(other, cx) + " m (line " + std::to_string(t.lineOf(other)) +
                       "): " + kImpossibleStep + "; a NODATA value left in the profile? Remove the point");
        }
    // Run-out is measured down the slope along +x: a profile climbing with x sends every block off its top edge.
    if (z.back() > z.front())
        t.fail(t.rows() - 1, cz,
               "the profile rises along x (z " + t.text(0, cz) + " m at x = " + t.text(0, cx) + " m, " + t.text(t.rows() - 1, cz) +
                   " m at x = " + t.text(t.rows() - 1, cx) + " m): blocks run out along +x, downhill; give it falling with x");
    return SlopeProfile(std::move(x), std::move(z));
}

std::size_t SlopeProfile::segmentAt(double x) const {
    // The first vertex past x lies in (lo, hi]; outside the bins (or for NaN) anywhere after the first.
    std::size_t lo = 0, hi = x_.size() - 1;
    const double u = (x - x_.front()) * binsPerMetre_;
    if (u >= 0 && u < static_cast<double>(bin_.size() - 1)) {
        const auto b = static_cast<std::size_t>(u);
        lo = bin_[b];
        hi = std::min(bin_[b + 1] + 3, hi);
    }
    const auto past = std::upper_bound(x_.begin() + static_cast<std::ptrdiff_t>(lo) + 1,
                                       x_.begin() + static_cast<std::ptrdiff_t>(hi) + 1, x);
    return std::min(static_cast<std::size_t>(past - x_.begin()) - 1, x_.size() - 2);
}

double SlopeProfile::height(double x) const {
    const std::size_t i = segmentAt(x);
    const double t = (x - x_[i]) / (x_[i + 1] - x_[i]);
    return z_[i] + t * (z_[i + 1] - z_[i]);
}

double SlopeProfile::slopeDeg(double x) const {
    const std::size_t i = segmentAt(x);
    return std::atan2(z_[i] - z_[i + 1], x_[i + 1] - x_[i]) * 180.0 / kPi;
}

double SlopeProfile::abscissa(double x) const {
    const std::size_t i = segmentAt(x);
    const double t = (x - x_[i]) / (x_[i + 1] - x_[i]);
    return s_[i] + t * (s_[i + 1] - s_[i]);
}

}  // namespace sylva::dem

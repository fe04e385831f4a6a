#include "libstand/Allometry.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sylva::stand {

namespace {
// Eq. 11 is a parabola in D (m) whose vertex is at D = 73.805 / (2 * 54.734) = 0.6742 m. Beyond it
// the fit (made on beech of ordinary sizes) would make thicker trees shorter, and below 1.3 m for
// D > 1.35 m; we hold H_T at the vertex value there (docs/stand.md, "Virtual forests").
constexpr double kLinear = 73.805;     // Eq. 11
constexpr double kQuadratic = 54.734;  // Eq. 11
constexpr double kVertexDiameterM = kLinear / (2 * kQuadratic);
}  // namespace

double treeHeightM(double dbhCm) {
    const double d = std::min(dbhCm / 100.0, kVertexDiameterM);
    return 1.3 + kLinear * d - kQuadratic * d * d;  // Eq. 11, D_stem in m
}

double crownLengthM(double heightM) { return 0.40642 * heightM; }  // Eq. 12

double crownMassKg(double dbhCm) { return 0.0031 * std::pow(dbhCm, 3.161); }  // Eq. 13 (Bartelink 1997), D_stem in cm

std::string dbhProblem(double dbhCm) {
    std::ostringstream os;
    os << "DBH " << dbhCm << " cm";
    if (!(dbhCm > 0)) return os.str() + " is not positive";
    if (dbhCm > kLargestDbhCm) return os.str() + " is above " + std::to_string(int(kLargestDbhCm)) + " cm: diameters in mm?";
    return {};
}

}  // namespace sylva::stand

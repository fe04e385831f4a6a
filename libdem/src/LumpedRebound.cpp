#include "libdem/LumpedRebound.hpp"

#include <algorithm>
#include <cmath>

namespace sylva::dem {

LumpedRebound::LumpedRebound(const LumpedParams& params, double blockRadius)
    : p_(params), soil_(soilRestitution(params.soilType)), radius_(blockRadius) {}

double LumpedRebound::tangentialRestitution(double obstacleHeight) const {
    return 1 / (1 + obstacleHeight / radius_);
}

Vec3 LumpedRebound::apply(const Vec3& v, const Vec3& n, SeededRandom& rng) const {
    // The obstacle met: rg70 in 70 % of the rebounds, rg20 in 20 %, rg10 in 10 %.
    const double u = rng.uniform(0, 1);
    const double h = std::min(u < 0.7 ? p_.rg70 : u < 0.9 ? p_.rg20 : p_.rg10, radius_);
    const double rn = soil_.mean + rng.uniform(-soil_.halfRange, soil_.halfRange);
    const double vn = v.dot(n);
    Vec3 vt = tangentialRestitution(h) * (v - vn * n);
    // A sphere rolling onto an obstacle of height h is turned up by the angle a, cos a = 1 - h/R,
    // of the obstacle's edge: rolling is a succession of such small rebounds, not a slide.
    const double sinA = std::sqrt(std::max(0.0, 1 - std::pow(1 - h / radius_, 2)));
    const double lift = rn * std::max(std::abs(vn), sinA * vt.norm());
    const double turn = rng.gaussian(p_.deviationSdDeg * M_PI / 180);
    vt = Eigen::AngleAxisd(turn, n) * vt;
    return vt + lift * n;
}

}  // namespace sylva::dem

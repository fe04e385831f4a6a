#include "libdem/LumpedTreeImpact.hpp"

#include <algorithm>
#include <cmath>

namespace sylva::dem {

// Dorren & Berger (2006, Tree Physiol. 26: 63-71): the energy a tree dissipates before it breaks or
// is uprooted, E = 38.7 DBH^2.31 J with DBH in cm.
double LumpedTreeImpact::capacity(double dbh) const {
    return p_.treeEnergyScale * 38.7 * std::pow(100 * dbh, 2.31);
}

double LumpedTreeImpact::eccentricityShare(double e) {
    const double a = std::min(1.0, std::abs(e));
    return a <= 1.0 / 3 ? 1.0 : 1.5 * (1 - a);
}

LumpedTreeImpact::Outcome LumpedTreeImpact::apply(const Vec3& v, double dbh, double eccentricity, double /*height*/,
                                                  double mass, SeededRandom& rng) const {
    const double energy = 0.5 * mass * v.squaredNorm();
    const double taken = eccentricityShare(eccentricity) * capacity(dbh);
    if (taken >= energy) return {Vec3::Zero(), false};
    // The energy taken comes off every component in proportion (the paper's Sect. 2.3.1); the path
    // turns away from the stem, more for a lateral impact. A block on the left of the stem (e > 0,
    // left of its direction of travel) turns further left: counter-clockwise, a positive angle about z.
    const double maxTurn = (std::abs(eccentricity) <= 1.0 / 3 ? 22.5 : 60.0) * M_PI / 180;
    const double side = eccentricity >= 0 ? 1 : -1;
    const double turn = side * rng.uniform(0, maxTurn);
    const Vec3 out = Eigen::AngleAxisd(turn, Vec3::UnitZ()) * v * std::sqrt(1 - taken / energy);
    return {out, true};
}

}  // namespace sylva::dem

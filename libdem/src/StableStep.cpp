#include "libdem/StableStep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sylva::dem {

void StableStep::add(double stiffness, double dampingCoefficient, double inverseMass) {
    if (stiffness <= 0 || inverseMass <= 0) return;
    omega2_ += stiffness * inverseMass;
    gamma_ += dampingCoefficient * inverseMass;
}

double StableStep::critical() const {
    if (omega2_ <= 0) return std::numeric_limits<double>::infinity();
    const double omega = std::sqrt(omega2_), zeta = gamma_ / (2 * omega);
    return 2.0 / omega * (std::sqrt(1 + zeta * zeta) - zeta);
}

}  // namespace sylva::dem

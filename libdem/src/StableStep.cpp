#include "libdem/StableStep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sylva::dem {

void StableStep::add(double stiffness, double dampingCoefficient, double inverseMass) {
    if (stiffness <= 0 || inverseMass <= 0) return;
    omega2_ += stiffness * inverseMass;
    zeta_ = std::max(zeta_, dampingCoefficient * std::sqrt(inverseMass) / (2 * std::sqrt(stiffness)));
}

double StableStep::critical() const {
    if (omega2_ <= 0) return std::numeric_limits<double>::infinity();
    return 2.0 / std::sqrt(omega2_) * (std::sqrt(1 + zeta_ * zeta_) - zeta_);
}

}  // namespace sylva::dem

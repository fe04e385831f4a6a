#include "libdem/BendingDamping.hpp"

#include <cmath>

namespace sylva::dem {

namespace {
constexpr double kPi = 3.14159265358979323846;
// Sum over branches one decade apart of omega tau / (1 + omega^2 tau^2), averaged over log(omega):
// the integral of x / (1 + x^2) d(log10 x) = pi / (2 ln 10).
const double kLossPerUnitBranchStiffness = kPi / (2 * std::log(10.0));

const std::array<double, BendingDamping::kBranches> kRelaxationTimes = [] {
    std::array<double, BendingDamping::kBranches> tau{};
    for (int b = 0; b < BendingDamping::kBranches; ++b) tau[b] = BendingDamping::kTauMax * std::pow(10.0, -b);
    return tau;
}();
}  // namespace

double BendingDamping::relaxationTime(int branch) { return kRelaxationTimes[branch]; }

BendingDamping::Decay BendingDamping::decayOver(double dt) {
    Decay d;
    d.dt = dt;
    for (int b = 0; b < kBranches; ++b) d.factor[b] = std::exp(-dt / kRelaxationTimes[b]);
    return d;
}

BendingDamping::BendingDamping(const BendingParams& p, const HingeCoefficients& k) {
    for (auto& m : branch_) m.setZero();
    if (p.damping == StemDamping::Viscous) {
        viscosity_ = k.viscosity;  // Eqs. 7-8
    } else {
        // eta = Im / Re of K (1 + sum g i w tau / (1 + i w tau)): across the band about half the
        // branches act as springs and stiffen the real part by 1 + (kBranches / 2) g.
        const double g = p.lossFactor / (kLossPerUnitBranchStiffness - 0.5 * kBranches * p.lossFactor);
        branchStiffness_ = g * k.elastic;
    }
}

BendingDamping::Step BendingDamping::advance(const Vec2& rate, const Decay& d) {
    const double dt = d.dt;
    Step s;
    if (viscosity_ > 0) {
        s.moment = viscosity_ * rate;  // Eqs. 7-8
        s.dissipated = s.moment.dot(rate) * dt;
        return s;
    }
    if (branchStiffness_ <= 0) return s;
    // Branch: dm/dt = K r - m / tau, exact for r constant over the step, r being the rate at the
    // step's middle (the leapfrog's velocities) and the step ending where the nodes now are. Its
    // work r . int m dt goes into its spring or is dissipated. The nodes feel the branches' moment at
    // the step's end, where they are: the step's mean would lag half a step behind their rotation,
    // and a spring that lags pumps energy in.
    double work = 0, storedChange = 0;
    for (int b = 0; b < kBranches; ++b) {
        const double tau = kRelaxationTimes[b];
        const double decay = d.factor[b];
        const Vec2 settled = branchStiffness_ * tau * rate;  // m for a steady rate
        const Vec2 before = branch_[b];
        const Vec2 integral = settled * dt + (before - settled) * (tau * (1 - decay));
        branch_[b] = settled + (before - settled) * decay;
        s.moment += branch_[b];
        work += rate.dot(integral);
        storedChange += (branch_[b].squaredNorm() - before.squaredNorm()) / (2 * branchStiffness_);
    }
    s.dissipated = work - storedChange;
    return s;
}

double BendingDamping::storedEnergy() const {
    if (branchStiffness_ <= 0) return 0;
    double e = 0;
    for (const Vec2& m : branch_) e += m.squaredNorm();
    return e / (2 * branchStiffness_);
}

double BendingDamping::release() {
    const double e = storedEnergy();
    for (auto& m : branch_) m.setZero();
    viscosity_ = 0;
    branchStiffness_ = 0;
    return e;
}

}  // namespace sylva::dem

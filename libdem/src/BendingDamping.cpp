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
    for (int b = 0; b < kBranches; ++b) {
        d.factor[b] = std::exp(-dt / kRelaxationTimes[b]);
        d.lag[b] = kRelaxationTimes[b] * (1 - d.factor[b]);
        d.settled += dt * kRelaxationTimes[b];
    }
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
        halfBranchCompliance_ = 0.5 / branchStiffness_;
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
    const Vec2 steady = branchStiffness_ * rate;
    Vec2 integral = d.settled * steady;
    double squares = 0;
    for (int b = 0; b < kBranches; ++b) {
        const Vec2 settled = kRelaxationTimes[b] * steady;  // m for a steady rate
        const Vec2 offset = branch_[b] - settled;
        integral += offset * d.lag[b];
        branch_[b] = settled + offset * d.factor[b];
        s.moment += branch_[b];
        squares += branch_[b].squaredNorm();
    }
    const double stored = squares * halfBranchCompliance_;
    s.dissipated = rate.dot(integral) - (stored - stored_);
    stored_ = stored;
    return s;
}

double BendingDamping::release() {
    const double e = stored_;
    stored_ = 0;
    for (auto& m : branch_) m.setZero();
    viscosity_ = 0;
    branchStiffness_ = 0;
    return e;
}

}  // namespace sylva::dem

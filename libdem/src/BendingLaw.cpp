#include "libdem/BendingLaw.hpp"

#include <cmath>

namespace sylva::dem {

namespace {
const double kPi = std::acos(-1.0);
}  // namespace

HingeCoefficients bendingCoefficients(const BendingParams& p, double diameter, double length) {
    const double inertia = kPi * std::pow(diameter, 4) / 64;  // I of the section, m^4
    HingeCoefficients k;
    k.elastic = p.moe * inertia / length;                        // Eq. 2
    k.plastic = p.ePlast * inertia / length;                     // Eq. 3
    k.unloading = p.eUnld * inertia / length;                    // Eq. 4
    k.yieldMoment = p.sigmaElast * inertia * 2 / diameter;       // Eq. 5
    k.ruptureMoment = p.sigmaRupt * inertia * 2 / diameter;      // Eq. 6
    k.viscosity = p.tau * k.elastic;                             // Eqs. 7-8
    return k;
}

BendingLaw::BendingLaw(const HingeCoefficients& k, BendingReading reading)
    : k_(k), reading_(reading), channels_{{k.yieldMoment}, {k.yieldMoment}} {}

HingeWork BendingLaw::rotate(const Vec2& dTheta) {
    if (broken_) return {};
    if (reading_ == BendingReading::Isotropic) {
        Moment m = moment_, d = dTheta;
        const HingeWork w = advance(m, d, channels_[0]);
        moment_ = broken_ ? Vec2::Zero() : Vec2(m);
        return w;
    }
    HingeWork total;
    for (int axis = 0; axis < 2 && !broken_; ++axis) {
        Moment m(1), d(1);
        m << moment_[axis];
        d << dTheta[axis];
        const HingeWork w = advance(m, d, channels_[axis]);
        moment_[axis] = m[0];
        total.dissipated += w.dissipated;
        total.created += w.created;
        total.released += w.released;
    }
    if (broken_) {
        // The other axis' stored energy goes with the connection too.
        total.released += storedEnergy();
        moment_.setZero();
    }
    return total;
}

// An elastic trial with the current stiffness; what lies beyond the elastic domain |M| <= M_y is
// rotation along the plastic branch, where dM = K_Plast dtheta (Eq. 3) and the domain grows with the
// moment (unloading and reloading then follow K_Unld up to the largest moment reached, Fig. 3).
// In one dimension this is the closed-form trilinear path, whatever the size of the increment.
HingeWork BendingLaw::advance(Moment& m, const Moment& d, Channel& ch) {
    const double k = stiffness(ch);
    const Moment trial = m + k * d;
    const double t = trial.norm();
    if (t <= ch.yieldMoment) {
        m = trial;
        return {};
    }
    HingeWork w;
    if (!ch.yielded) {
        w.created = 0.5 * ch.yieldMoment * ch.yieldMoment * (1 / k_.unloading - 1 / k_.elastic);
        ch.yielded = true;
    }
    // Plastic rotation delta from moment M0 along K_Plast: the work M0 delta + K_Plast delta^2 / 2
    // minus the growth of the energy recoverable along K_Unld.
    const auto plasticWork = [this](double m0, double delta) {
        return delta * (m0 + 0.5 * k_.plastic * delta) * (1 - k_.plastic / k_.unloading);
    };
    const double delta = (t - ch.yieldMoment) / k;
    const double reached = ch.yieldMoment + k_.plastic * delta;
    if (reached >= k_.ruptureMoment) {
        w.dissipated = plasticWork(ch.yieldMoment, (k_.ruptureMoment - ch.yieldMoment) / k_.plastic);
        w.released = 0.5 * k_.ruptureMoment * k_.ruptureMoment / k_.unloading;
        broken_ = true;
        m.setZero();
        return w;
    }
    w.dissipated = plasticWork(ch.yieldMoment, delta);
    ch.yieldMoment = reached;
    m = trial * (reached / t);
    return w;
}

HingeWork BendingLaw::snap() {
    HingeWork w;
    if (broken_) return w;
    w.released = storedEnergy();
    broken_ = true;
    moment_.setZero();
    return w;
}

double BendingLaw::storedEnergy() const {
    if (reading_ == BendingReading::Isotropic) return 0.5 * moment_.squaredNorm() / stiffness(channels_[0]);
    return 0.5 * (moment_[0] * moment_[0] / stiffness(channels_[0]) + moment_[1] * moment_[1] / stiffness(channels_[1]));
}

}  // namespace sylva::dem

#include "libdem/BendingLaw.hpp"

#include <algorithm>
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

HingeWork BendingLaw::rotate(const Vec2& dTheta, const Vec2& offset) {
    if (broken_) return {};
    if (reading_ == BendingReading::Isotropic) {
        Moment m = moment_, d = dTheta, o = offset;
        const HingeWork w = advance(m, d, o, channels_[0]);
        moment_ = broken_ ? Vec2::Zero() : Vec2(m);
        return w;
    }
    HingeWork total;
    for (int axis = 0; axis < 2 && !broken_; ++axis) {
        Moment m(1), d(1), o(1);
        m << moment_[axis];
        d << dTheta[axis];
        o << offset[axis];
        const HingeWork w = advance(m, d, o, channels_[axis]);
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

// An elastic trial with the current stiffness; what takes the critical section (the connection's
// moment plus `offset`) beyond its elastic domain |M| <= M_y is rotation along the plastic branch,
// where the section's moment grows as dM = K_Plast dtheta (Eq. 3) and the domain grows with it
// (unloading and reloading then follow K_Unld up to the largest moment reached, Fig. 3). With no
// offset, in one dimension, this is the closed-form trilinear path whatever the size of the increment.
// The energy is booked from the connection's own moment (the one its nodes feel): the work along the
// elastic piece up to the yield point and along the plastic piece, less what the connection stores.
// The offset may change between increments with no rotation at all; the return onto the yield
// surface then dissipates exactly the stored energy it removes.
HingeWork BendingLaw::advance(Moment& m, const Moment& d, const Moment& offset, Channel& ch) {
    const double k = stiffness(ch);
    const Moment trial = m + k * d;
    const double t = (trial + offset).norm();
    if (t <= ch.yieldMoment) {
        m = trial;
        return {};
    }
    // Fraction s of the increment taken elastically before the section reaches its yield moment.
    const Moment a = m + offset, b = k * d;
    double s = 0;
    if (a.norm() < ch.yieldMoment) {
        const double bb = b.squaredNorm(), ab = a.dot(b), aa = a.squaredNorm();
        s = (-ab + std::sqrt(std::max(0.0, ab * ab - bb * (aa - ch.yieldMoment * ch.yieldMoment)))) / bb;
    }
    const Moment atYield = m + s * b;
    const Moment n = (trial + offset) / t;
    HingeWork w;
    if (!ch.yielded) {
        w.created = 0.5 * atYield.squaredNorm() * (1 / k_.unloading - 1 / k_.elastic);
        ch.yielded = true;
    }
    const double storedBefore = 0.5 * m.squaredNorm() / k;
    const double elasticWork = 0.5 * (m + atYield).dot(s * d);
    const double delta = (t - ch.yieldMoment) / k;  // rotation beyond the yield point
    double reached = ch.yieldMoment + k_.plastic * delta;
    double used = 1 - s;  // of the increment, along the plastic branch
    if (reached >= k_.ruptureMoment) {
        used *= (k_.ruptureMoment - ch.yieldMoment) / (reached - ch.yieldMoment);
        reached = k_.ruptureMoment;
        broken_ = true;
    }
    const Moment after = n * reached - offset;
    const double plasticWork = 0.5 * (atYield + after).dot(used * d);
    const double storedAfter = 0.5 * after.squaredNorm() / k_.unloading;
    w.dissipated = elasticWork + plasticWork - (storedAfter - storedBefore) + w.created;
    if (broken_) {
        w.released = storedAfter;
        m.setZero();
        return w;
    }
    ch.yieldMoment = reached;
    m = after;
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

Vec2 BendingLaw::dampingMoment(const Vec2& relativeRate) const {
    return broken_ ? Vec2::Zero() : Vec2(k_.viscosity * relativeRate);  // Eqs. 7-8
}

double BendingLaw::storedEnergy() const {
    if (reading_ == BendingReading::Isotropic) return 0.5 * moment_.squaredNorm() / stiffness(channels_[0]);
    return 0.5 * (moment_[0] * moment_[0] / stiffness(channels_[0]) + moment_[1] * moment_[1] / stiffness(channels_[1]));
}

}  // namespace sylva::dem

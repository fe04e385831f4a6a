#include "libdem/SoilContact.hpp"

#include <algorithm>
#include <cmath>

#include "libcommon/InputError.hpp"

namespace sylva::dem {

double dampingRatioFromRestitution(double en) {
    const double l = std::log(en);
    return -l / std::sqrt(M_PI * M_PI + l * l);  // Eq. 15
}

double restitutionFromDampingRatio(double ratio) {
    return std::exp(-M_PI * ratio / std::sqrt(1 - ratio * ratio));  // Eq. 15 inverted (ratio < 1)
}

SoilContact::SoilContact(const SoilContactParams& p, double blockMass)
    : kn_(p.kn),
      kt_(p.kappa * p.kn),                                          // Eq. 19
      alpha_(p.dampingRatio * 2.0 * std::sqrt(p.kn * blockMass)),   // Eqs. 15-16
      ratio_(p.dampingRatio),
      tanPhi_(std::tan(p.frictionDeg * M_PI / 180)),
      dashpotPulls_(p.dashpotPulls) {
    if (!(p.kn > 0)) throw InputError("soil.kn must be positive");
    if (!(p.kappa > 0)) throw InputError("soil.kappa must be positive");
    if (!(p.dampingRatio >= 0 && p.dampingRatio < 1))
        throw InputError("soil.damping_ratio (alpha/alpha_cr) must be in [0, 1)");
    if (!(p.frictionDeg >= 0 && p.frictionDeg < 90)) throw InputError("soil.friction_deg must be in [0, 90)");
}

// Eq. 16 with the mass at this contact when it is not the block's (a stem node on the soil).
double SoilContact::dampingCoefficientAt(const ContactGeometry& g) const {
    return g.movingMass > 0 ? ratio_ * 2.0 * std::sqrt(kn_ * g.movingMass) : alpha_;
}

Vec3 SoilContact::force(const ContactGeometry& g, ContactHistory& h, double dt, DissipationLedger& ledger) const {
    const double overlapRate = -g.normal.dot(g.relativeVelocity);  // dU_n/dt > 0 while approaching
    // Eq. 14 as written: the dashpot acts on loading and unloading alike, so near the end of a
    // rebound it may pull; this is the law whose restitution is exactly Eq. 15's e_n. With
    // dashpotPulls = false the normal force is floored at zero, as Yade's viscoelastic law does
    // (docs/model.md compares the two readings).
    const double spring = kn_ * g.overlap;
    const double alpha = dampingCoefficientAt(g);
    const double fn = dashpotPulls_ ? spring + alpha * overlapRate : std::max(0.0, spring + alpha * overlapRate);
    // Work of the dashpot over the last step: the mean of the forces applied before and after it
    // (trapezoid, as the leapfrog applies them; each along its own normal, which turns as the block
    // slides over the soil sphere: one shared normal would book a first-order error) times the
    // contact point's displacement. Its force is what the contact applies beyond the spring: once the
    // floor clips it, only -K_n U_n of it acts, and booking alpha U_n' would count dissipation that
    // never happened (issue 17).
    const Vec3 damping = (fn - spring) * g.normal;
    ledger.contactDamping -= 0.5 * (h.dampingForce + damping).dot(g.relativeVelocity) * dt;
    h.dampingForce = damping;
    const Vec3 ft = updateShearForce(g, h, kt_, fn, tanPhi_, dt, ledger);  // Eqs. 17-19
    return fn * g.normal + ft;
}

double SoilContact::storedEnergy(const ContactGeometry& g, const ContactHistory& h) const {
    return 0.5 * kn_ * g.overlap * g.overlap + 0.5 * h.shearForce.squaredNorm() / kt_;
}

}  // namespace sylva::dem

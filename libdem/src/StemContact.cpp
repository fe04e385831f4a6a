#include "libdem/StemContact.hpp"

#include <cmath>
#include <limits>

#include "libcommon/InputError.hpp"

namespace sylva::dem {

namespace {
double tanDeg(double deg) { return std::tan(deg * M_PI / 180); }

// Eqs. 20-21 (elastic normal force) with the tangential spring of Eqs. 17-18.
Vec3 elasticFrictional(const ContactGeometry& g, ContactHistory& h, double kn, double kappa, double tanPhi, double dt,
                       DissipationLedger& ledger) {
    const double fn = kn * g.overlap;
    return fn * g.normal + updateShearForce(g, h, kappa * kn, fn, tanPhi, dt, ledger);
}

double springEnergy(const ContactGeometry& g, const ContactHistory& h, double kn, double kappa) {
    return 0.5 * kn * g.overlap * g.overlap + 0.5 * h.shearForce.squaredNorm() / (kappa * kn);
}
}  // namespace

BlockStemContact::BlockStemContact(const StemContactParams& p)
    : er_(p.woodRadialModulus), eb_(p.blockModulus), kappa_(p.kappaBlockStem), tanPhi_(tanDeg(p.frictionBlockStemDeg)),
      crushing_(p.crushingStrength) {
    if (!(er_ > 0 && eb_ > 0 && kappa_ > 0)) throw InputError("stem contact moduli and kappa must be positive");
    if (!(crushing_ >= 0)) throw InputError("tree_contact.crushing_strength_pa must be >= 0");
}

double BlockStemContact::crushingStiffness(const ContactGeometry& g) const {
    if (crushing_ <= 0) return std::numeric_limits<double>::infinity();
    return 2 * M_PI * crushing_ * std::sqrt(g.radiusA * g.radiusB);
}

double BlockStemContact::normalStiffness(const ContactGeometry& g) const {
    const double rb = g.radiusA, rs = g.radiusB;
    return 2 * er_ * rs * eb_ * rb / (eb_ * rb + er_ * rs);  // Eq. 22
}

Vec3 BlockStemContact::force(const ContactGeometry& g, ContactHistory& h, double dt, DissipationLedger& ledger) const {
    const double ke = normalStiffness(g), kc = crushingStiffness(g);
    if (!(kc < ke)) return elasticFrictional(g, h, ke, kappa_, tanPhi_, dt, ledger);  // Eq. 20
    // On the envelope the dent is U_n (1 - k_c / K): the deepest overlap reached so far is the dent
    // over that factor. Going deeper crushes: the work k_c (U^2 - U_max^2) / 2 minus what the elastic
    // spring stores more, (k_c^2 / K) (U^2 - U_max^2) / 2, is dissipated.
    const double keep = 1 - kc / ke;
    const double deepest = h.plasticOverlap / keep;
    if (g.overlap > deepest) {
        ledger.crushing += 0.5 * kc * keep * (g.overlap * g.overlap - deepest * deepest);
        h.plasticOverlap = keep * g.overlap;
    }
    const double fn = ke * std::max(0.0, g.overlap - h.plasticOverlap);
    return fn * g.normal + updateShearForce(g, h, kappa_ * ke, fn, tanPhi_, dt, ledger);
}

double BlockStemContact::storedEnergy(const ContactGeometry& g, const ContactHistory& h) const {
    const double ke = normalStiffness(g);
    const double elastic = std::max(0.0, g.overlap - h.plasticOverlap);
    return 0.5 * ke * elastic * elastic + 0.5 * h.shearForce.squaredNorm() / (kappa_ * ke);
}

StemStemContact::StemStemContact(const StemContactParams& p)
    : er_(p.woodRadialModulus), kappa_(p.kappaStemStem), tanPhi_(tanDeg(p.frictionStemStemDeg)) {
    if (!(er_ > 0 && kappa_ > 0)) throw InputError("stem contact moduli and kappa must be positive");
}

double StemStemContact::normalStiffness(const ContactGeometry& g) const {
    return 2 * er_ * g.radiusA * g.radiusB / (g.radiusA + g.radiusB);  // Eq. 23
}

Vec3 StemStemContact::force(const ContactGeometry& g, ContactHistory& h, double dt, DissipationLedger& ledger) const {
    return elasticFrictional(g, h, normalStiffness(g), kappa_, tanPhi_, dt, ledger);  // Eq. 21
}

double StemStemContact::storedEnergy(const ContactGeometry& g, const ContactHistory& h) const {
    return springEnergy(g, h, normalStiffness(g), kappa_);
}

}  // namespace sylva::dem

#include "libdem/StemContact.hpp"

#include <cmath>

#include "libstand/InputError.hpp"

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
    : er_(p.woodRadialModulus), eb_(p.blockModulus), kappa_(p.kappaBlockStem), tanPhi_(tanDeg(p.frictionBlockStemDeg)) {
    if (!(er_ > 0 && eb_ > 0 && kappa_ > 0)) throw InputError("stem contact moduli and kappa must be positive");
}

double BlockStemContact::normalStiffness(const ContactGeometry& g) const {
    const double rb = g.radiusA, rs = g.radiusB;
    return 2 * er_ * rs * eb_ * rb / (eb_ * rb + er_ * rs);  // Eq. 22
}

Vec3 BlockStemContact::force(const ContactGeometry& g, ContactHistory& h, double dt, DissipationLedger& ledger) const {
    return elasticFrictional(g, h, normalStiffness(g), kappa_, tanPhi_, dt, ledger);  // Eq. 20
}

double BlockStemContact::storedEnergy(const ContactGeometry& g, const ContactHistory& h) const {
    return springEnergy(g, h, normalStiffness(g), kappa_);
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

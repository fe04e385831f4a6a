#pragma once
// Contacts with stem connections (paper Sect. 2.1.3, Eqs. 20-23; Table 2): elastic normal springs
// whose stiffness follows the radii in contact, and the incremental tangential spring with
// Coulomb limit of Eqs. 17-18 with its own kappa and friction angle.
#include "libdem/ContactLaw.hpp"

namespace sylva::dem {

struct StemContactParams {
    double woodRadialModulus = 1.5e9;  // E_r, Pa (Table 2: 1.5e3 MPa)
    double blockModulus = 80e9;        // E_b, Pa (Table 2: 80e3 MPa)
    double kappaBlockStem = 0.3;       // K_t / K_n, block/stem
    double frictionBlockStemDeg = 30;  // phi^b-t
    double kappaStemStem = 0.3;        // K_t / K_n, stem/stem
    double frictionStemStemDeg = 0;    // phi^t-t (frictionless)
    // Compression strength of the wood across the grain, Pa: 0 keeps the paper's elastic block/stem
    // contact (Eq. 20); above, the stem crushes under the block once the contact pressure reaches it
    // (a Walton-Braun loading envelope, docs/model-stems.md, "Crushing").
    double crushingStrength = 0;
};

// Block sphere (A, radius r_b) on a stem connection (B, radius r_s = D_con / 2). With a crushing
// strength, loading follows the envelope F = k_c U_n, k_c = 2 pi sigma_c sqrt(r_b r_s) (the pressure
// sigma_c over the ellipse of semi-axes sqrt(2 r U_n) a sphere dents in a cylinder), and unloading
// the elastic K_b-t of Eq. 22 from the plastic dent it left (history: ContactHistory::plasticOverlap);
// the energy between the two goes to DissipationLedger::crushing. Restitution sqrt(k_c / K_b-t).
class BlockStemContact final : public ContactLaw {
public:
    explicit BlockStemContact(const StemContactParams& p);
    Vec3 force(const ContactGeometry& g, ContactHistory& h, double dt, DissipationLedger& ledger) const override;
    double storedEnergy(const ContactGeometry& g, const ContactHistory& h) const override;
    double normalStiffness(const ContactGeometry& g) const override;  // Eq. 22: the elastic (unloading) one
    double crushingStiffness(const ContactGeometry& g) const;         // k_c; infinity without crushing

private:
    double er_, eb_, kappa_, tanPhi_, crushing_;
};

// Stem connection on stem connection (radii R_s1, R_s2 at the contact).
class StemStemContact final : public ContactLaw {
public:
    explicit StemStemContact(const StemContactParams& p);
    Vec3 force(const ContactGeometry& g, ContactHistory& h, double dt, DissipationLedger& ledger) const override;
    double storedEnergy(const ContactGeometry& g, const ContactHistory& h) const override;
    double normalStiffness(const ContactGeometry& g) const override;  // Eq. 23

private:
    double er_, kappa_, tanPhi_;
};

}  // namespace sylva::dem

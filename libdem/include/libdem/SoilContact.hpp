#pragma once
// Block sphere / soil sphere contact (paper Sect. 2.1.3, Eqs. 14-19; Table 2).
#include "libdem/ContactLaw.hpp"

namespace sylva::dem {

struct SoilContactParams {
    double kn = 1e6;              // K_n^soil, N/m (Table 2)
    double kappa = 0.05;          // K_t / K_n (Eq. 19; Table 2)
    double dampingRatio = 0.54;   // alpha / alpha_cr (Eq. 15; Table 2)
    double frictionDeg = 30;      // phi^soil (Table 2)
    bool dashpotPulls = true;     // Eq. 14 literally (true) or normal force floored at 0 (Yade's ViscEl)
};

// e_n <-> alpha/alpha_cr of a linear spring-dashpot (Eq. 15) and its inverse.
double dampingRatioFromRestitution(double en);
double restitutionFromDampingRatio(double ratio);

class SoilContact final : public ContactLaw {
public:
    // blockMass: m_b of Eq. 16 (alpha_cr = 2 sqrt(K_n m_b)).
    SoilContact(const SoilContactParams& p, double blockMass);
    Vec3 force(const ContactGeometry& g, ContactHistory& h, double dt, DissipationLedger& ledger) const override;
    double storedEnergy(const ContactGeometry& g, const ContactHistory& h) const override;
    double normalStiffness(const ContactGeometry&) const override { return kn_; }
    double dampingCoefficient() const override { return alpha_; }
    double dampingCoefficientAt(const ContactGeometry& g) const override;
    double tangentialStiffness() const { return kt_; }  // K_t (Eq. 19)

private:
    double kn_, kt_, alpha_, ratio_, tanPhi_;
    bool dashpotPulls_;
};

}  // namespace sylva::dem

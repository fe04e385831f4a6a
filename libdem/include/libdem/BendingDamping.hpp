#pragma once
// The damping of a connection's bending: what turns the energy of a stem's vibrations into heat.
//
// Two laws (StemDamping):
// - Viscous, the paper's Eqs. 7-8: a dashpot tau K_Elast on the relative rotation rate. Its damping
//   ratio tau omega / 2 grows with frequency without bound, so what it takes from an impact depends on
//   how many high bending modes the node spacing carries (docs/model-stems.md, "Damping").
// - ConstantLoss: wood's internal friction, whose loss factor eta = tan(delta) hardly depends on
//   frequency (Bremaud et al. 2012, Ann. For. Sci. 69:373). A generalised Maxwell model: kBranches
//   spring-dashpot branches in parallel with the elastic hinge, relaxation times one per decade, each
//   branch stiffness g K_Elast with g = eta / (pi / (2 ln 10) - 3 eta), so that the loss factor is
//   eta within 6 % for omega from 1 to 5000 rad/s, a stem's first mode to the bending waves of an
//   impact (BendingDamping.ConstantLossFactorAcrossTheBand; the "constant Q" of seismic modelling:
//   Emmerich & Korn 1987, Geophysics 52:1252). The branches are integrated exactly over a step (the
//   rate held constant), so they do not limit the stable step and dissipate exactly what they should.
#include <array>

#include <Eigen/Core>

#include "libdem/BendingLaw.hpp"

namespace sylva::dem {

class BendingDamping {
public:
    static constexpr int kBranches = 6;
    static constexpr double kTauMax = 2.0;  // s: the slowest branch (omega 0.5 rad/s, below a stem's first mode)

    BendingDamping() = default;
    // For a connection of hinge coefficients k (K_Elast and tau K_Elast).
    BendingDamping(const BendingParams& p, const HingeCoefficients& k);

    struct Step {
        Vec2 moment = Vec2::Zero();  // on the relative rotation (x, y), N m, at the step's end
        double dissipated = 0;       // J, >= 0
    };
    // How much each branch's moment decays over a step dt: the same for every connection a step
    // advances, so a stem computes it once per step rather than kBranches exponentials per connection.
    struct Decay {
        double dt = 0;
        std::array<double, kBranches> factor{};  // exp(-dt / tau_b)
        std::array<double, kBranches> lag{};     // tau_b (1 - exp(-dt / tau_b)): the step's integral of the decay
        double settled = 0;  // dt times the sum of the tau_b: the step's integral of the branches settled at a unit rate
    };
    static Decay decayOver(double dt);
    // Over a step at the relative rotation rate `rate` (x, y of the connection frame, rad/s).
    Step advance(const Vec2& rate, const Decay& decay);
    Step advance(const Vec2& rate, double dt) { return advance(rate, decayOver(dt)); }
    // Energy held by the Maxwell branches' springs, J (zero for the viscous law).
    double storedEnergy() const { return stored_; }
    // The connection broke: the branches let go; returns what they held, J.
    double release();

    // For the stable step: the stiffness the branches add at high frequency (N m/rad) and the
    // dashpot coefficient (N m s/rad) of the viscous law.
    double addedStiffness() const { return kBranches * branchStiffness_; }
    double viscosity() const { return viscosity_; }
    static double relaxationTime(int branch);  // s

private:
    double viscosity_ = 0;        // tau K_Elast (Eqs. 7-8)
    double branchStiffness_ = 0;  // g K_Elast
    double halfBranchCompliance_ = 0;  // 1 / (2 g K_Elast), for the branches' energy
    std::array<Vec2, kBranches> branch_{};
    double stored_ = 0;  // sum of |m_b|^2 / (2 g K_Elast), kept as the branches advance
};

}  // namespace sylva::dem

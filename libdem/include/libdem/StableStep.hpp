#pragma once
// The largest stable explicit time step for what is currently in contact.
namespace sylva::dem {

// Accumulates, over the active springs acting on one body, an upper bound of its highest
// eigen-frequency: omega^2 <= sum_c k_c / m_c (the trace of M^-1 K, m_c the effective mass the
// spring sees), and the largest damping ratio zeta_c = c_c / (2 sqrt(k_c m_c)).
class StableStep {
public:
    void add(double stiffness, double dampingCoefficient, double inverseMass);
    // Leapfrog with a viscous term is stable for dt < 2/omega (sqrt(1 + zeta^2) - zeta).
    double critical() const;
    double omegaSquared() const { return omega2_; }

private:
    double omega2_ = 0, zeta_ = 0;
};

}  // namespace sylva::dem

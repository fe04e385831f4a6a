#pragma once
// The largest stable explicit time step for what is currently in contact.
namespace sylva::dem {

// Accumulates, over the active springs acting on one body, an upper bound of its highest
// eigen-frequency, omega^2 <= sum_c k_c / m_c (the trace of M^-1 K, m_c the effective mass the
// spring sees), and of its highest damping rate, gamma <= sum_c c_c / m_c.
class StableStep {
public:
    void add(double stiffness, double dampingCoefficient, double inverseMass);
    // Leapfrog with a viscous term is stable for dt < 2/omega (sqrt(1 + zeta^2) - zeta), zeta =
    // gamma / (2 omega): both bounds enter, so the step stays below the limit of every mode.
    double critical() const;
    double omegaSquared() const { return omega2_; }
    // Both bounds of springs acting on the same body add (as add() does).
    StableStep& operator+=(const StableStep& other) {
        omega2_ += other.omega2_;
        gamma_ += other.gamma_;
        return *this;
    }

private:
    double omega2_ = 0, gamma_ = 0;
};

}  // namespace sylva::dem

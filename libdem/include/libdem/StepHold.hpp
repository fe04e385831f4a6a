#pragma once
// The time step a run takes from a stable-step bound that changes from step to step.
#include <limits>

namespace sylva::dem {

// A leapfrog is stable at any constant step below 2 / omega_max, but not at a step that alternates
// between two such values: the two-step map of a mode at omega has trace
// (1 - u1^2)(1 - u2^2) - 2 u1 u2 + 1 (u = omega dt), below -2 for u1 = 1.9, u2 = 1.28 (steps 1.48
// apart), and for u1 = 1.5 already at 1.1 apart: a parametric resonance of the modes near
// omega dt = sqrt(2) (Skeel 1993, "Variable step size destabilizes the Stormer/leapfrog/Verlet
// method", BIT 33: 172-175). A stem node that touches the soil at one step and not at the next makes the
// bound chatter so (measured: 2.4e-4 s and 1.7e-4 s at alternate steps), and the stems' energy
// grew without a source. The step therefore drops at once to a lower bound (stability asks for it)
// but rises only once the bound has let it for kRiseAfter steps in a row, and then to the lowest
// bound of those: a contact that comes and goes holds the step at its lower value.
class StepHold {
public:
    static constexpr int kRiseAfter = 20;  // steps; 5 still let a chattering contact through (docs/accuracy.md)

    // The step to take, given this step's bound (infinity: no limit from this side).
    double next(double bound);

private:
    double current_ = std::numeric_limits<double>::infinity();
    double lowestWhileWaiting_ = std::numeric_limits<double>::infinity();
    int waited_ = 0;
};

}  // namespace sylva::dem

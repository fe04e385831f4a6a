#pragma once
// A simulation that went numerically wrong (NaN, energy growth, a time step above the stable
// limit). We stop with this instead of printing a plausible-looking number.
#include <stdexcept>
#include <string>

namespace sylva::dem {

class SimulationError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace sylva::dem

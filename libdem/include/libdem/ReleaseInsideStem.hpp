#pragma once
// A block released where a stem stands: a bad release, refused before the first step (its contact
// spring would start loaded by no motion, energy from nowhere). simulate names it as an input error;
// a hazard map, which draws its release points at random, draws another.
#include "libcommon/InputError.hpp"

namespace sylva::dem {

class ReleaseInsideStem : public InputError {
public:
    using InputError::InputError;
};

}  // namespace sylva::dem

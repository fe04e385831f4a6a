#pragma once
// The lumped model's rebound on the soil (docs/lumped.md): the normal velocity reversed and scaled
// by a random R_n of the soil type, the tangential one scaled by R_t from the obstacle height met,
// the direction turned by a random deviation about the slope's normal.
#include "libdem/LumpedParams.hpp"
#include "libdem/RigidBody.hpp"
#include "libcommon/SeededRandom.hpp"

namespace sylva::dem {

class LumpedRebound {
public:
    LumpedRebound(const LumpedParams& params, double blockRadius);
    // Velocity after an impact with velocity `v` on a surface of upward unit normal `n`.
    Vec3 apply(const Vec3& v, const Vec3& n, SeededRandom& rng) const;
    // R_t for an obstacle of height h under a sphere of the block's radius.
    double tangentialRestitution(double obstacleHeight) const;

private:
    LumpedParams p_;
    SoilRestitution soil_;
    double radius_;
};

}  // namespace sylva::dem

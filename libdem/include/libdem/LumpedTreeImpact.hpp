#pragma once
// The lumped model's tree impact (docs/lumped.md): the block loses the energy the stem can take,
// after Dorren & Berger (2006), scaled by the impact's eccentricity, and is deviated.
#include "libdem/LumpedParams.hpp"
#include "libdem/RigidBody.hpp"
#include "libcommon/SeededRandom.hpp"

namespace sylva::dem {

class LumpedTreeImpact {
public:
    explicit LumpedTreeImpact(const LumpedParams& params) : p_(params) {}
    // Energy a stem of this DBH (m) takes from a central impact, J.
    double capacity(double dbh) const;
    // Share of it taken at eccentricity e (lateral offset / (block radius + stem radius), in [-1, 1]).
    static double eccentricityShare(double e);
    struct Outcome {
        Vec3 velocity;
        bool treeBroken;  // the block had more energy than the stem takes
    };
    Outcome apply(const Vec3& v, double dbh, double eccentricity, double height, double mass, SeededRandom& rng) const;

private:
    LumpedParams p_;
};

}  // namespace sylva::dem

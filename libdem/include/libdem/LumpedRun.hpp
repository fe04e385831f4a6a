#pragma once
// One block of the lumped-mass model (the paper's Sect. 2.3.1, after Rockyfor3D): a sphere of the
// block's mass and equivalent radius in parabolic flight over the scene's macroscopic surface,
// rebounding with random restitution (LumpedRebound) and losing energy on the stems it passes
// (LumpedTreeImpact). No soil spheres, no stems' mechanics: thousands of runs per second.
#include <cstdint>

#include "libdem/BlockRun.hpp"

namespace sylva::dem {

// Same release as the DEM's (drawRelease: x, y, fall height) from rest; the run's random draws come
// from `seed` alone. RunResult::steps counts the rebounds; impacts list the trees hit.
RunResult simulateLumped(const Scene& scene, int run, std::uint64_t seed, const RunOptions& options = {});

// InputError when the block's sphere is larger than the fall height, so that every release would start
// inside the ground (simulateLumped refuses each such run): for callers that run many blocks of one
// scene, to say so once, before anything is written.
void refuseReleaseInsideTheGround(const Scene& scene);

}  // namespace sylva::dem

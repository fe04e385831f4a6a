#pragma once
// The run-out of a block on a DTM: the length, along the ground, of the path it took from its release
// to where it stopped (issue 15). On a slope profile the run-out stays the paper's (Eq. 26's distance
// along the slope between the release's and the stop's x); on a DTM a block can run in any direction,
// so a difference of x means nothing there.
#include "libdem/RigidBody.hpp"
#include "libdem/SoilBed.hpp"

namespace sylva::dem {

class SurfacePath {
public:
    // Positions are kept once the block is `chord` (m, horizontally) from the last kept one: the
    // path is the polyline through them, each chord measured along the surface under it
    // (sqrt(horizontal^2 + rise of the surface^2)), so bounces add nothing and a resting block's
    // jitter is not counted.
    SurfacePath(const SoilBed& soil, const Vec3& release, double chord = kDefaultChord);
    void moveTo(const Vec3& position);
    // The path's length with its last piece to `end`, m.
    double length(const Vec3& end) const;

    // A resolution: tests/dem/test_surface_path.cpp shows a curved path's length converging as it
    // is halved (0.5, 0.25, 0.125 m).
    static constexpr double kDefaultChord = 0.25;

private:
    double piece(const Vec3& a, const Vec3& b) const;
    const SoilBed& soil_;
    double chord_;
    Vec3 kept_;
    double length_ = 0;
};

// A run's run-out: along the path on a DTM (SurfacePath), along the profile between the release's and
// the stop's x on a slope profile (Eq. 26, the paper's Dist).
double runoutAlongSlope(const SoilBed& soil, const Vec3& release, const Vec3& stop, const SurfacePath& path);

}  // namespace sylva::dem

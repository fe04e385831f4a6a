#pragma once
// The narrow phase every contact shares: two spheres. A block's ball, a soil sphere, a stem node, or
// a stem connection's cross-section at the point of its axis closest to the other body (Fig. 2:
// cylinders touch like the spheres inscribed at their closest points).
#include "libdem/ContactLaw.hpp"

namespace sylva::dem {

// Spheres A (centre ca, radius ra) and B: fills g's overlap (ra + rb - |ca - cb|; <= 0 when apart,
// for callers that look ahead), and, when they touch, the normal from B to A, the point in the
// middle of the overlap and both radii. Returns whether they touch (coinciding centres have no
// normal: not a contact). The relative velocity, spin and moving mass are the caller's: they depend
// on what carries each sphere.
// Inline: it runs for every block sphere against every connection within reach, every step.
inline bool touchSpheres(const Vec3& ca, double ra, const Vec3& cb, double rb, ContactGeometry& g) {
    const Vec3 d = ca - cb;
    const double dist = d.norm();
    g.overlap = ra + rb - dist;
    if (g.overlap <= 0 || dist == 0) return false;
    g.normal = d / dist;
    g.point = cb + g.normal * (rb - 0.5 * g.overlap);
    g.radiusA = ra;
    g.radiusB = rb;
    return true;
}

}  // namespace sylva::dem

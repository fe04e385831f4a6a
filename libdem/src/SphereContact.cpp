#include "libdem/SphereContact.hpp"

namespace sylva::dem {

bool touchSpheres(const Vec3& ca, double ra, const Vec3& cb, double rb, ContactGeometry& g) {
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

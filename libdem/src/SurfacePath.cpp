#include "libdem/SurfacePath.hpp"

#include <cmath>

namespace sylva::dem {

SurfacePath::SurfacePath(const SoilBed& soil, const Vec3& release, double chord) : soil_(soil), chord_(chord), kept_(release) {}

double SurfacePath::piece(const Vec3& a, const Vec3& b) const {
    const double horizontal = (b - a).head<2>().norm();
    if (horizontal == 0) return 0;
    const double rise = soil_.surfaceHeight(b.x(), b.y()) - soil_.surfaceHeight(a.x(), a.y());
    return std::hypot(horizontal, rise);
}

void SurfacePath::moveTo(const Vec3& position) {
    if ((position - kept_).head<2>().squaredNorm() < chord_ * chord_ || !position.allFinite()) return;
    length_ += piece(kept_, position);
    kept_ = position;
}

double SurfacePath::length(const Vec3& end) const { return length_ + (end.allFinite() ? piece(kept_, end) : 0); }

double runoutAlongSlope(const SoilBed& soil, const Vec3& release, const Vec3& stop, const SurfacePath& path) {
    return soil.onProfile() ? soil.alongSlope(release.x(), stop.x(), stop.y()) : path.length(stop);
}

}  // namespace sylva::dem

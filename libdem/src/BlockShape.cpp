#include "libdem/BlockShape.hpp"

#include <cmath>

#include "libcommon/InputError.hpp"

namespace sylva::dem {

BlockShapeKind parseBlockShape(const std::string& name) {
    if (name == "cube") return BlockShapeKind::Cube;
    if (name == "cuboid") return BlockShapeKind::Cuboid;
    if (name == "sphere") return BlockShapeKind::Sphere;
    throw InputError("block shape '" + name + "' is not one of cube, cuboid, sphere");
}

std::string toString(BlockShapeKind kind) {
    switch (kind) {
        case BlockShapeKind::Cube: return "cube";
        case BlockShapeKind::Cuboid: return "cuboid";
        case BlockShapeKind::Sphere: return "sphere";
    }
    return "?";
}

namespace {

// Sphere centres along one edge of length d for spheres of radius r: the outer spheres touch the
// faces, the spacing is as close to r as the edge allows (exactly r, i.e. D/4, for the cube of Eq. 1).
std::vector<double> centresAlong(double d, double r) {
    const int n = std::max(1, static_cast<int>(std::lround((d - 2 * r) / r)) + 1);
    std::vector<double> c(n);
    for (int i = 0; i < n; ++i) c[i] = n == 1 ? 0.0 : -(d / 2 - r) + i * (d - 2 * r) / (n - 1);
    return c;
}

RigidBody boxClump(double d1, double d2, double d3, double density) {
    const double r = std::min({d1, d2, d3}) / 4;  // Eq. 1 (R_b = D1/4 for the cube)
    std::vector<ClumpSphere> spheres;
    for (double x : centresAlong(d1, r))
        for (double y : centresAlong(d2, r))
            for (double z : centresAlong(d3, r)) spheres.push_back({Vec3(x, y, z), r});
    const double m = density * d1 * d2 * d3;
    const Vec3 inertia(m / 12 * (d2 * d2 + d3 * d3), m / 12 * (d1 * d1 + d3 * d3), m / 12 * (d1 * d1 + d2 * d2));
    return RigidBody(m, inertia, std::move(spheres));
}

}  // namespace

RigidBody makeBlock(const BlockSpec& spec) {
    if (!(spec.densityKgM3 > 0)) throw InputError("block density must be positive");
    switch (spec.shape) {
        case BlockShapeKind::Cube: {
            if (!(spec.volumeM3 > 0)) throw InputError("block volume must be positive");
            const double d = std::cbrt(spec.volumeM3);
            return boxClump(d, d, d, spec.densityKgM3);
        }
        case BlockShapeKind::Cuboid:
            if (!(spec.d1 > 0 && spec.d2 > 0 && spec.d3 > 0))
                throw InputError("a cuboid block needs positive edges block.d1_m, block.d2_m, block.d3_m");
            return boxClump(spec.d1, spec.d2, spec.d3, spec.densityKgM3);
        case BlockShapeKind::Sphere: {
            if (!(spec.volumeM3 > 0)) throw InputError("block volume must be positive");
            const double r = std::cbrt(3 * spec.volumeM3 / (4 * M_PI));
            const double m = spec.densityKgM3 * spec.volumeM3;
            return RigidBody(m, Vec3::Constant(0.4 * m * r * r), {{Vec3::Zero(), r}});
        }
    }
    throw InputError("unknown block shape");
}

}  // namespace sylva::dem

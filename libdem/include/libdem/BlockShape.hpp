#pragma once
// The falling block: a rigid clump of spheres with the mass and inertia of the true solid.
#include <string>

#include "libdem/RigidBody.hpp"

namespace sylva::dem {

enum class BlockShapeKind { Cube, Cuboid, Sphere };

struct BlockSpec {
    BlockShapeKind shape = BlockShapeKind::Cube;
    double volumeM3 = 0.5;       // cube and sphere: sets the size (Table 2: 0.5 m^3)
    double d1 = 0, d2 = 0, d3 = 0;  // cuboid edges, m (cube: all equal to volume^(1/3))
    double densityKgM3 = 2700;  // Table 2: 2.7 t/m^3
};

BlockShapeKind parseBlockShape(const std::string& name);  // "cube" | "cuboid" | "sphere"; InputError otherwise
std::string toString(BlockShapeKind kind);

// Cube: 27 spheres of radius R_b = D1/4 (Eq. 1) on a 3x3x3 grid of spacing D1/4, so the clump spans
// exactly D1; mass rho D1^3 and inertia m D1^2/6 of the true cube. Cuboid: spheres of radius
// min(D)/4 on a grid spanning each edge exactly, inertia of the true cuboid. Sphere: one sphere of
// the given volume, inertia 2/5 m r^2.
RigidBody makeBlock(const BlockSpec& spec);

}  // namespace sylva::dem

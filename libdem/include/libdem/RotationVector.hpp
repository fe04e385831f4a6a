#pragma once
// Rotation vectors (axis times angle, rad) and the maps between them and quaternions, with the
// Jacobians the stems' springs need. Stems turn by hundredths of a radian per connection and by
// microradians per step, so each function switches to its Taylor series below a small angle:
// the series are truncated where the next term is under 1e-15 relative, and they spare the
// trigonometric calls that otherwise dominate a stem step.
#include "libdem/RigidBody.hpp"

namespace sylva::dem {

// Rotation vector of q, taking the shorter way round.
Vec3 rotationVector(Quat q);
// The rotation whose rotation vector is theta.
Quat fromRotationVector(const Vec3& theta);

// A Jacobian of the rotation-vector map, I - b [theta]x + c [theta]x^2, kept as its two coefficients:
// the stems only ever apply it (or its transpose) to a vector, which costs two cross products where
// the 3x3 matrix would cost two matrix products to build.
struct RotationJacobian {
    Vec3 theta;
    double b, c;
    Vec3 operator*(const Vec3& u) const {
        const Vec3 tu = theta.cross(u);
        return u - b * tu + c * theta.cross(tu);
    }
    Vec3 transposeTimes(const Vec3& u) const {  // [theta]x is antisymmetric, [theta]x^2 symmetric
        const Vec3 tu = theta.cross(u);
        return u + b * tu + c * theta.cross(tu);
    }
};

// A small turn u applied on the left of the rotation exp(theta) moves theta by
// inverseLeftJacobian(theta) * u; a change d of theta turns exp(theta) on the right by
// rightJacobian(theta) * d.
RotationJacobian inverseLeftJacobian(const Vec3& theta);
RotationJacobian rightJacobian(const Vec3& theta);

}  // namespace sylva::dem

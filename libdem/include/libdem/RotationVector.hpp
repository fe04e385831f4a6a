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

// A small turn u applied on the left of the rotation exp(theta) moves theta by
// inverseLeftJacobian(theta) u; a change d of theta turns exp(theta) on the right by
// rightJacobian(theta) d.
Eigen::Matrix3d inverseLeftJacobian(const Vec3& theta);
Eigen::Matrix3d rightJacobian(const Vec3& theta);

}  // namespace sylva::dem

#include "libdem/RigidBody.hpp"

#include <algorithm>
#include <stdexcept>

namespace sylva::dem {

RigidBody::RigidBody(double mass, const Vec3& principalInertia, std::vector<ClumpSphere> spheres)
    : mass_(mass), inertia_(principalInertia), spheres_(std::move(spheres)) {
    if (!(mass > 0) || !(principalInertia.minCoeff() > 0) || spheres_.empty())
        throw std::invalid_argument("RigidBody needs a positive mass, positive inertia and at least one sphere");
    for (const auto& s : spheres_) boundingRadius_ = std::max(boundingRadius_, s.offset.norm() + s.radius);
}

Vec3 RigidBody::bodyOmega(const Quat& q, const Vec3& angularMomentumWorld) const {
    return (q.conjugate() * angularMomentumWorld).cwiseQuotient(inertia_);
}

Vec3 RigidBody::angularVelocity() const { return orientation * bodyOmega(orientation, angularMomentum); }

void RigidBody::setAngularVelocity(const Vec3& omegaWorld) {
    const Vec3 bodyL = (orientation.conjugate() * omegaWorld).cwiseProduct(inertia_);
    angularMomentum = orientation * bodyL;
}

double RigidBody::kineticEnergy() const {
    const Vec3 w = bodyOmega(orientation, angularMomentum);
    return 0.5 * mass_ * velocity.squaredNorm() + 0.5 * w.dot(inertia_.cwiseProduct(w));
}

double RigidBody::inverseMassAlong(const Vec3& point, const Vec3& n) const {
    const Vec3 rn = orientation.conjugate() * (point - position).cross(n);
    return 1.0 / mass_ + rn.cwiseQuotient(inertia_).dot(rn);
}

double RigidBody::maxInverseMass() const { return 1.0 / mass_ + boundingRadius_ * boundingRadius_ / inertia_.minCoeff(); }

namespace {
// q rotated by a constant body-frame angular velocity w for dt: dq/dt = q (0, w/2) integrated
// exactly, so the quaternion stays unit.
Quat rotated(const Quat& q, const Vec3& wBody, double dt) {
    const double angle = wBody.norm() * dt;
    if (angle == 0.0) return q;
    return (q * Quat(Eigen::AngleAxisd(angle, wBody.normalized()))).normalized();
}
}  // namespace

void RigidBody::advance(double dt, const Vec3& force, const Vec3& torque) {
    velocity += force / mass_ * dt;
    position += velocity * dt;

    const Vec3 lNow = angularMomentum + 0.5 * dt * torque;  // L(t)
    angularMomentum += dt * torque;                          // L(t + dt/2)
    const Quat qHalf = rotated(orientation, bodyOmega(orientation, lNow), 0.5 * dt);
    orientation = rotated(orientation, bodyOmega(qHalf, angularMomentum), dt);
}

}  // namespace sylva::dem

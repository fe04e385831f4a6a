#pragma once
// A rigid clump of spheres (the block): state, mass properties and time integration.
// Spheres give the contact geometry only; mass and inertia are those of the true solid.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace sylva::dem {

using Vec3 = Eigen::Vector3d;
using Quat = Eigen::Quaterniond;

struct ClumpSphere {
    Vec3 offset;  // centre in the body frame (principal axes, origin at the centre of mass)
    double radius;
};

class RigidBody {
public:
    RigidBody(double mass, const Vec3& principalInertia, std::vector<ClumpSphere> spheres);

    double mass() const { return mass_; }
    const Vec3& principalInertia() const { return inertia_; }
    const std::vector<ClumpSphere>& spheres() const { return spheres_; }
    double boundingRadius() const { return boundingRadius_; }  // centre of mass to farthest sphere surface

    // State. Velocities are the leapfrog mid-step values (t - dt/2) between integrations.
    Vec3 position{0, 0, 0};
    Quat orientation = Quat::Identity();
    Vec3 velocity{0, 0, 0};
    Vec3 angularMomentum{0, 0, 0};  // world frame

    Vec3 angularVelocity() const;  // world frame, from the angular momentum and current orientation
    void setAngularVelocity(const Vec3& omegaWorld);
    Vec3 sphereCentre(std::size_t i) const { return position + orientation * spheres_[i].offset; }
    Vec3 velocityAt(const Vec3& point) const { return velocity + angularVelocity().cross(point - position); }
    double kineticEnergy() const;

    // Inverse effective mass of a unit force along n applied at `point`: 1/m + (r x n)^T I^-1 (r x n).
    // This is what a contact spring there "sees"; it sets the stable time step.
    double inverseMassAlong(const Vec3& point, const Vec3& n) const;
    double maxInverseMass() const;  // upper bound of inverseMassAlong over the clump's surface

    // One leapfrog step: translation v(t+dt/2) = v(t-dt/2) + F/m dt, x(t+dt) = x + v dt; rotation by
    // the second-order scheme for a non-spherical body of Omelyan (1998) (as Yade's exactAsphericalRot):
    // torque updates the world angular momentum, the orientation advances with the body-frame
    // angular velocity evaluated at the half step.
    void advance(double dt, const Vec3& force, const Vec3& torque);

private:
    Vec3 bodyOmega(const Quat& q, const Vec3& angularMomentumWorld) const;
    double mass_;
    Vec3 inertia_;
    std::vector<ClumpSphere> spheres_;
    double boundingRadius_ = 0;
};

}  // namespace sylva::dem

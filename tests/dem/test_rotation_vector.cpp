// The rotation-vector maps switch to Taylor series at small angles: on both sides of each switch
// they must agree with the closed forms (evaluated here in long double) to near machine precision,
// and the maps must invert each other.
#include <gtest/gtest.h>

#include <cmath>

#include "libdem/RotationVector.hpp"

using namespace sylva::dem;

namespace {

// Closed forms in long double: the reference the series are checked against.
long double invLeftCoefficient(long double a) { return 1 / (a * a) - (1 + std::cos(a)) / (2 * a * std::sin(a)); }
long double rightB(long double a) { return (1 - std::cos(a)) / (a * a); }
long double rightC(long double a) { return (a - std::sin(a)) / (a * a * a); }

// The matrix of a Jacobian, column by column, and of its transpose.
Eigen::Matrix3d matrixOf(const RotationJacobian& j) {
    Eigen::Matrix3d m;
    for (int i = 0; i < 3; ++i) m.col(i) = j * Vec3::Unit(i);
    return m;
}
Eigen::Matrix3d transposeOf(const RotationJacobian& j) {
    Eigen::Matrix3d m;
    for (int i = 0; i < 3; ++i) m.col(i) = j.transposeTimes(Vec3::Unit(i));
    return m;
}

}  // namespace

TEST(RotationVector, RoundTripAcrossTheSeriesSwitch) {
    const Vec3 axis = Vec3(0.3, -0.5, 0.81).normalized();
    for (double angle : {1e-9, 1e-5, 0.01, 0.0999, 0.1001, 0.2, 1.0, 3.0}) {
        const Vec3 theta = angle * axis;
        const Quat q = fromRotationVector(theta);
        EXPECT_NEAR(q.norm(), 1.0, 1e-15) << angle;
        const Quat reference(Eigen::AngleAxisd(angle, axis));
        EXPECT_LT((q.coeffs() - reference.coeffs()).norm(), 1e-15) << angle;
        // 1e-15 of the angle: the series stop where their next term is below that.
        EXPECT_LT((rotationVector(q) - theta).norm(), 2e-15 * std::max(1.0, angle)) << angle;
    }
}

TEST(RotationVector, JacobiansMatchTheClosedFormsNearTheSwitch) {
    const Vec3 axis = Vec3(-0.2, 0.7, 0.4).normalized();
    for (long double a : {0.02L, 0.0999L, 0.1001L, 0.3L}) {
        const Vec3 theta = static_cast<double>(a) * axis;
        Eigen::Matrix3d k;
        k << 0, -theta.z(), theta.y(), theta.z(), 0, -theta.x(), -theta.y(), theta.x(), 0;
        const Eigen::Matrix3d invLeft = Eigen::Matrix3d::Identity() - 0.5 * k + double(invLeftCoefficient(a)) * k * k;
        const Eigen::Matrix3d right = Eigen::Matrix3d::Identity() - double(rightB(a)) * k + double(rightC(a)) * k * k;
        EXPECT_LT((matrixOf(inverseLeftJacobian(theta)) - invLeft).norm(), 1e-14) << double(a);
        EXPECT_LT((matrixOf(rightJacobian(theta)) - right).norm(), 1e-14) << double(a);
        EXPECT_LT((transposeOf(inverseLeftJacobian(theta)) - invLeft.transpose()).norm(), 1e-14) << double(a);
        EXPECT_LT((transposeOf(rightJacobian(theta)) - right.transpose()).norm(), 1e-14) << double(a);
    }
    // J_r(theta) = J_l(-theta): inverseLeftJacobian(-theta) undoes rightJacobian(theta).
    const Vec3 theta = 0.05 * axis;
    EXPECT_LT((matrixOf(inverseLeftJacobian(-theta)) * matrixOf(rightJacobian(theta)) - Eigen::Matrix3d::Identity()).norm(),
              1e-14);
}

// The stems take the rate of a connection's rotation vector from the relative angular velocity in
// its halfway frame: inverseLeftJacobian(theta) R(theta / 2), which midpointInverseJacobian gives
// as one symmetric map. Against that product, on both sides of the series switch and at large angles
// (the closed forms of the product's factors are 1e-16 accurate, so 1e-14 leaves room for the
// product's rounding only).
TEST(RotationVector, MidpointJacobianIsTheInverseLeftJacobianTurnedByHalfTheRotation) {
    const Vec3 axis = Vec3(0.6, 0.1, -0.75).normalized();
    for (double a : {1e-6, 0.02, 0.0999, 0.1001, 0.3, 1.0, 1.5}) {
        const Vec3 theta = a * axis;
        const Eigen::Matrix3d product =
            matrixOf(inverseLeftJacobian(theta)) * fromRotationVector(0.5 * theta).toRotationMatrix();
        const RotationJacobian s = midpointInverseJacobian(theta);
        EXPECT_LT((matrixOf(s) - product).norm(), 1e-14) << a;
        EXPECT_LT((transposeOf(s) - product.transpose()).norm(), 1e-14) << a;
    }
}

// The connection's frame is halfway along the relative rotation, taken without the rotation vector:
// it must be the rotation by half that vector, whichever sign the quaternion comes with. Both are unit
// quaternions from exact formulas (or series truncated below 1e-15), so they differ by rounding:
// a few ulp of 1 (2.2e-16 each), under 1e-15.
TEST(RotationVector, HalfwayIsTheRotationByHalfTheRotationVector) {
    const Vec3 axis = Vec3(-0.4, 0.9, 0.2).normalized();
    for (double a : {1e-8, 0.01, 0.5, 2.0, 3.1}) {
        const Quat q = fromRotationVector(a * axis);
        const Quat expected = fromRotationVector(0.5 * rotationVector(q));
        for (const Quat& sign : {q, Quat(-q.coeffs())}) {
            const Quat h = halfway(sign);
            EXPECT_LT((h.coeffs() - expected.coeffs()).norm(), 1e-15) << a;
        }
    }
}

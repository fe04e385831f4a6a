#pragma once
// Rotation vectors (axis times angle, rad) and the maps between them and quaternions, with the
// Jacobians the stems' springs need. Stems turn by hundredths of a radian per connection and by
// microradians per step, so each function switches to its Taylor series below a small angle:
// the series are truncated where the next term is under 1e-15 relative, and they spare the
// trigonometric calls that otherwise dominate a stem step. Their constants are reciprocals
// multiplied, never divisors (a division costs several multiplications, and the compiler may not
// swap one for the other), and their halves are summed as Estrin's scheme does, so that the
// processor computes them side by side rather than in one chain of dependent operations. They run
// for every connection and every node at every stem step, so they are defined here, where the
// compiler can inline them.
#include <cmath>

#include "libdem/RigidBody.hpp"

namespace sylva::dem {

// A Jacobian of the rotation-vector map, I - b [theta]x + c [theta]x^2 (the left and right Jacobians
// of SO(3) and their inverses: Sola, Deray & Atchuthan 2018, "A micro Lie theory for state
// estimation in robotics", arXiv:1812.01537, the SO(3) example), kept as its two coefficients:
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

namespace rotation_series {
// Below these the series are used (the first omitted term is given for each).
constexpr double kSmallHalfSine = 0.05;  // sin(angle / 2): next term x^10 / 11 < 1e-14
constexpr double kSmallAngle = 0.1;      // rad: next terms ~ a^8 / 4e6 < 3e-15
}  // namespace rotation_series

// Rotation vector of q, taking the shorter way round.
inline Vec3 rotationVector(Quat q) {
    if (q.w() < 0) q.coeffs() *= -1;
    const double s2 = q.vec().squaredNorm(), w = q.w();
    if (s2 < rotation_series::kSmallHalfSine * rotation_series::kSmallHalfSine * w * w) {
        // angle = 2 atan(x) with x = s / w: 2 atan(x) / s = (2 / w) (1 - x^2/3 + x^4/5 - x^6/7 + x^8/9)
        const double invW = 1 / w;
        const double x2 = s2 * invW * invW, x4 = x2 * x2;
        const double series = (1 - x2 * (1.0 / 3)) + x4 * ((1.0 / 5 - x2 * (1.0 / 7)) + x4 * (1.0 / 9));
        return 2 * invW * series * q.vec();
    }
    const double s = std::sqrt(s2);
    return 2 * std::atan2(s, w) / s * q.vec();
}

// The rotation halfway along q, the shorter way round: fromRotationVector(rotationVector(q) / 2),
// taken from q directly as (1 + q) / |1 + q|, where |1 + q|^2 = 2 (1 + w) for a unit q with w >= 0,
// so that it need not wait for the rotation vector.
inline Quat halfway(Quat q) {
    if (q.w() < 0) q.coeffs() *= -1;
    const double scale = 1 / std::sqrt(2 * (1 + q.w()));
    return Quat((1 + q.w()) * scale, q.x() * scale, q.y() * scale, q.z() * scale);
}

// The rotation whose rotation vector is theta.
inline Quat fromRotationVector(const Vec3& theta) {
    const double a2 = theta.squaredNorm();
    if (a2 < rotation_series::kSmallAngle * rotation_series::kSmallAngle) {
        // h = angle / 2: cos h and sin(h) / angle by their series to h^8
        const double h2 = 0.25 * a2, h4 = h2 * h2;
        const double c = (1 - h2 * 0.5) + h4 * ((1.0 / 24 - h2 * (1.0 / 720)) + h4 * (1.0 / 40320));
        const double sOverAngle = 0.5 * ((1 - h2 * (1.0 / 6)) + h4 * ((1.0 / 120 - h2 * (1.0 / 5040)) + h4 * (1.0 / 362880)));
        return Quat(c, sOverAngle * theta.x(), sOverAngle * theta.y(), sOverAngle * theta.z());
    }
    const double angle = std::sqrt(a2);
    return Quat(Eigen::AngleAxisd(angle, theta / angle));
}

// A small turn u applied on the left of the rotation exp(theta) moves theta by
// inverseLeftJacobian(theta) * u.
inline RotationJacobian inverseLeftJacobian(const Vec3& theta) {
    const double a2 = theta.squaredNorm();
    double c;
    if (a2 < rotation_series::kSmallAngle * rotation_series::kSmallAngle) {
        c = (1.0 / 12 + a2 * (1.0 / 720)) + a2 * a2 * (1.0 / 30240 + a2 * (1.0 / 1209600));
    } else {
        const double a = std::sqrt(a2);
        c = 1 / a2 - (1 + std::cos(a)) / (2 * a * std::sin(a));
    }
    return {theta, 0.5, c};
}

// The same map for a turn u given in the frame halfway along the rotation, exp(theta / 2):
// inverseLeftJacobian(theta) R(theta / 2) = I - beta [theta]x^2, beta = ((a / 2) / sin(a / 2) - 1) / a^2,
// a = |theta| (both factors are functions of [theta]x; the product's odd part cancels, as expanding
// them shows). Symmetric, so it is its own transpose.
inline RotationJacobian midpointInverseJacobian(const Vec3& theta) {
    const double a2 = theta.squaredNorm();
    double beta;
    if (a2 < rotation_series::kSmallAngle * rotation_series::kSmallAngle) {
        // (h / sin h - 1) / (4 h^2) with h = a / 2, by its series to a^6
        beta = (1.0 / 24 + a2 * (7.0 / 5760)) + a2 * a2 * (31.0 / 967680 + a2 * (127.0 / 154828800));
    } else {
        const double h = 0.5 * std::sqrt(a2);
        beta = (h / std::sin(h) - 1) / a2;
    }
    return {theta, 0, -beta};
}

// A change d of theta turns exp(theta) on the right by rightJacobian(theta) * d.
inline RotationJacobian rightJacobian(const Vec3& theta) {
    const double a2 = theta.squaredNorm();
    double b, c;
    if (a2 < rotation_series::kSmallAngle * rotation_series::kSmallAngle) {
        const double a4 = a2 * a2;
        b = (0.5 - a2 * (1.0 / 24)) + a4 * (1.0 / 720 - a2 * (1.0 / 40320));
        c = (1.0 / 6 - a2 * (1.0 / 120)) + a4 * (1.0 / 5040 - a2 * (1.0 / 362880));
    } else {
        const double a = std::sqrt(a2);
        b = (1 - std::cos(a)) / a2;
        c = (a - std::sin(a)) / (a2 * a);
    }
    return {theta, b, c};
}

}  // namespace sylva::dem

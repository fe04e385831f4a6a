#include "libdem/RotationVector.hpp"

#include <cmath>

namespace sylva::dem {

namespace {

// Below these the series are used (the first omitted term is given for each).
constexpr double kSmallHalfSine = 0.05;  // sin(angle / 2): next term x^10 / 11 < 1e-14
constexpr double kSmallAngle = 0.1;      // rad: next terms ~ a^8 / 4e6 < 3e-15

}  // namespace

Vec3 rotationVector(Quat q) {
    if (q.w() < 0) q.coeffs() *= -1;
    const double s = q.vec().norm();
    if (s < kSmallHalfSine * q.w()) {
        // angle = 2 atan(x) with x = s / w: 2 atan(x) / s = (2 / w) (1 - x^2/3 + x^4/5 - x^6/7 + x^8/9)
        const double x2 = s * s / (q.w() * q.w());
        return 2 / q.w() * (1 - x2 * (1.0 / 3 - x2 * (1.0 / 5 - x2 * (1.0 / 7 - x2 / 9)))) * q.vec();
    }
    return 2 * std::atan2(s, q.w()) / s * q.vec();
}

Quat fromRotationVector(const Vec3& theta) {
    const double a2 = theta.squaredNorm();
    if (a2 < kSmallAngle * kSmallAngle) {
        // h = angle / 2: cos h and sin(h) / angle by their series to h^8
        const double h2 = 0.25 * a2;
        const double c = 1 - h2 * (1.0 / 2 - h2 * (1.0 / 24 - h2 * (1.0 / 720 - h2 / 40320)));
        const double sOverAngle = 0.5 * (1 - h2 * (1.0 / 6 - h2 * (1.0 / 120 - h2 * (1.0 / 5040 - h2 / 362880))));
        return Quat(c, sOverAngle * theta.x(), sOverAngle * theta.y(), sOverAngle * theta.z());
    }
    const double angle = std::sqrt(a2);
    return Quat(Eigen::AngleAxisd(angle, theta / angle));
}

RotationJacobian inverseLeftJacobian(const Vec3& theta) {
    const double a2 = theta.squaredNorm();
    double c;
    if (a2 < kSmallAngle * kSmallAngle) {
        c = 1.0 / 12 + a2 * (1.0 / 720 + a2 * (1.0 / 30240 + a2 / 1209600));
    } else {
        const double a = std::sqrt(a2);
        c = 1 / a2 - (1 + std::cos(a)) / (2 * a * std::sin(a));
    }
    return {theta, 0.5, c};
}

RotationJacobian rightJacobian(const Vec3& theta) {
    const double a2 = theta.squaredNorm();
    double b, c;
    if (a2 < kSmallAngle * kSmallAngle) {
        b = 0.5 - a2 * (1.0 / 24 - a2 * (1.0 / 720 - a2 / 40320));
        c = 1.0 / 6 - a2 * (1.0 / 120 - a2 * (1.0 / 5040 - a2 / 362880));
    } else {
        const double a = std::sqrt(a2);
        b = (1 - std::cos(a)) / a2;
        c = (a - std::sin(a)) / (a2 * a);
    }
    return {theta, b, c};
}

}  // namespace sylva::dem

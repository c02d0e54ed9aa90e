#include "rigid/RotationVector.h"

#include <cmath>

namespace airtrap {

Quatd RotationVector::toQuaternion(const Vec3d& phi) {
    const double angle = phi.norm();
    // sin(θ/2)/θ, by its Taylor series near 0 where the quotient loses precision or divides by
    // zero; with θ < 1e-3 the first omitted term (θ⁶/645120) is below 1e-23.
    double sinHalfOverAngle = 0.0;
    if (angle < 1e-3) {
        const double a2 = angle * angle;
        sinHalfOverAngle = 0.5 - a2 / 48.0 + a2 * a2 / 3840.0;
    } else {
        sinHalfOverAngle = std::sin(0.5 * angle) / angle;
    }
    const Vec3d v = sinHalfOverAngle * phi;
    return Quatd(std::cos(0.5 * angle), v.x(), v.y(), v.z());
}

Vec3d RotationVector::fromQuaternion(const Quatd& q) {
    // q and −q are the same rotation; the one with w ≥ 0 turns by at most π.
    const double sign = q.w() < 0.0 ? -1.0 : 1.0;
    const double w = sign * q.w();
    const Vec3d v = sign * q.vec();
    const double sinHalf = v.norm();
    // atan2 keeps full precision for both small and near-π angles (acos(w) does not).
    const double angle = 2.0 * std::atan2(sinHalf, w);
    if (sinHalf < 1e-12)
        return (2.0 / w) * v; // θ/sin(θ/2) → 2/w (1 + O(θ²)), exact to rounding here
    return (angle / sinHalf) * v;
}

} // namespace airtrap

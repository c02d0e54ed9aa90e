#pragma once
// The exponential map between rotation vectors and unit quaternions. A rotation vector φ means a
// turn by |φ| radians about φ/|φ|; exp gives the quaternion (cos(|φ|/2), sin(|φ|/2) φ/|φ|),
// i.e. the quaternion exponential of the pure quaternion (0, φ/2). Both the integrator
// (q ← exp(ω Δt) q) and keyframe slerp (exp(s log(q₁ q₀⁻¹)) q₀) go through these two functions,
// so a kinematic body integrated with its keyframe velocity lands on the path.
#include "core/Math.h"

namespace airtrap {

class RotationVector {
public:
    //! Unit quaternion of a turn by |φ| (rad) about φ/|φ|; exact identity for φ = 0.
    static Quatd toQuaternion(const Vec3d& phi);
    //! Rotation vector of `q` (need not be normalised), on the shortest arc: |φ| ≤ π.
    static Vec3d fromQuaternion(const Quatd& q);
};

} // namespace airtrap

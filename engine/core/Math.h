#pragma once
// Math aliases. Particle state is float (memory bandwidth); rigid bodies, time and scene values
// are double.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace airtrap {

using Vec3f = Eigen::Vector3f;
//! xyz and a zero: one aligned SIMD register (SSE, NEON) per vector in the solvers' inner loops.
using Vec4f = Eigen::Vector4f;
using Vec3d = Eigen::Vector3d;
using Vec3i = Eigen::Vector3i;
using Mat3d = Eigen::Matrix3d;
using Quatd = Eigen::Quaterniond;

//! v as xyz0.
inline Vec4f padded(const Vec3f& v) {
    return Vec4f(v.x(), v.y(), v.z(), 0.0f);
}

inline constexpr double kPi = 3.14159265358979323846;

//! Axis-aligned box in double precision.
struct Aabb {
    Vec3d min = Vec3d::Zero();
    Vec3d max = Vec3d::Zero();

    Vec3d size() const { return max - min; }
    Vec3d center() const { return 0.5 * (min + max); }
    bool contains(const Vec3d& p) const {
        return (p.array() >= min.array()).all() && (p.array() <= max.array()).all();
    }
    double volume() const { return size().prod(); }
    //! The box grown by `margin` on every side.
    Aabb expanded(double margin) const {
        return {min - Vec3d::Constant(margin), max + Vec3d::Constant(margin)};
    }
};

} // namespace airtrap

#pragma once
// The scene's rotations: three angles in degrees, turning about the world x axis first, then y,
// then z (Blender's default "XYZ Euler" order), so a rotation typed in one tool reads the same
// in the other.
#include "core/Math.h"

#include <numbers>

namespace airtrap {

struct EulerRotation {
    static Quatd fromDegrees(const Vec3d& degrees) {
        const Vec3d radians = degrees * (std::numbers::pi / 180.0);
        return Quatd(Eigen::AngleAxisd(radians.z(), Vec3d::UnitZ()) *
                     Eigen::AngleAxisd(radians.y(), Vec3d::UnitY()) *
                     Eigen::AngleAxisd(radians.x(), Vec3d::UnitX()));
    }
};

} // namespace airtrap

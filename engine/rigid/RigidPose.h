#pragma once
#include "core/Math.h"

namespace airtrap {

//! Where a body is: its reference point (m, world) and orientation (unit, body → world).
struct RigidPose {
    Vec3d position = Vec3d::Zero();
    Quatd orientation = Quatd::Identity();

    bool operator==(const RigidPose& other) const = default;
};

} // namespace airtrap

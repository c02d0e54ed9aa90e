#pragma once
#include "core/Math.h"

namespace airtrap {

//! How a body moves: velocity of its reference point (m/s) and angular velocity about it
//! (rad/s), both in the world frame. A material point x moves at linear + angular × (x − X).
struct RigidVelocity {
    Vec3d linear = Vec3d::Zero();
    Vec3d angular = Vec3d::Zero();

    bool operator==(const RigidVelocity& other) const = default;
};

} // namespace airtrap

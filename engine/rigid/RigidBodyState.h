#pragma once
// The part of a rigid body that changes every step: what the frame cache stores per body (chunk
// BODY, docs/CACHE_FORMAT.md) and what `info --json` reports (docs/CLI.md "info"). Mass, inertia,
// shape and name are fixed for a bake and come from the scene.
#include "core/Math.h"

namespace airtrap {

struct RigidBodyState {
    //! m, world. The centre of mass for a dynamic body; the origin of the body frame, which the
    //! motion is described about, for a static or kinematic one.
    Vec3d position = Vec3d::Zero();
    //! Unit quaternion, body → world (y up).
    Quatd orientation = Quatd::Identity();
    Vec3d linearVelocity = Vec3d::Zero();  //!< m/s, world, of `position`
    Vec3d angularVelocity = Vec3d::Zero(); //!< rad/s, world, about `position`

    //! Exact comparison (bit patterns aside from ±0), as a resumed bake must reproduce.
    bool operator==(const RigidBodyState& other) const = default;
};

} // namespace airtrap

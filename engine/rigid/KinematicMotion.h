#pragma once
// The prescribed motion of a kinematic body: it moves the water, the water does not move it.
#include "rigid/KeyframedPath.h"
#include "rigid/RigidPose.h"
#include "rigid/RigidVelocity.h"

#include <variant>

namespace airtrap {

class KinematicMotion {
public:
    //! Constant linear velocity (m/s) and angular velocity about the body's reference point
    //! (rad/s), both in the world frame, from the body's pose at t = 0.
    struct ConstantVelocity {
        Vec3d linear = Vec3d::Zero();
        Vec3d angular = Vec3d::Zero();
    };

    KinematicMotion(const RigidPose& startPose, const ConstantVelocity& velocity)
        : startPose_(startPose), motion_(velocity) {}
    explicit KinematicMotion(KeyframedPath path) : motion_(std::move(path)) {}

    //! Pose at time `t` (s, t ≥ 0). Constant velocity: X₀ + V t and exp(ω t) q₀, exact for any
    //! t rather than accumulated step by step.
    RigidPose poseAt(double t) const;
    //! The time derivative of poseAt, chosen so that the solver's X + V Δt, exp(ω Δt) q from
    //! poseAt(t) reproduces poseAt(t + Δt) while no keyframe lies in between.
    RigidVelocity velocityAt(double t) const;

private:
    RigidPose startPose_; //!< used by ConstantVelocity only
    std::variant<ConstantVelocity, KeyframedPath> motion_;
};

} // namespace airtrap

#pragma once
// A prescribed path through keyframed poses, for kinematic bodies (a paddle, a moving container).
#include "rigid/RigidPose.h"
#include "rigid/RigidVelocity.h"

#include <vector>

namespace airtrap {

//! Piecewise linear position and slerp orientation between keyframes; before the first and
//! after the last keyframe the body holds that keyframe's pose at rest.
//!
//! Why linear and not Catmull–Rom: within a segment the velocity is then constant and equal to
//! the segment's finite difference, so a body the solver moves from poseAt(t) with
//! velocityAt(t) lands exactly on poseAt(t + Δt); and the path never overshoots its keyframes
//! (a Catmull–Rom container could swing through a wall between two keys). The price is a
//! velocity jump at each keyframe; add keyframes for a smoother start or stop.
class KeyframedPath {
public:
    struct Keyframe {
        double time = 0.0; //!< s
        Vec3d position = Vec3d::Zero();
        Quatd orientation = Quatd::Identity(); //!< normalised on construction
    };

    //! At least one keyframe, finite and strictly increasing times, non-zero quaternions; throws
    //! Error(InvalidInput) otherwise. Orientation takes the shortest arc between two keyframes,
    //! so a turn by more than 180° needs a keyframe in between.
    explicit KeyframedPath(std::vector<Keyframe> keyframes);

    //! Pose at time `t` (s); exactly the keyframe's pose at a keyframe's time.
    RigidPose poseAt(double t) const;
    //! Velocity of the segment containing `t` (s), t_i ≤ t < t_{i+1}: its finite difference
    //! (p_{i+1} − p_i)/(t_{i+1} − t_i) and log(q_{i+1} q_i⁻¹)/(t_{i+1} − t_i). Zero outside the
    //! keyframes' range, where the pose is held. At a keyframe it is the velocity of the
    //! segment that starts there, as the solver steps forward in time.
    RigidVelocity velocityAt(double t) const;

    const std::vector<Keyframe>& keyframes() const { return keyframes_; }

private:
    //! Index of the segment with t_i ≤ t < t_{i+1}; only for t inside the range.
    std::size_t segmentAt(double t) const;

    std::vector<Keyframe> keyframes_;
    std::vector<RigidVelocity> segmentVelocities_; //!< one per segment, computed once
};

} // namespace airtrap

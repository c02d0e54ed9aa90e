#include "rigid/KeyframedPath.h"

#include "core/Error.h"
#include "rigid/RotationVector.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace airtrap {
namespace {

[[noreturn]] void invalidPath(const std::string& what) {
    throw Error(ErrorKind::InvalidInput, "keyframed path: " + what);
}

void checkKeyframes(const std::vector<KeyframedPath::Keyframe>& keyframes) {
    if (keyframes.empty())
        invalidPath("needs at least one keyframe");
    for (std::size_t i = 0; i < keyframes.size(); ++i) {
        const KeyframedPath::Keyframe& key = keyframes[i];
        const std::string which = "keyframe " + std::to_string(i);
        if (!std::isfinite(key.time) || !key.position.allFinite() ||
            !key.orientation.coeffs().allFinite())
            invalidPath(which + " is not finite");
        if (key.orientation.norm() == 0.0)
            invalidPath(which + " has a zero quaternion");
        if (i > 0 && key.time <= keyframes[i - 1].time)
            invalidPath(which + " (t = " + std::to_string(key.time) +
                        " s) is not later than the one before it");
    }
}

RigidVelocity segmentVelocity(const KeyframedPath::Keyframe& from,
                              const KeyframedPath::Keyframe& to) {
    const double duration = to.time - from.time;
    // World-frame turn from one keyframe to the next: q₁ = exp(φ) q₀, so slerp(s) = exp(s φ) q₀.
    const Vec3d turn =
        RotationVector::fromQuaternion(to.orientation * from.orientation.conjugate());
    return {(to.position - from.position) / duration, turn / duration};
}

} // namespace

KeyframedPath::KeyframedPath(std::vector<Keyframe> keyframes) : keyframes_(std::move(keyframes)) {
    checkKeyframes(keyframes_);
    for (Keyframe& key : keyframes_)
        key.orientation.normalize();
    for (std::size_t i = 0; i + 1 < keyframes_.size(); ++i)
        segmentVelocities_.push_back(segmentVelocity(keyframes_[i], keyframes_[i + 1]));
}

std::size_t KeyframedPath::segmentAt(double t) const {
    const auto after =
        std::upper_bound(keyframes_.begin(), keyframes_.end(), t,
                         [](double time, const Keyframe& key) { return time < key.time; });
    return static_cast<std::size_t>(after - keyframes_.begin()) - 1;
}

RigidPose KeyframedPath::poseAt(double t) const {
    if (t <= keyframes_.front().time)
        return {keyframes_.front().position, keyframes_.front().orientation};
    if (t >= keyframes_.back().time)
        return {keyframes_.back().position, keyframes_.back().orientation};
    const std::size_t i = segmentAt(t);
    const Keyframe& key = keyframes_[i];
    const double elapsed = t - key.time;
    if (elapsed == 0.0) // exactly the keyframe, not the keyframe after a round trip through exp
        return {key.position, key.orientation};
    // The same expressions the solver's integration evaluates: X + V Δt and exp(ω Δt) q.
    const RigidVelocity& v = segmentVelocities_[i];
    const Quatd orientation = RotationVector::toQuaternion(v.angular * elapsed) * key.orientation;
    return {key.position + v.linear * elapsed, orientation.normalized()};
}

RigidVelocity KeyframedPath::velocityAt(double t) const {
    if (t < keyframes_.front().time || t >= keyframes_.back().time)
        return {};
    return segmentVelocities_[segmentAt(t)];
}

} // namespace airtrap

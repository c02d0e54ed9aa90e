#include "rigid/KinematicMotion.h"

#include "rigid/RotationVector.h"

namespace airtrap {
namespace {

// Overload set for std::visit.
template <typename... Fs>
struct Visitor : Fs... {
    using Fs::operator()...;
};
// Written out for clang 16, which does not deduce an aggregate's arguments by itself.
template <typename... Fs>
Visitor(Fs...) -> Visitor<Fs...>;

} // namespace

RigidPose KinematicMotion::poseAt(double t) const {
    return std::visit(Visitor{[&](const ConstantVelocity& v) {
                                  const Quatd turn = RotationVector::toQuaternion(v.angular * t);
                                  return RigidPose{startPose_.position + v.linear * t,
                                                   (turn * startPose_.orientation).normalized()};
                              },
                              [&](const KeyframedPath& path) { return path.poseAt(t); }},
                      motion_);
}

RigidVelocity KinematicMotion::velocityAt(double t) const {
    return std::visit(Visitor{[](const ConstantVelocity& v) {
                                  return RigidVelocity{v.linear, v.angular};
                              },
                              [&](const KeyframedPath& path) { return path.velocityAt(t); }},
                      motion_);
}

} // namespace airtrap

#include "rigid/RigidBody.h"

namespace airtrap {

RigidBody::RigidBody(std::string name, BoundaryParticles boundary, BodyShape shape,
                     const RigidPose& pose)
    : name_(std::move(name)), boundary_(std::move(boundary)), shape_(std::move(shape)) {
    state_.position = pose.position;
    state_.orientation = pose.orientation;
}

const char* RigidBody::motionName(Motion motion) {
    switch (motion) {
    case Motion::Static:
        return "static";
    case Motion::Dynamic:
        return "dynamic";
    case Motion::Kinematic:
        return "kinematic";
    }
    return "";
}

void RigidBody::makeDynamic(const RigidBodyInertia& inertia, double volume,
                            const Vec3d& centreOfMass, const RigidVelocity& velocity) {
    motion_ = Motion::Dynamic;
    inertia_ = inertia;
    volume_ = volume;
    const Vec3f shift = centreOfMass.cast<float>();
    for (Vec3f& x : boundary_.positions)
        x -= shift;
    state_.position += state_.orientation * (centreOfMass - shapeOffset_);
    shapeOffset_ = centreOfMass;
    state_.linearVelocity = velocity.linear;
    state_.angularVelocity = velocity.angular;
}

void RigidBody::makeKinematic(KinematicMotion motion) {
    motion_ = Motion::Kinematic;
    kinematic_ = std::move(motion);
    followPath(0.0);
}

void RigidBody::setMaterials(const ContactMaterial& water, const ContactMaterial& bodies) {
    waterMaterial_ = water;
    bodyMaterial_ = bodies;
}

void RigidBody::followPath(double t) {
    if (!kinematic_)
        return;
    const RigidPose pose = kinematic_->poseAt(t);
    const RigidVelocity velocity = kinematic_->velocityAt(t);
    state_.position = pose.position;
    state_.orientation = pose.orientation;
    state_.linearVelocity = velocity.linear;
    state_.angularVelocity = velocity.angular;
}

RigidPose RigidBody::shapePose() const {
    return {state_.position - state_.orientation * shapeOffset_, state_.orientation};
}

Vec3d RigidBody::toShapeFrame(const Vec3d& world) const {
    return state_.orientation.conjugate() * (world - state_.position) + shapeOffset_;
}

double RigidBody::signedDistance(const Vec3d& x) const {
    return shape_.signedDistance(toShapeFrame(x));
}

double RigidBody::clearanceBound(const Vec3d& x) const {
    return shape_.clearanceBound(toShapeFrame(x));
}

Vec3d RigidBody::normalAt(const Vec3d& x) const {
    return state_.orientation * shape_.normal(toShapeFrame(x));
}

Vec3d RigidBody::surfacePoint(std::size_t k) const {
    const Vec3d local = boundary_.positions[k].cast<double>() +
                        surfaceOffset_ * boundary_.normals[k].cast<double>();
    return state_.orientation * local + state_.position;
}

} // namespace airtrap

#pragma once
// A body the water interacts with through its boundary particles (DESIGN §4). This version has
// static bodies (the container, box obstacles); dynamic and kinematic motion build on the same
// pose and velocity fields.
#include "rigid/BoundaryParticles.h"

#include <string>

namespace airtrap {

class RigidBody {
public:
    enum class Motion { Static };

    //! `boundary` is in the body's frame, whose origin sits at `position` in the world.
    RigidBody(std::string name, Motion motion, BoundaryParticles boundary, const Vec3d& position)
        : name_(std::move(name)), motion_(motion), boundary_(std::move(boundary)),
          position_(position) {}

    const std::string& name() const { return name_; }
    Motion motion() const { return motion_; }
    static const char* motionName(Motion motion) {
        switch (motion) {
        case Motion::Static:
            return "static";
        }
        return "";
    }
    const BoundaryParticles& boundary() const { return boundary_; }

    const Vec3d& position() const { return position_; }
    const Quatd& orientation() const { return orientation_; }
    const Vec3d& linearVelocity() const { return linearVelocity_; }
    const Vec3d& angularVelocity() const { return angularVelocity_; }

    Vec3f toWorld(const Vec3f& local) const {
        return (orientation_ * local.cast<double>() + position_).cast<float>();
    }
    Vec3f directionToWorld(const Vec3f& local) const {
        return (orientation_ * local.cast<double>()).cast<float>();
    }
    //! Velocity of the body's material point at world position x.
    Vec3f velocityAt(const Vec3f& x) const {
        return (linearVelocity_ + angularVelocity_.cross(x.cast<double>() - position_))
            .cast<float>();
    }

private:
    std::string name_;
    Motion motion_;
    BoundaryParticles boundary_;
    Vec3d position_;
    Quatd orientation_ = Quatd::Identity();
    Vec3d linearVelocity_ = Vec3d::Zero();
    Vec3d angularVelocity_ = Vec3d::Zero();
};

} // namespace airtrap

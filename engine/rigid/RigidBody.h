#pragma once
// A body the water interacts with through its boundary particles (docs/METHOD.md "Boundary
// particles"): the static container and obstacles, and the scene's static, dynamic and kinematic
// bodies.
//
// Frames: the shape frame is the one the scene describes the solid in (a box's centre, a mesh
// file's origin). The body frame is the one the boundary particles and the state live in: the
// shape frame itself for static and kinematic bodies, the shape frame moved to the centre of
// mass for dynamic ones, where the Newton–Euler equations are simplest.
#include "rigid/BodyShape.h"
#include "rigid/BoundaryParticles.h"
#include "rigid/ContactMaterial.h"
#include "rigid/KinematicMotion.h"
#include "rigid/RigidBodyInertia.h"
#include "rigid/RigidBodyState.h"

#include <optional>
#include <string>

namespace airtrap {

class RigidBody {
public:
    enum class Motion { Static, Dynamic, Kinematic };

    //! A static body at `pose` (of its shape frame); `boundary` is in the shape frame, on the
    //! surface the water sees.
    RigidBody(std::string name, BoundaryParticles boundary, BodyShape shape, const RigidPose& pose);

    //! Lets forces and contacts move the body. `inertia` is about the centre of mass, which
    //! lies at `centreOfMass` in the shape frame; `volume` (m³) is the solid's, which sets the
    //! water it carries along (its added mass); `velocity` is the centre of mass's velocity and
    //! the angular velocity at t = 0.
    void makeDynamic(const RigidBodyInertia& inertia, double volume, const Vec3d& centreOfMass,
                     const RigidVelocity& velocity);
    //! Moves the body along `motion` (of its shape frame), whatever the water does.
    void makeKinematic(KinematicMotion motion);
    //! `water` for water particles hitting the body, `bodies` for other bodies.
    void setMaterials(const ContactMaterial& water, const ContactMaterial& bodies);
    //! How far the solid's surface lies from the boundary layer along the layer's normals (m,
    //! towards the water): the layer sits half a particle spacing inside the solid, the water
    //! particles nearest it half a spacing outside, so that the water's volume ends at the
    //! surface.
    void setSurfaceOffset(double offset) { surfaceOffset_ = offset; }

    const std::string& name() const { return name_; }
    Motion motion() const { return motion_; }
    static const char* motionName(Motion motion);
    bool isDynamic() const { return motion_ == Motion::Dynamic; }
    bool isMoving() const { return motion_ != Motion::Static; }

    const BoundaryParticles& boundary() const { return boundary_; }
    const BodyShape& shape() const { return shape_; }
    const RigidBodyInertia& inertia() const { return inertia_; }
    //! m³ of solid a dynamic body displaces when immersed (0 for other bodies).
    double volume() const { return volume_; }
    const ContactMaterial& waterMaterial() const { return waterMaterial_; }
    const ContactMaterial& bodyMaterial() const { return bodyMaterial_; }
    //! Where the body frame's origin lies in the shape frame (the centre of mass of a dynamic
    //! body, zero otherwise).
    const Vec3d& shapeOffset() const { return shapeOffset_; }
    double surfaceOffset() const { return surfaceOffset_; }

    const RigidBodyState& state() const { return state_; }
    void setState(const RigidBodyState& state) { state_ = state; }
    //! Puts a kinematic body where its motion has it at time `t` (s); no-op for other bodies.
    void followPath(double t);

    const Vec3d& position() const { return state_.position; }
    const Quatd& orientation() const { return state_.orientation; }
    const Vec3d& linearVelocity() const { return state_.linearVelocity; }
    const Vec3d& angularVelocity() const { return state_.angularVelocity; }
    //! Pose of the shape frame, for drawing the shape where the body is.
    RigidPose shapePose() const;

    Vec3f toWorld(const Vec3f& local) const {
        return (state_.orientation * local.cast<double>() + state_.position).cast<float>();
    }
    Vec3f directionToWorld(const Vec3f& local) const {
        return (state_.orientation * local.cast<double>()).cast<float>();
    }
    //! Velocity of the body's material point at world position x.
    Vec3d velocityAt(const Vec3d& x) const {
        return state_.linearVelocity + state_.angularVelocity.cross(x - state_.position);
    }
    Vec3f velocityAt(const Vec3f& x) const {
        const Vec3d point = x.cast<double>();
        return velocityAt(point).cast<float>();
    }
    //! Signed distance (m, negative inside) and outward world normal of the solid at world x.
    double signedDistance(const Vec3d& x) const;
    Vec3d normalAt(const Vec3d& x) const;
    //! BodyShape::clearanceBound at world x.
    double clearanceBound(const Vec3d& x) const;
    //! World position of the solid's surface under boundary particle `k`.
    Vec3d surfacePoint(std::size_t k) const;

private:
    Vec3d toShapeFrame(const Vec3d& world) const;

    std::string name_;
    Motion motion_ = Motion::Static;
    BoundaryParticles boundary_;
    BodyShape shape_;
    Vec3d shapeOffset_ = Vec3d::Zero();
    double surfaceOffset_ = 0.0;
    double volume_ = 0.0;
    RigidBodyInertia inertia_ = RigidBodyInertia::infinite();
    ContactMaterial waterMaterial_;
    ContactMaterial bodyMaterial_;
    std::optional<KinematicMotion> kinematic_;
    RigidBodyState state_;
};

} // namespace airtrap

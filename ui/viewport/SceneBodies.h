#pragma once
// The scene's rigid bodies as the viewport shows them: each body's surface, its colour's motion
// and where it is — its scene pose in edit mode (a keyframed body at its first keyframe), or the
// pose a cached frame recorded in playback. Drawing and picking read the same poses.
#include "controller/BodyMeshCache.h"
#include "document/SceneItem.h"
#include "rigid/RigidBodyState.h"
#include "scene/Scene.h"
#include "viewport/PickHit.h"
#include "viewport/Ray.h"

#include <QMatrix4x4>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace airtrap {

class SceneBodies {
public:
    struct Body {
        SceneItem item;                         //!< bodies[i]
        std::string motion;                     //!< "static", "dynamic" or "kinematic"
        std::shared_ptr<const SolidMesh> solid; //!< null: nothing to draw (unusable mesh)
        Vec3d centreOfMass = Vec3d::Zero();     //!< shape frame
        QMatrix4x4 scenePose;                   //!< shape frame → world, in edit mode
        QMatrix4x4 pose;                        //!< shape frame → world, as shown now
        float boundingRadius = 0.0f;            //!< of the solid, m
    };

    SceneBodies() = default;
    //! Every body of `scene` in scene order, at its scene pose; meshes come from `meshes`.
    SceneBodies(const Scene& scene, BodyMeshCache& meshes);

    const std::vector<Body>& bodies() const { return bodies_; }

    //! Playback: shows each body where `states` (a frame's SimulationState::bodies, one per
    //! body in scene order) has it. Bodies without a state, and every body when `states` is
    //! null, return to their scene pose.
    void showStates(const std::vector<RigidBodyState>* states);

    //! The nearest body whose surface the ray crosses.
    std::optional<PickHit> pick(const Ray& ray) const;

    //! Pose of the shape frame from a recorded state: a dynamic body's state is at its centre of
    //! mass, a static or kinematic body's at its shape origin.
    static QMatrix4x4 shapePose(const RigidBodyState& state, const std::string& motion,
                                const Vec3d& centreOfMass);

private:
    static QMatrix4x4 scenePoseOf(const Scene& scene, const RigidBodySettings& body);

    std::vector<Body> bodies_;
};

} // namespace airtrap

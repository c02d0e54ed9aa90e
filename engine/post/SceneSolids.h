#pragma once
// The solids of a baked scene as the post stage needs them: the tank, the static obstacles and
// the rigid bodies, each as a shape to measure distances to (the free-surface mesh drops the
// water's polygons near them, paper §4.1) and, except the tank, as a mesh to export. Built once
// per post run — mesh bodies load their file and distance field here — and placed per frame by
// FrameSolids.
#include "post/NamedMesh.h"
#include "rigid/BodyShape.h"
#include "rigid/RigidPose.h"
#include "scene/Scene.h"
#include "sim/SimulationState.h"

#include <string>
#include <vector>

namespace airtrap {

class SceneSolids {
public:
    struct Solid {
        std::string name;
        BodyShape shape;      //!< in the shape frame
        TriangleMesh mesh;    //!< shape frame; empty for the tank, which is not exported
        Vec3d centreOfMass;   //!< shape frame; a dynamic body's cached position is this point
        bool dynamic = false; //!< its cached position is the centre of mass
        int stateIndex = -1;  //!< in SimulationState::bodies; −1 for fixed scenery
        RigidPose scenePose;  //!< where it stands when the frame does not say
    };

    //! Throws Error(InvalidInput) naming the scene, the body and the file for a mesh that cannot
    //! be loaded.
    explicit SceneSolids(const Scene& scene);

    const std::vector<Solid>& solids() const { return solids_; }
    //! Shape frame → world for solid `index` in `state`.
    RigidPose poseIn(std::size_t index, const SimulationState& state) const;

private:
    void addBody(const Scene& scene, std::size_t index);

    std::vector<Solid> solids_;
};

} // namespace airtrap

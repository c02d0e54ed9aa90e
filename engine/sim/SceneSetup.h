#pragma once
// Turns a scene into the things the solver works on: the rigid bodies with their boundary
// particles, and the water particles of the fluid blocks at t = 0.
#include "rigid/RigidBody.h"
#include "scene/Scene.h"
#include "sim/SimulationState.h"

#include <vector>

namespace airtrap {

class SceneSetup {
public:
    //! The static container (open top) first, then the box obstacles, then the scene's bodies
    //! in their order, each with one layer of boundary particles half a spacing outside the
    //! surface the water sees, so that water particles filled half a spacing inside it start one
    //! spacing away from the layer. Throws Error(InvalidInput) for a body that cannot be built
    //! (an unusable mesh, keyframes that do not form a path).
    static std::vector<RigidBody> buildBodies(const Scene& scene);
    //! How many of buildBodies' bodies come before the scene's `bodies`: the container and the
    //! obstacles.
    static std::size_t sceneryCount(const Scene& scene);
    //! The state of each of the scene's bodies at t = 0, in scene order, from buildBodies' list.
    static std::vector<RigidBodyState> initialBodyStates(const Scene& scene,
                                                         const std::vector<RigidBody>& bodies);

    //! Fills every fluid block on the particle lattice, skipping points outside the container,
    //! inside obstacles or `bodies` (buildBodies' list; or closer than half a spacing to them) or
    //! already filled by an earlier block. Densities start hydrostatic (inverse Tait at the
    //! depth below the top of its particle layers), so a resting pool starts at rest (DFSPH sums
    //! its own).
    static void fillFluid(const Scene& scene, const std::vector<RigidBody>& bodies,
                          SimulationState& state);
};

} // namespace airtrap

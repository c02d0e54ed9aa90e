#pragma once
// Turns a scene into the things the solver works on: the rigid bodies with their boundary
// particles, and the water particles of the fluid blocks at t = 0.
#include "rigid/RigidBody.h"
#include "scene/Scene.h"
#include "sim/SimulationState.h"

#include <vector>

namespace airtrap {

class WcsphSolver;

class SceneSetup {
public:
    //! The static container (open top) first, then the box obstacles, each with one layer of
    //! boundary particles half a spacing outside the surface the water sees, so that water
    //! particles filled half a spacing inside it start one spacing away from the layer.
    static std::vector<RigidBody> buildBodies(const Scene& scene);

    //! Fills every fluid block on the particle lattice, skipping points outside the container,
    //! inside obstacles or already filled by an earlier block. Densities start hydrostatic
    //! (inverse Tait at the depth below the block's top), so a resting pool starts at rest.
    static void fillFluid(const Scene& scene, const WcsphSolver& solver, SimulationState& state);
};

} // namespace airtrap

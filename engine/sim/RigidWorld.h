#pragma once
// The rigid bodies of a simulation and how a step moves them (paper §3.3, docs/METHOD.md
// "Impulse-based boundary force", "Bubbles"): the scenery (container and obstacles, static),
// the scene's bodies, and one sphere body per living bubble, in that order. Each step places
// them from the state, and after the water's forces moves the dynamic ones under the water's
// reaction and gravity, the bubbles' steered rise (eq. 5), drag (eq. 6) and pair impulses, and
// their contacts; then copies them back into the state.
#include "bubbles/BubbleDynamics.h"
#include "rigid/RigidBody.h"
#include "scene/Scene.h"
#include "sim/SimulationState.h"
#include "sph/BoundaryModel.h"
#include "sph/RigidCoupling.h"

#include <optional>
#include <vector>

namespace airtrap {

class RigidWorld {
public:
    //! `bodies` holds the scenery first, `sceneryCount` of them (static, not in the state), then
    //! the bodies whose states SimulationState::bodies carries in the same order. With bubbles
    //! enabled, the state's bubbles join them as bodies; `kernel` is the water's.
    RigidWorld(std::vector<RigidBody> bodies, std::size_t sceneryCount,
               const SolverSettings& solver, const BubbleSettings& bubbles,
               const CubicSplineKernel& kernel);

    const std::vector<RigidBody>& bodies() const { return bodies_; }
    //! Index in bodies() of the first bubble's body; the bodies before it are the scene's.
    std::size_t firstBubbleBody() const { return firstBubble_; }
    //! The scenery and the scene's bodies: what a new bubble may not start in.
    std::vector<const RigidBody*> solids() const;

    //! Whether the boundary particles must be placed again this step: a body moves, or bubbles
    //! exist or have just been deleted.
    bool needPlacing(const SimulationState& state) const;
    //! Makes the bodies those of `state` (kinematic ones on their paths at state.time, bubbles
    //! as the state's bubbles). Throws Error(CacheCorrupt) for a state of another scene.
    void place(SimulationState& state);
    //! Puts the kinematic bodies of `state` where their paths have them at state.time.
    void followPaths(SimulationState& state);

    //! Whether the water around the bubbles is to be measured in the step of `dt` s from
    //! state.time.
    bool bubbleSurroundingsDue(const SimulationState& state, double dt) const;
    //! Measures the water around the bubbles into the state, from the step's sorted water.
    void measureBubbleSurroundings(SimulationState& state, double dt, const NeighborGrid& grid,
                                   const PositionArrays& sortedPositions) const;

    //! Moves the dynamic bodies over `dt` s under `reactions`, the water's force on each
    //! particle of `boundary`'s moving layer, with the bubbles' own forces and impulses, and
    //! stores them in `state`; false when a body's state is no longer finite. Touches no water.
    bool move(SimulationState& state, const BoundaryModel& boundary,
              const std::vector<Vec3d>& reactions, double dt);

private:
    //! Copies the moved bodies back into the state; returns false when one is not finite.
    bool storeMoved(SimulationState& state) const;

    std::vector<RigidBody> bodies_;
    std::size_t sceneryCount_;
    std::size_t firstBubble_; //!< index in bodies_ of the first bubble's body
    bool anyBodyMoves_ = false;
    std::optional<BubbleDynamics> bubbles_;
    RigidCoupling coupling_;
};

} // namespace airtrap

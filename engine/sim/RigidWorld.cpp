#include "sim/RigidWorld.h"

#include "core/Error.h"
#include "scene/SceneSchema.h"

#include <algorithm>

namespace airtrap {

RigidWorld::RigidWorld(std::vector<RigidBody> bodies, std::size_t sceneryCount,
                       const SolverSettings& solver, const BubbleSettings& bubbles,
                       const CubicSplineKernel& kernel)
    : bodies_(std::move(bodies)), sceneryCount_(std::min(sceneryCount, bodies_.size())),
      firstBubble_(bodies_.size()), coupling_(solver.gravity, solver.particleSpacing) {
    for (const RigidBody& body : bodies_)
        anyBodyMoves_ = anyBodyMoves_ || body.isMoving();
    if (bubbles.enabled)
        bubbles_.emplace(bubbles, solver, kernel);
    coupling_.setBubblesFrom(firstBubble_);
    if (solver.divergenceFree())
        coupling_.setBubbleAddedMass(solver.restDensity);
}

std::vector<const RigidBody*> RigidWorld::solids() const {
    std::vector<const RigidBody*> solids;
    for (std::size_t k = 0; k < firstBubble_; ++k)
        solids.push_back(&bodies_[k]);
    return solids;
}

bool RigidWorld::needPlacing(const SimulationState& state) const {
    // Bodies of bubbles deleted since the last step must leave too.
    return anyBodyMoves_ || !state.bubbles.empty() || bodies_.size() != firstBubble_;
}

void RigidWorld::place(SimulationState& state) {
    const std::size_t sceneBodies = firstBubble_ - sceneryCount_;
    if (state.bodies.size() != sceneBodies)
        throw Error(ErrorKind::CacheCorrupt,
                    "the state holds " + std::to_string(state.bodies.size()) +
                        " rigid bodies but the scene has " + std::to_string(sceneBodies) +
                        "; the frame was baked from another scene");
    if (!state.bubbles.empty() && !bubbles_)
        throw Error(ErrorKind::CacheCorrupt, "the state holds bubbles but the scene has " +
                                                 SceneSchema::keyOf(&BubbleSettings::enabled) +
                                                 " = false");
    for (std::size_t k = 0; k < state.bodies.size(); ++k)
        bodies_[sceneryCount_ + k].setState(state.bodies[k]);
    if (bubbles_)
        bubbles_->syncBodies(bodies_, firstBubble_, state.bubbles);
    followPaths(state);
}

void RigidWorld::followPaths(SimulationState& state) {
    for (std::size_t k = 0; k < state.bodies.size(); ++k) {
        RigidBody& body = bodies_.at(sceneryCount_ + k);
        if (body.motion() != RigidBody::Motion::Kinematic)
            continue;
        body.followPath(state.time);
        state.bodies[k] = body.state();
    }
}

bool RigidWorld::bubbleSurroundingsDue(const SimulationState& state, double dt) const {
    return bubbles_ && BubbleDynamics::measureDue(state.time, state.time + dt, state.bubbles);
}

void RigidWorld::measureBubbleSurroundings(SimulationState& state, double dt,
                                           const NeighborGrid& grid,
                                           const PositionArrays& sortedPositions) const {
    bubbles_->measureSurroundings(state.time, state.time + dt, bodies_, firstBubble_, state.bubbles,
                                  state.fluid, sortedPositions, grid);
}

bool RigidWorld::move(SimulationState& state, const BoundaryModel& boundary,
                      const std::vector<Vec3d>& reactions, double dt) {
    if (!bubbles_ || state.bubbles.empty()) {
        coupling_.advance(bodies_, boundary, reactions, dt);
        return storeMoved(state);
    }
    coupling_.advance(
        bodies_, boundary, reactions, dt,
        [&](std::vector<RigidBody>& bodies, const std::vector<Vec3d>& before, double step) {
            bubbles_->applyForces(bodies, firstBubble_, state.bubbles, before, step);
            bubbles_->applyPairImpulses(bodies, firstBubble_);
        });
    return storeMoved(state);
}

bool RigidWorld::storeMoved(SimulationState& state) const {
    const auto finite = [](const RigidBodyState& moved) {
        return moved.position.allFinite() && moved.orientation.coeffs().allFinite() &&
               moved.linearVelocity.allFinite() && moved.angularVelocity.allFinite();
    };
    bool allFinite = true;
    for (std::size_t k = 0; k < state.bodies.size(); ++k) {
        const RigidBody& body = bodies_[sceneryCount_ + k];
        if (!body.isDynamic())
            continue;
        state.bodies[k] = body.state();
        allFinite = allFinite && finite(state.bodies[k]);
    }
    for (std::size_t k = 0; k < state.bubbles.size(); ++k) {
        state.bubbles[k].body = bodies_[firstBubble_ + k].state();
        allFinite = allFinite && finite(state.bubbles[k].body);
    }
    return allFinite;
}

} // namespace airtrap

#pragma once
// Scenes with bubbles placed by hand: the initial state of a scene, with the water inside and
// around each bubble removed, and the bubbles added, handed to a Simulation as if resumed.
#include "sim/Simulation.h"

#include <memory>
#include <vector>

namespace airtrap::test {

inline BubbleState bubbleAt(std::uint32_t id, const Vec3d& centre, double radius,
                            const Vec3d& velocity = Vec3d::Zero()) {
    BubbleState bubble;
    bubble.id = id;
    bubble.birthFrame = 1;
    bubble.radius = radius;
    bubble.body.position = centre;
    bubble.body.linearVelocity = velocity;
    return bubble;
}

//! Drops the particles closer than half a spacing to any bubble's surface.
inline void clearWaterAround(ParticleSet& fluid, const std::vector<BubbleState>& bubbles,
                             double spacing) {
    ParticleSet kept;
    for (std::size_t i = 0; i < fluid.size(); ++i) {
        bool inside = false;
        for (const BubbleState& bubble : bubbles)
            inside = inside || (fluid.positions[i].cast<double>() - bubble.body.position).norm() <
                                   bubble.radius + 0.5 * spacing;
        if (!inside)
            kept.push(fluid.positions[i], fluid.velocities[i], fluid.densities[i],
                           fluid.ids[i]);
    }
    fluid = std::move(kept);
}

inline std::unique_ptr<Simulation> simulationWithBubbles(const Scene& scene,
                                                         std::vector<BubbleState> bubbles) {
    SimulationState state = Simulation(scene).state();
    clearWaterAround(state.fluid, bubbles, scene.solver.particleSpacing);
    state.nextBubbleId = 0;
    for (const BubbleState& bubble : bubbles)
        state.nextBubbleId = std::max(state.nextBubbleId, bubble.id + 1);
    state.bubbles = std::move(bubbles);
    return std::make_unique<Simulation>(scene, std::move(state));
}

} // namespace airtrap::test

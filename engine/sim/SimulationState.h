#pragma once
// Everything needed to continue a bake bit-for-bit: the cache stores exactly this per frame.
#include "bubbles/BubbleState.h"
#include "bubbles/BubbleTally.h"
#include "rigid/RigidBodyState.h"
#include "sph/ParticleSet.h"
#include "sph/PressureWarmStart.h"

#include <cstdint>
#include <vector>

namespace airtrap {

struct SimulationState {
    int frame = 1;                    //!< the frame this state is the end of (1 = initial state)
    double time = 0.0;                //!< s
    std::uint64_t steps = 0;          //!< sub-steps taken since t = 0
    double lastTimeStep = 0.0;        //!< s, Δt of the last sub-step
    double lastMaxAcceleration = 0.0; //!< m/s², feeds the next Δt (force criterion)
    std::uint32_t nextParticleId = 0;
    ParticleSet fluid;
    //! Pose and velocities of every rigid body, in the scene's body order; empty when the scene
    //! has none (and in frames written before bodies were cached).
    std::vector<RigidBodyState> bodies;
    //! The trapped air bubbles alive at the end of the frame, oldest first.
    std::vector<BubbleState> bubbles;
    std::uint32_t nextBubbleId = 0; //!< also the number of bubbles created so far
    //! Bubbles deleted so far, per rule (`created` unused: nextBubbleId counts them).
    BubbleTally bubblesDeleted;
    //! Where a divergence-free solver's next step starts from (empty for WCSPH).
    PressureWarmStart warmStart;

    bool operator==(const SimulationState& other) const = default;
};

} // namespace airtrap

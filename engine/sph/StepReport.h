#pragma once
// What one step of the water did, for the time-step controller and the blow-up guard.
#include "core/Math.h"

#include <cstddef>

namespace airtrap {

struct StepReport {
    double timeStep = 0.0;            //!< s, Δt actually taken
    double maxAcceleration = 0.0;     //!< m/s², without contact impulses (WCSPH: the next Δt)
    double maxSpeed = 0.0;            //!< m/s, at the start of the step (DFSPH: predicted)
    Vec3f fastestAt = Vec3f::Zero();  //!< m, where maxSpeed was reached (DFSPH)
    bool stepAtMinimum = false;       //!< the flow asked for a step below the minimum (DFSPH)
    double maxDensityDeviation = 0.0; //!< max |ρ/ρ₀ − 1| after the step
    std::size_t removedParticles = 0; //!< left the domain this step
    bool nonFinite = false;           //!< a NaN or infinity appeared
    // Divergence-free SPH only.
    int divergenceIterations = 0;
    int densityIterations = 0;
    double densityError = 0.0; //!< average compression (ρ/ρ₀ − 1)⁺ the density solve reached
    bool densityConverged = true; //!< false when the density solve stopped at max_iterations
};

} // namespace airtrap

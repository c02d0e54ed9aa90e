#pragma once
// What one step of the water did, for the time-step controller and the blow-up guard.
#include <cstddef>

namespace airtrap {

struct StepReport {
    double timeStep = 0.0;            //!< s, Δt actually taken
    double maxAcceleration = 0.0;     //!< m/s², without contact impulses (feeds the next Δt)
    double maxSpeed = 0.0;            //!< m/s, at the start of the step
    double maxDensityDeviation = 0.0; //!< max |ρ/ρ₀ − 1| after the step
    std::size_t removedParticles = 0; //!< left the domain this step
    bool nonFinite = false;           //!< a NaN or infinity appeared
};

} // namespace airtrap

#pragma once
// An inflow nozzle that emits: appends the layers that left the nozzle during a step to the
// water. Emission is a pure function of the simulated time (see InflowNozzle), so a resumed bake
// emits exactly what a straight one does, with no emitter state in the cache.
#include "scene/InflowNozzle.h"
#include "sim/SimulationState.h"

#include <cstddef>

namespace airtrap {

class InflowEmitter : public InflowNozzle {
public:
    //! `spacing` is the scene's particle spacing Δx; emitted particles get `restDensity`.
    InflowEmitter(const InflowEmitterSettings& settings, double spacing, double restDensity);

    //! Appends the layers that leave during [from, to), each where it is at `to`: the nozzle plane
    //! advanced by speed·(to − t_k) along the direction, so consecutive layers are Δx apart.
    //! Ids come from state.nextParticleId. Returns the number of particles added.
    std::size_t emit(double from, double to, SimulationState& state) const;

private:
    float restDensity_;
};

} // namespace airtrap

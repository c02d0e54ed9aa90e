#include "sim/InflowEmitter.h"

namespace airtrap {

InflowEmitter::InflowEmitter(const InflowEmitterSettings& settings, double spacing,
                             double restDensity)
    : InflowNozzle(settings, spacing), restDensity_(static_cast<float>(restDensity)) {}

std::size_t InflowEmitter::emit(double from, double to, SimulationState& state) const {
    const std::size_t first = layersBefore(from);
    const std::size_t last = layersBefore(to);
    const Vec3f velocity = (settings().speed * direction()).cast<float>();
    // No reserve(): an exact reserve every step would defeat the vector's geometric growth.
    ParticleSet& fluid = state.fluid;
    for (std::size_t k = first; k < last; ++k) {
        const Vec3d centre =
            settings().position + settings().speed * (to - layerTime(k)) * direction();
        for (const Vec3d& offset : layerOffsets())
            fluid.push((centre + offset).cast<float>(), velocity, restDensity_,
                       state.nextParticleId++);
    }
    return (last - first) * layerOffsets().size();
}

} // namespace airtrap

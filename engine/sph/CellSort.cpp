#include "sph/CellSort.h"

#include "core/ParallelMax.h"

#include <utility>

namespace airtrap {

void sortByCell(NeighborGrid& grid, ParticleSet& fluid, ParticleSet& scratch,
                PositionArrays& sorted, StepReport& report) {
    grid.build(fluid.positions);
    report.removedParticles = grid.outsideCount();
    const auto& order = grid.order();
    const std::size_t n = order.size();
    scratch.resize(n);
    sorted.resize(n);
    report.maxSpeed = parallelMax(n, [&](std::size_t s) {
        const std::uint32_t from = order[s];
        const Vec3f& x = fluid.positions[from];
        scratch.positions[s] = x;
        sorted.x[s] = x.x();
        sorted.y[s] = x.y();
        sorted.z[s] = x.z();
        scratch.velocities[s] = fluid.velocities[from];
        scratch.densities[s] = fluid.densities[from];
        scratch.ids[s] = fluid.ids[from];
        return scratch.velocities[s].norm();
    });
    std::swap(fluid, scratch);
}

} // namespace airtrap

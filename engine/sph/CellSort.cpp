#include "sph/CellSort.h"

#include "core/Parallel.h"
#include "core/ParallelMax.h"

#include <tbb/blocked_range.h>
#include <utility>

namespace airtrap {
namespace {

constexpr std::size_t kPermuteGrain = 4096;

//! values ← values in `order`, through `spare`.
template <class T>
void permute(std::vector<T>& values, const std::vector<std::uint32_t>& order,
             std::vector<T>& spare) {
    const std::size_t n = order.size();
    spare.resize(n);
    parallelFor(tbb::blocked_range<std::size_t>(0, n, kPermuteGrain),
                [&](const tbb::blocked_range<std::size_t>& r) {
                    for (std::size_t s = r.begin(); s != r.end(); ++s)
                        spare[s] = values[order[s]];
                });
    std::swap(values, spare);
}

} // namespace

void sortByCell(NeighborGrid& grid, ParticleSet& fluid, SortSpares spares, PositionArrays& sorted,
                StepReport& report) {
    grid.build(fluid.positions);
    report.removedParticles = grid.outsideCount();
    const auto& order = grid.order();
    const std::size_t n = order.size();
    sorted.resize(n);
    spares.vectors.resize(n);
    parallelFor(tbb::blocked_range<std::size_t>(0, n, kPermuteGrain),
                [&](const tbb::blocked_range<std::size_t>& r) {
                    for (std::size_t s = r.begin(); s != r.end(); ++s) {
                        const Vec3f& x = fluid.positions[order[s]];
                        spares.vectors[s] = x;
                        sorted.x[s] = x.x();
                        sorted.y[s] = x.y();
                        sorted.z[s] = x.z();
                    }
                });
    std::swap(fluid.positions, spares.vectors);
    spares.vectors.resize(n);
    report.maxSpeed = parallelMax(n, [&](std::size_t s) {
        spares.vectors[s] = fluid.velocities[order[s]];
        return spares.vectors[s].norm();
    });
    std::swap(fluid.velocities, spares.vectors);
    permute(fluid.densities, order, spares.scalars);
    permute(fluid.ids, order, spares.ids);
}

} // namespace airtrap

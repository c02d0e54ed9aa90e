#include "sph/BoundaryVolumes.h"

#include "core/Parallel.h"
#include "sph/NeighborGrid.h"

#include <cmath>

namespace airtrap {

double BoundaryVolumes::flatLatticeKernelSum(const CubicSplineKernel& kernel, double spacing) {
    const int reach = static_cast<int>(std::ceil(kernel.supportRadius() / spacing));
    double sum = 0.0;
    for (int j = -reach; j <= reach; ++j)
        for (int i = -reach; i <= reach; ++i)
            sum += kernel.value(static_cast<float>(spacing * std::sqrt(double(i * i + j * j))));
    return sum;
}

void BoundaryVolumes::compute(BoundaryParticles& particles, const CubicSplineKernel& kernel,
                              double spacing) {
    if (particles.size() == 0)
        return;
    Aabb bounds{particles.positions[0].cast<double>(), particles.positions[0].cast<double>()};
    for (const Vec3f& p : particles.positions) {
        bounds.min = bounds.min.cwiseMin(p.cast<double>());
        bounds.max = bounds.max.cwiseMax(p.cast<double>());
    }
    NeighborGrid grid(bounds, kernel.supportRadius());
    grid.build(particles.positions);
    const auto& order = grid.order();
    std::vector<Vec3f> sorted(order.size());
    for (std::size_t s = 0; s < order.size(); ++s)
        sorted[s] = particles.positions[order[s]];

    const float radius2 = kernel.supportRadius() * kernel.supportRadius();
    const float flatVolume =
        static_cast<float>(std::pow(spacing, 3) * flatLatticeKernelSum(kernel, spacing));
    parallelFor(std::size_t(0), particles.size(), [&](std::size_t b) {
        const Vec3f& x = particles.positions[b];
        float sum = 0.0f;
        grid.forEachNeighborRange(x, kernel.supportRadius(),
                                  [&](std::uint32_t begin, std::uint32_t end) {
                                      for (std::uint32_t s = begin; s < end; ++s) {
                                          const float r2 = (x - sorted[s]).squaredNorm();
                                          if (r2 < radius2)
                                              sum += kernel.value(std::sqrt(r2));
                                      }
                                  });
        particles.volumes[b] = flatVolume / sum; // sum ≥ W(0) > 0: b is its own neighbour
    });
}

} // namespace airtrap

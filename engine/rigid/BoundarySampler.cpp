#include "rigid/BoundarySampler.h"

#include "sph/NeighborGrid.h"

#include <cmath>
#include <tbb/parallel_for.h>

namespace airtrap {

BoundaryParticles BoundarySampler::sampleBox(const Aabb& box, double spacing, WaterSide side,
                                             bool openTop) {
    Vec3i cells;
    Vec3d step;
    for (int axis = 0; axis < 3; ++axis) {
        cells[axis] = std::max(1, static_cast<int>(std::lround(box.size()[axis] / spacing)));
        step[axis] = box.size()[axis] / cells[axis];
    }
    const double sign = side == WaterSide::Inside ? -1.0 : 1.0;
    BoundaryParticles out;
    for (int k = 0; k <= cells.z(); ++k)
        for (int j = 0; j <= cells.y(); ++j)
            for (int i = 0; i <= cells.x(); ++i) {
                const Vec3i index(i, j, k);
                Vec3d normal = Vec3d::Zero();
                for (int axis = 0; axis < 3; ++axis) {
                    if (index[axis] == 0)
                        normal[axis] -= 1.0;
                    else if (index[axis] == cells[axis])
                        normal[axis] += 1.0;
                }
                if (normal.isZero())
                    continue; // interior lattice point
                if (openTop && j == cells.y())
                    continue;
                const Vec3d position = box.min + index.cast<double>().cwiseProduct(step);
                out.positions.push_back(position.cast<float>());
                out.normals.push_back((sign * normal.normalized()).cast<float>());
            }
    out.volumes.assign(out.positions.size(), 0.0f);
    return out;
}

double BoundarySampler::flatLatticeKernelSum(const CubicSplineKernel& kernel, double spacing) {
    const int reach = static_cast<int>(std::ceil(kernel.supportRadius() / spacing));
    double sum = 0.0;
    for (int j = -reach; j <= reach; ++j)
        for (int i = -reach; i <= reach; ++i)
            sum += kernel.value(static_cast<float>(spacing * std::sqrt(double(i * i + j * j))));
    return sum;
}

void BoundarySampler::computeVolumes(BoundaryParticles& particles, const CubicSplineKernel& kernel,
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
    tbb::parallel_for(std::size_t(0), particles.size(), [&](std::size_t b) {
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

#include "bubbles/BubbleFitter.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace airtrap {

BubbleFitter::BubbleFitter(double spacing, double minRadius)
    : spacing_(spacing), minRadius_(minRadius) {}

std::optional<FittedBubble> BubbleFitter::fit(const AirPocket& pocket, const NeighborGrid& grid,
                                              const PositionArrays& positions) const {
    const double equalVolume = std::cbrt(3.0 * pocket.volume / (4.0 * std::numbers::pi));
    // A water particle stands for the half spacing around it: the bubble's surface keeps clear
    // of that.
    const double clearance = 0.5 * spacing_;
    const double nearest = nearestWater(pocket.centre, equalVolume + clearance, grid, positions);
    const double radius = std::min(equalVolume, nearest - clearance);
    if (radius < minRadius_)
        return std::nullopt;
    FittedBubble bubble;
    bubble.centre = pocket.centre;
    bubble.radius = radius;
    bubble.pocketVolume = pocket.volume;
    return bubble;
}

double BubbleFitter::nearestWater(const Vec3d& x, double reach, const NeighborGrid& grid,
                                  const PositionArrays& positions) const {
    const Vec3i centre = grid.cellCoordinates(x.cast<float>());
    const int cells = static_cast<int>(std::ceil(reach / grid.cellSize()));
    const Vec3i& dims = grid.dimensions();
    double best2 = reach * reach;
    for (int k = std::max(0, centre.z() - cells); k <= std::min(dims.z() - 1, centre.z() + cells);
         ++k)
        for (int j = std::max(0, centre.y() - cells);
             j <= std::min(dims.y() - 1, centre.y() + cells); ++j)
            for (int i = std::max(0, centre.x() - cells);
                 i <= std::min(dims.x() - 1, centre.x() + cells); ++i) {
                const auto [first, last] = grid.cellRange(grid.linearIndex(i, j, k));
                for (std::uint32_t p = first; p < last; ++p)
                    best2 = std::min(best2, (positions[p].cast<double>() - x).squaredNorm());
            }
    return std::sqrt(best2);
}

double BubbleFitter::areaFractionInWater(const Vec3d& centre, double radius,
                                         const NeighborGrid& grid,
                                         const PositionArrays& positions) const {
    // A Fibonacci sphere: evenly spread, deterministic points.
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    int wet = 0;
    for (int s = 0; s < kSurfaceSamples; ++s) {
        const double y = 1.0 - 2.0 * (s + 0.5) / kSurfaceSamples;
        const double ring = std::sqrt(1.0 - y * y);
        const Vec3d direction(ring * std::cos(golden * s), y, ring * std::sin(golden * s));
        const Vec3d point = centre + radius * direction;
        if (nearestWater(point, spacing_, grid, positions) < spacing_)
            ++wet;
    }
    return double(wet) / kSurfaceSamples;
}

} // namespace airtrap

#pragma once
// The boundary particles around a water particle, for every pass that sums over them (both
// pressure solvers' density, force and reaction passes).
#include "sph/BoundaryModel.h"

#include <cstddef>
#include <cstdint>

namespace airtrap {

//! Calls visit(layer, b, d, r²) for every boundary particle b within `radius` of sorted water
//! particle i at xi, d = xi − x_b: the static layer's from its grid, the moving layer's from the
//! step's pair list; ascending within each layer, so sums over them are deterministic.
template <class Visit>
void forEachBoundaryNeighbor(const BoundaryModel& boundary, float radius, std::size_t i,
                             const Vec3f& xi, Visit&& visit) {
    const float radius2 = radius * radius;
    const auto visitWithin = [&](const BoundaryLayer& layer, std::uint32_t b) {
        const Vec3f d = xi - layer.positions()[b];
        const float r2 = d.squaredNorm();
        if (r2 < radius2)
            visit(layer, b, d, r2);
    };
    const BoundaryLayer& fixed = boundary.staticLayer();
    if (fixed.size() > 0 && fixed.reaches(xi))
        fixed.grid().forEachNeighborRange(xi, radius, [&](std::uint32_t begin, std::uint32_t end) {
            for (std::uint32_t b = begin; b < end; ++b)
                visitWithin(fixed, b);
        });
    const BoundaryLayer& moving = boundary.movingLayer();
    if (moving.size() > 0)
        for (std::uint32_t b : boundary.movingPairs().boundaryNear(i))
            visitWithin(moving, b);
}

} // namespace airtrap

#pragma once
// Visits the water neighbours of one particle within the support radius. A branch-free sweep over
// the 27 surrounding cells keeps the candidates inside the support in a small batch (most of the
// time goes into this sweep, so it reads only the three coordinate arrays), then the caller's
// SPH sum runs over the few that remain.
#include "sph/NeighborGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace airtrap {

//! Positions as three separate arrays, in the grid's sorted order.
struct PositionArrays {
    std::vector<float> x, y, z;
    void resize(std::size_t n) {
        x.resize(n);
        y.resize(n);
        z.resize(n);
    }
    Vec3f operator[](std::size_t i) const { return Vec3f(x[i], y[i], z[i]); }
    //! Becomes `points` in the order of `order` (a NeighborGrid's sorted order): entry k is
    //! points[order[k]].
    void gather(const std::vector<Vec3f>& points, const std::vector<std::uint32_t>& order) {
        resize(order.size());
        for (std::size_t k = 0; k < order.size(); ++k) {
            const Vec3f& p = points[order[k]];
            x[k] = p.x();
            y[k] = p.y();
            z[k] = p.z();
        }
    }
    std::size_t allocatedBytes() const {
        return (x.capacity() + y.capacity() + z.capacity()) * sizeof(float);
    }
};

//! The `skip` of a sweep around a point that is none of the particles.
inline constexpr std::size_t kSkipNone = std::numeric_limits<std::size_t>::max();

//! Calls visit(j, d, r²) for every particle j ≠ skip with |d| = |x − xⱼ| < radius: the sweep of
//! a point that need not be one of the particles.
template <class Visit>
void sweepNeighborsAround(const NeighborGrid& grid, const PositionArrays& positions, const Vec3f& x,
                          std::size_t skip, float radius2, Visit&& visit) {
    constexpr std::size_t kBatch = 256;
    std::array<std::uint32_t, kBatch> neighbor;
    const float* px = positions.x.data();
    const float* py = positions.y.data();
    const float* pz = positions.z.data();
    std::size_t count = 0;

    const auto flush = [&] {
        for (std::size_t k = 0; k < count; ++k) {
            const std::uint32_t j = neighbor[k];
            if (j == skip)
                continue; // kept out of the sweep's inner loop, which runs ~8× as often
            const Vec3f d(x.x() - px[j], x.y() - py[j], x.z() - pz[j]);
            visit(j, d, d.squaredNorm());
        }
        count = 0;
    };
    // The distances of a whole row first, in a loop the compiler vectorises; then the cheap
    // compaction of those inside the support.
    std::array<float, kBatch> rowDistance2;
    grid.forEachNeighborRange(x, std::sqrt(radius2), [&](std::uint32_t begin, std::uint32_t end) {
        while (begin < end) {
            const std::uint32_t chunk = std::min<std::uint32_t>(end - begin, kBatch);
            if (count + chunk > kBatch)
                flush();
            const float* cx = px + begin;
            const float* cy = py + begin;
            const float* cz = pz + begin;
            for (std::uint32_t k = 0; k < chunk; ++k) {
                const float dx = x.x() - cx[k];
                const float dy = x.y() - cy[k];
                const float dz = x.z() - cz[k];
                rowDistance2[k] = dx * dx + dy * dy + dz * dz;
            }
            for (std::uint32_t k = 0; k < chunk; ++k) {
                neighbor[count] = begin + k;
                count += rowDistance2[k] < radius2;
            }
            begin += chunk;
        }
    });
    flush();
}

//! Calls visit(j, d, r²) for every particle j ≠ i with |d| = |xᵢ − xⱼ| < radius.
template <class Visit>
void sweepNeighbors(const NeighborGrid& grid, const PositionArrays& positions, std::size_t i,
                    float radius2, Visit&& visit) {
    sweepNeighborsAround(grid, positions, positions[i], i, radius2, std::forward<Visit>(visit));
}

} // namespace airtrap

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
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace airtrap {

namespace sweep_detail {

//! Appends to `kept` (at `count`) the ids begin + k of the candidates with distance2[k] < radius2,
//! k < size, in order. Writes up to three entries past the new count.
inline void keepInside(const float* distance2, std::uint32_t size, float radius2,
                       std::uint32_t begin, std::uint32_t* kept, std::size_t& count) {
    std::uint32_t k = 0;
#if defined(__SSE2__)
    // Four candidates at a time: the positions of a comparison's set bits from a table, stored
    // at once. One by one, each candidate's store waited on the count the last one left (a
    // third of the sweep's time, measured).
    alignas(16) static constexpr std::int32_t kSetBits[16][4] = {
        {0, 0, 0, 0}, {0, 0, 0, 0}, {1, 0, 0, 0}, {0, 1, 0, 0}, {2, 0, 0, 0}, {0, 2, 0, 0},
        {1, 2, 0, 0}, {0, 1, 2, 0}, {3, 0, 0, 0}, {0, 3, 0, 0}, {1, 3, 0, 0}, {0, 1, 3, 0},
        {2, 3, 0, 0}, {0, 2, 3, 0}, {1, 2, 3, 0}, {0, 1, 2, 3}};
    static constexpr std::uint8_t kBitCount[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
    const __m128 limit = _mm_set1_ps(radius2);
    for (; k + 4 <= size; k += 4) {
        const int mask = _mm_movemask_ps(_mm_cmplt_ps(_mm_loadu_ps(distance2 + k), limit));
        const __m128i offsets = _mm_load_si128(reinterpret_cast<const __m128i*>(kSetBits[mask]));
        const __m128i ids = _mm_add_epi32(_mm_set1_epi32(static_cast<int>(begin + k)), offsets);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(kept + count), ids);
        count += kBitCount[mask];
    }
#endif
    for (; k < size; ++k) {
        kept[count] = begin + k;
        count += distance2[k] < radius2;
    }
}

} // namespace sweep_detail

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

//! The most candidates a sweep hands over at once.
inline constexpr std::size_t kSweepBatch = 256;

//! Calls visitBatch(js, count) with the particles j within radius of x, up to kSweepBatch at a
//! time, in a fixed order; the caller skips x's own particle if it is one of them. For sums
//! whose work per pair is short: they run in the caller's own loop, with their totals in
//! registers, rather than through a call per pair that keeps them in memory.
template <class VisitBatch>
void sweepNeighborBatchesAround(const NeighborGrid& grid, const PositionArrays& positions,
                                const Vec3f& x, float radius2, VisitBatch&& visitBatch) {
    // With room for keepInside()'s writes past the count.
    std::array<std::uint32_t, kSweepBatch + 3> neighbor;
    const float* px = positions.x.data();
    const float* py = positions.y.data();
    const float* pz = positions.z.data();
    std::size_t count = 0;

    const auto flush = [&] {
        if (count > 0)
            visitBatch(neighbor.data(), count);
        count = 0;
    };
    // The distances of a whole row first, in a loop the compiler vectorises; then the cheap
    // compaction of those inside the support.
    std::array<float, kSweepBatch> rowDistance2;
    grid.forEachNeighborRange(x, std::sqrt(radius2), [&](std::uint32_t begin, std::uint32_t end) {
        while (begin < end) {
            const std::uint32_t chunk =
                std::min<std::uint32_t>(end - begin, static_cast<std::uint32_t>(kSweepBatch));
            if (count + chunk > kSweepBatch)
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
            sweep_detail::keepInside(rowDistance2.data(), chunk, radius2, begin, neighbor.data(),
                                     count);
            begin += chunk;
        }
    });
    flush();
}

//! Calls visit(j, d, r²) for every particle j ≠ skip with |d| = |x − xⱼ| < radius: the sweep of
//! a point that need not be one of the particles.
template <class Visit>
void sweepNeighborsAround(const NeighborGrid& grid, const PositionArrays& positions, const Vec3f& x,
                          std::size_t skip, float radius2, Visit&& visit) {
    const float* px = positions.x.data();
    const float* py = positions.y.data();
    const float* pz = positions.z.data();
    sweepNeighborBatchesAround(
        grid, positions, x, radius2, [&](const std::uint32_t* batch, std::size_t count) {
            for (std::size_t k = 0; k < count; ++k) {
                const std::uint32_t j = batch[k];
                if (j == skip)
                    continue; // kept out of the sweep's inner loop, which runs ~8× as often
                const Vec3f d(x.x() - px[j], x.y() - py[j], x.z() - pz[j]);
                visit(j, d, d.squaredNorm());
            }
        });
}

//! Calls visit(j, d, r²) for every particle j ≠ i with |d| = |xᵢ − xⱼ| < radius.
template <class Visit>
void sweepNeighbors(const NeighborGrid& grid, const PositionArrays& positions, std::size_t i,
                    float radius2, Visit&& visit) {
    sweepNeighborsAround(grid, positions, positions[i], i, radius2, std::forward<Visit>(visit));
}

} // namespace airtrap

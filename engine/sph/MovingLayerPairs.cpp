#include "sph/MovingLayerPairs.h"

#include "core/Parallel.h"

#include <algorithm>
#include <tbb/blocked_range.h>

namespace airtrap {
namespace {

//! Boundary particles per chunk: a bubble has a handful, a dropped body a few hundred.
constexpr std::size_t kChunk = 32;

} // namespace

void MovingLayerPairs::find(const BoundaryLayer& layer, const NeighborGrid& waterGrid,
                            const PositionArrays& water, float supportRadius) {
    // A hair wider than the passes' test, so rounding can only add pairs, never lose one.
    const float radius2 = supportRadius * supportRadius * (1.0f + 1e-4f);
    findWaterNearLayer(layer, waterGrid, water, radius2);
    listBoundaryNearWater(waterGrid.sortedCount());
}

void MovingLayerPairs::findWaterNearLayer(const BoundaryLayer& layer, const NeighborGrid& waterGrid,
                                          const PositionArrays& water, float radius2) {
    const auto& positions = layer.positions();
    const std::size_t chunks = (positions.size() + kChunk - 1) / kChunk;
    chunkCounts_.resize(std::max(chunkCounts_.size(), chunks));
    chunkWater_.resize(std::max(chunkWater_.size(), chunks));
    parallelFor(tbb::blocked_range<std::size_t>(0, chunks, 1), [&](const auto& r) {
        for (std::size_t c = r.begin(); c != r.end(); ++c) {
            std::vector<std::uint32_t>& counts = chunkCounts_[c];
            std::vector<std::uint32_t>& found = chunkWater_[c];
            counts.clear();
            found.clear();
            const std::size_t end = std::min(positions.size(), (c + 1) * kChunk);
            for (std::size_t b = c * kChunk; b < end; ++b) {
                const std::size_t before = found.size();
                // The sweep visits the water in ascending sorted order.
                sweepNeighborsAround(
                    waterGrid, water, positions[b], kSkipNone, radius2,
                    [&](std::uint32_t i, const Vec3f&, float) { found.push_back(i); });
                counts.push_back(static_cast<std::uint32_t>(found.size() - before));
            }
        }
    });
    waterStart_.assign(1, 0);
    water_.clear();
    for (std::size_t c = 0; c < chunks; ++c) {
        for (std::uint32_t count : chunkCounts_[c])
            waterStart_.push_back(waterStart_.back() + count);
        water_.insert(water_.end(), chunkWater_[c].begin(), chunkWater_[c].end());
    }
}

void MovingLayerPairs::listBoundaryNearWater(std::size_t waterCount) {
    // Only last step's marks are cleared: most of the water never has a partner.
    for (std::uint32_t i : marked_)
        if (i < slot_.size())
            slot_[i] = 0;
    slot_.resize(waterCount, 0);
    marked_.clear();
    cursor_.clear();
    for (std::uint32_t i : water_) {
        if (slot_[i] == 0) {
            marked_.push_back(i);
            cursor_.push_back(0);
            slot_[i] = static_cast<std::uint32_t>(marked_.size());
        }
        ++cursor_[slot_[i] - 1];
    }
    boundaryStart_.assign(marked_.size() + 1, 0);
    for (std::size_t k = 0; k < marked_.size(); ++k) {
        boundaryStart_[k + 1] = boundaryStart_[k] + cursor_[k];
        cursor_[k] = boundaryStart_[k];
    }
    boundary_.resize(water_.size());
    // Boundary particles in ascending order, so each water particle's list ascends too.
    const std::size_t layerSize = waterStart_.size() - 1;
    for (std::uint32_t b = 0; b < layerSize; ++b)
        for (std::uint32_t i : waterNear(b))
            boundary_[cursor_[slot_[i] - 1]++] = b;
}

std::size_t MovingLayerPairs::allocatedBytes() const {
    std::size_t bytes =
        (waterStart_.capacity() + water_.capacity() + slot_.capacity() + marked_.capacity() +
         boundaryStart_.capacity() + boundary_.capacity() + cursor_.capacity()) *
        sizeof(std::uint32_t);
    for (std::size_t c = 0; c < chunkCounts_.size(); ++c)
        bytes += (chunkCounts_[c].capacity() + chunkWater_[c].capacity()) * sizeof(std::uint32_t);
    return bytes;
}

} // namespace airtrap

#pragma once
// The pairs of sorted water particles and moving-layer particles closer than the support radius,
// found once a step from the layer's side, where there are few particles to sweep around, and
// read three times: per water particle by the density and force passes, per boundary particle by
// the bodies' reactions. Bubbles carry only a handful of boundary particles each, so a sweep of
// the layer's grid from every water particle near one (twice a step) cost several times the
// interaction it found; a list lookup costs nothing.
//
// Both views list their partners in ascending sorted order, the order a grid sweep visits them,
// so every sum over a view is the same, to the bit, as the sum over the sweep it replaces.
#include "sph/BoundaryLayer.h"
#include "sph/NeighborSweep.h"

#include <cstdint>
#include <span>
#include <vector>

namespace airtrap {

class MovingLayerPairs {
public:
    //! Finds the pairs of `layer` with the water (sorted on `waterGrid`) within a hair more than
    //! `supportRadius`: rounding can only add pairs, which the passes' own distance test drops.
    void find(const BoundaryLayer& layer, const NeighborGrid& waterGrid,
              const PositionArrays& water, float supportRadius);

    //! Sorted water particles near boundary particle `b` of the layer, ascending.
    std::span<const std::uint32_t> waterNear(std::size_t b) const {
        return span(water_, waterStart_[b], waterStart_[b + 1]);
    }
    //! Boundary particles near sorted water particle `i`, ascending; empty for most of the water.
    std::span<const std::uint32_t> boundaryNear(std::size_t i) const {
        if (i >= slot_.size() || slot_[i] == 0)
            return {};
        const std::uint32_t k = slot_[i] - 1;
        return span(boundary_, boundaryStart_[k], boundaryStart_[k + 1]);
    }
    //! How many water particles have a partner in the layer.
    std::size_t waterCount() const { return marked_.size(); }
    //! The sorted water particles that have a partner in the layer, in a fixed order.
    std::span<const std::uint32_t> waterWithPartners() const { return marked_; }
    std::size_t pairCount() const { return water_.size(); }
    std::size_t allocatedBytes() const;

private:
    static std::span<const std::uint32_t> span(const std::vector<std::uint32_t>& list,
                                               std::uint32_t begin, std::uint32_t end) {
        return {list.data() + begin, end - begin};
    }
    //! The water near each boundary particle, by chunks of the layer swept in parallel and joined
    //! in the layer's order: the same lists on any number of threads.
    void findWaterNearLayer(const BoundaryLayer& layer, const NeighborGrid& waterGrid,
                            const PositionArrays& water, float radius2);
    //! The transpose: the boundary particles near each water particle that has any.
    void listBoundaryNearWater(std::size_t waterCount);

    // By boundary particle: its water neighbours water_[waterStart_[b], waterStart_[b + 1]).
    std::vector<std::uint32_t> waterStart_;
    std::vector<std::uint32_t> water_;
    // By water particle: slot_[i] = 0 for none, else k + 1 where boundary_[boundaryStart_[k],
    // boundaryStart_[k + 1]) are its boundary neighbours; marked_[k] = i.
    std::vector<std::uint32_t> slot_;
    std::vector<std::uint32_t> marked_;
    std::vector<std::uint32_t> boundaryStart_;
    std::vector<std::uint32_t> boundary_;
    std::vector<std::uint32_t> cursor_;
    //! Per chunk of the layer: its particles' neighbour counts, then their neighbours.
    std::vector<std::vector<std::uint32_t>> chunkCounts_;
    std::vector<std::vector<std::uint32_t>> chunkWater_;
};

} // namespace airtrap

#pragma once
// The water neighbours of every particle for one step, found once by the pass that sweeps the
// grid and read again by the passes after it, so the 27-cell sweep runs once per step.
//
// The lists are packed without gaps, block by block of kBlockSize particles: the memory is what
// the neighbours need (about 30 per particle in water at rest, 26 on the initial lattice) rather
// than a fixed capacity sized for the most compressed particle, and nothing overflows. One task
// fills a block in particle order, so the lists are the same on any number of threads. Each pair
// may keep a 16-bit value beside its index (DFSPH keeps its kernel factor's code there: 6 bytes
// a pair rather than 8, the lists being most of the solver's memory).
#include "core/Parallel.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <tbb/blocked_range.h>
#include <vector>

namespace airtrap {

class NeighborList {
public:
    static constexpr std::size_t kBlockSize = 512;
    using Value = std::uint16_t;

    //! Where the search of one particle puts its neighbours, in the order it finds them.
    class Sink {
    public:
        void add(std::uint32_t j) { indices_.push_back(j); }
        //! count pairs with a value each: js[k] with values[k].
        void add(const std::uint32_t* js, const Value* values, std::size_t count) {
            indices_.insert(indices_.end(), js, js + count);
            values_.insert(values_.end(), values, values + count);
        }

    private:
        friend class NeighborList;
        std::vector<std::uint32_t> indices_;
        std::vector<Value> values_;
    };

    //! Lists particles [0, particles): find(i, sink) hands each of particle i's neighbours to the
    //! sink, every pair with a value or none without (values() is only for the former). Blocks
    //! run in parallel.
    template <class Find>
    void build(std::size_t particles, Find&& find) {
        const std::size_t blockCount = (particles + kBlockSize - 1) / kBlockSize;
        blocks_.resize(blockCount);
        ends_.resize(particles);
        parallelFor(tbb::blocked_range<std::size_t>(0, blockCount, 1),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                        Sink sink;
                        for (std::size_t b = r.begin(); b != r.end(); ++b)
                            fillBlock(b, std::min(particles, (b + 1) * kBlockSize), sink, find);
                    });
    }

    std::uint32_t count(std::size_t i) const { return ends_[i] - begin(i); }
    const std::uint32_t* neighbors(std::size_t i) const {
        return blocks_[i / kBlockSize].indices.data() + begin(i);
    }
    //! The values kept with particle i's pairs, in the order of neighbors(i).
    const Value* values(std::size_t i) const {
        return blocks_[i / kBlockSize].values.data() + begin(i);
    }

    std::size_t allocatedBytes() const {
        std::size_t bytes = ends_.capacity() * sizeof(std::uint32_t);
        for (const Block& block : blocks_)
            bytes += block.indices.capacity() * sizeof(std::uint32_t) +
                     block.values.capacity() * sizeof(Value);
        return bytes;
    }

private:
    struct Block {
        std::vector<std::uint32_t> indices;
        std::vector<Value> values;
    };
    //! A block keeps its memory while its lists fit, unless they use less than this share of it
    //! (a splash's block, once dense, would hold its peak for the rest of the bake).
    static constexpr std::size_t kShrinkBelowPercent = 75;

    template <class T>
    static void assignFitting(std::vector<T>& to, const std::vector<T>& from) {
        if (from.size() * 100 < to.capacity() * kShrinkBelowPercent)
            std::vector<T>().swap(to);
        to.assign(from.begin(), from.end());
    }

    std::uint32_t begin(std::size_t i) const { return i % kBlockSize == 0 ? 0 : ends_[i - 1]; }

    template <class Find>
    void fillBlock(std::size_t b, std::size_t end, Sink& sink, Find& find) {
        sink.indices_.clear();
        sink.values_.clear();
        for (std::size_t i = b * kBlockSize; i != end; ++i) {
            find(i, sink);
            ends_[i] = static_cast<std::uint32_t>(sink.indices_.size());
        }
        // Copied at their exact size: a block grown pair by pair would keep up to twice the
        // memory its lists need.
        Block& block = blocks_[b];
        assignFitting(block.indices, sink.indices_);
        assignFitting(block.values, sink.values_);
    }

    std::vector<Block> blocks_;
    std::vector<std::uint32_t> ends_; //!< end of each particle's list within its block
};

} // namespace airtrap

#pragma once
// The water neighbours of every particle for one step, found once by the density pass and read
// again by the force pass, so the 27-cell sweep runs once per step. Fixed capacity per particle:
// about 26 neighbours sit within a support of 2Δx on the initial lattice, so 40 leaves room for
// compression; a particle with more is marked and the force pass sweeps its cells again.
#include <cstdint>
#include <vector>

namespace airtrap {

class NeighborList {
public:
    static constexpr std::uint32_t kCapacity = 40;
    static constexpr std::uint8_t kOverflow = 0xff;

    void resize(std::size_t particles) {
        indices_.resize(particles * kCapacity);
        counts_.resize(particles);
    }

    //! Stores the neighbours `found[0, count)` of particle i, or marks it as overflowing.
    void store(std::size_t i, const std::uint32_t* found, std::uint32_t count) {
        if (count > kCapacity) {
            counts_[i] = kOverflow;
            return;
        }
        std::uint32_t* out = &indices_[i * kCapacity];
        for (std::uint32_t k = 0; k < count; ++k)
            out[k] = found[k];
        counts_[i] = static_cast<std::uint8_t>(count);
    }

    bool overflowed(std::size_t i) const { return counts_[i] == kOverflow; }
    std::uint32_t count(std::size_t i) const { return counts_[i]; }
    const std::uint32_t* neighbors(std::size_t i) const { return &indices_[i * kCapacity]; }

    std::size_t allocatedBytes() const {
        return indices_.capacity() * sizeof(std::uint32_t) + counts_.capacity();
    }

private:
    std::vector<std::uint32_t> indices_;
    std::vector<std::uint8_t> counts_;
};

} // namespace airtrap

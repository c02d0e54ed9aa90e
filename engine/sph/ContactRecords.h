#pragma once
// The contact impulses water particles received from dynamic bodies in a force pass (paper
// eq. 4), kept so that each body can take the equal and opposite impulse: per water particle,
// in the step's sorted order, the boundary particle it hit (−1 for none) and the impulse J.
#include "core/Math.h"

#include <cstdint>
#include <vector>

namespace airtrap {

struct ContactRecords {
    std::vector<std::int32_t> boundaryParticle;
    std::vector<Vec3f> impulse; //!< N·s, on the water particle; stale where there is no contact

    void resize(std::size_t n) {
        boundaryParticle.resize(n);
        impulse.resize(n);
    }
    std::size_t allocatedBytes() const {
        return boundaryParticle.capacity() * sizeof(std::int32_t) +
               impulse.capacity() * sizeof(Vec3f);
    }
};

} // namespace airtrap

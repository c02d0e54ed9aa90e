#pragma once
#include "post/SubgridBubble.h"

#include <cstdint>
#include <vector>

namespace airtrap {

//! The sub-grid bubbles at the end of a cache frame, with what the next frame needs to go on from
//! them (paper §4.2): the next free sub-grid id, and which trapped bubbles were already born, so
//! only the ones born later shed.
struct SubgridFrame {
    //! Trapped bubbles with a smaller id existed by this frame: the cache frame's nextBubbleId.
    std::uint32_t trappedIdsBelow = 0;
    std::uint32_t nextId = 0; //!< id of the next sub-grid bubble shed
    std::vector<SubgridBubble> bubbles;

    bool operator==(const SubgridFrame& other) const = default;
};

} // namespace airtrap

#pragma once
#include "core/Math.h"

#include <cstdint>

namespace airtrap {

//! A bubble below the grid's resolution (paper §4.2): a point carried by the water, rising at its
//! own Stokes speed, rendered as an instanced sphere of `radius`.
struct SubgridBubble {
    std::uint32_t id = 0;
    std::uint32_t parentId =
        0; //!< the trapped bubble (generation 1) or sub-grid bubble it came from
    int generation = 1;
    Vec3d position = Vec3d::Zero(); //!< m
    double radius = 0.0;            //!< m
    Vec3d velocity = Vec3d::Zero(); //!< m/s, of its last step
    double age = 0.0;               //!< s

    bool operator==(const SubgridBubble& other) const = default;
};

} // namespace airtrap

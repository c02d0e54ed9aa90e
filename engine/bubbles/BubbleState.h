#pragma once
// What the frame cache keeps of a trapped air bubble (chunks BUBL and BSUR,
// docs/CACHE_FORMAT.md): enough to continue a bake bit for bit and to render the bubble (paper
// §3.2–3.4, §4).
#include "bubbles/BubbleSurroundings.h"
#include "rigid/RigidBodyState.h"

#include <cstdint>

namespace airtrap {

struct BubbleState {
    std::uint32_t id = 0;
    std::int32_t birthFrame = 0;      //!< the first frame that holds it
    double radius = 0.0;              //!< m
    RigidBodyState body;              //!< centre, orientation and velocities
    double age = 0.0;                 //!< s since creation
    double floatingTime = 0.0;        //!< s spent at the free surface without a break
    double areaFractionInWater = 1.0; //!< share of its surface in water at creation (sub-grid)
    double pocketVolume = 0.0;        //!< m³ of the air pocket it was made from (sub-grid)
    BubbleSurroundings surroundings;  //!< the water around it, as last measured (chunk BSUR)

    bool operator==(const BubbleState& other) const = default;
};

} // namespace airtrap

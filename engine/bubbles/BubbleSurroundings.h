#pragma once
// What the water around a bubble looks like this step, measured over the water particles within
// two support radii of its surface.
#include "core/Math.h"

namespace airtrap {

struct BubbleSurroundings {
    //! m/s, the ambient water velocity: the mean over a shell from one to two support radii off
    //! the bubble's surface, beyond the layer of water the bubble drags along. Eq. 6's drag pulls
    //! toward it and the rise is steered relative to it.
    Vec3d waterVelocity = Vec3d::Zero();
    //! m/s, the fastest water particle touching the bubble approaches its surface.
    double impactSpeed = 0.0;
    //! Share of directions around the bubble with water against its surface.
    double wettedShare = 0.0;
    //! The water does not cover its top: the bubble floats at the free surface.
    bool floating = false;
};

} // namespace airtrap

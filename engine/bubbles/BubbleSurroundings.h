#pragma once
// What the water around a bubble looked like when it was last measured, over the water
// particles within two support radii of its surface. Measured every 0.25 ms of simulated time
// (BubbleDynamics::kMeasureInterval) and kept in the cache with the bubble, so that a resumed
// bake holds the same measure as one that ran on.
#include "bubbles/BubbleImmersion.h"
#include "core/Math.h"

#include <cmath>

namespace airtrap {

struct BubbleSurroundings {
    //! m/s, the ambient water velocity: the mean over a shell from one to two support radii off
    //! the bubble's surface, beyond the layer of water the bubble drags along. Eq. 6's drag pulls
    //! toward it and the rise is steered relative to it.
    Vec3d waterVelocity = Vec3d::Zero();
    //! m/s, the fastest water particle touching the bubble approaches its surface.
    double impactSpeed = 0.0;
    //! Share of BubbleImmersion's 26 probes around the bubble that water wets: the share of its
    //! surface in water.
    double wettedShare = 0.0;
    //! 7–12 of the probes wet: the bubble floats at the free surface.
    bool floating = false;
    //! False until the bubble's first measure: a new bubble, or one read from a frame written
    //! before the surroundings were cached.
    bool measured = false;

    int wetProbes() const { return int(std::lround(wettedShare * BubbleImmersion::kProbeCount)); }
    BubbleImmersion::Placement placement() const { return BubbleImmersion::placement(wetProbes()); }

    bool operator==(const BubbleSurroundings& other) const = default;
};

} // namespace airtrap

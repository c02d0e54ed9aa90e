#pragma once
// Sizes a bubble for an air pocket (paper §3.4, docs/METHOD.md "Creation"): at the pocket's centre,
// with the pocket's volume (equal-volume radius), shrunk until it keeps half a particle spacing
// from every water particle, so a new bubble never starts inside the water. Also measures a
// bubble's area fraction in water: the share of points spread evenly over its surface that have a
// water particle within one spacing, which the sub-grid stage uses to judge the gap between bubble
// and pocket (paper §4.2). Apart from the fit, because it costs twenty times as much and only
// the few pockets chosen for a bubble need it.
#include "bubbles/AirPocket.h"
#include "bubbles/FittedBubble.h"
#include "sph/NeighborGrid.h"
#include "sph/NeighborSweep.h"

#include <optional>

namespace airtrap {

class BubbleFitter {
public:
    //! `spacing` of the water particles (m); bubbles smaller than `minRadius` (m) are not made.
    BubbleFitter(double spacing, double minRadius);

    //! The bubble for `pocket` on `grid`, whose points are `positions` (sorted as the grid
    //! sorted them), without its area fraction; none when the fitted radius is below the minimum.
    std::optional<FittedBubble> fit(const AirPocket& pocket, const NeighborGrid& grid,
                                    const PositionArrays& positions) const;

    //! Surface samples used for the area fraction.
    static constexpr int kSurfaceSamples = 64;

    //! The area fraction in water of a sphere at `centre` of `radius`, 0–1.
    double areaFractionInWater(const Vec3d& centre, double radius, const NeighborGrid& grid,
                               const PositionArrays& positions) const;

private:
    //! Distance from `x` to the nearest point of `grid` within `reach` (m); `reach` if none.
    double nearestWater(const Vec3d& x, double reach, const NeighborGrid& grid,
                        const PositionArrays& positions) const;

    double spacing_;
    double minRadius_;
};

} // namespace airtrap

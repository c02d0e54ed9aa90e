#pragma once
// Moves sub-grid bubbles through the cached water (paper §4.2): passively with the water's
// velocity, interpolated from the frame's particles, plus their own rise, the Stokes speed of
// their radius capped as the trapped bubbles' is (eq. 5), integrated with the midpoint rule
// (second-order Runge–Kutta). A bubble that reaches air (less than half a particle's worth of
// water around it) has surfaced and pops; one older than the lifetime is deleted too. The air
// pocket around a trapped bubble is not the surface: sub-grid bubbles are shed into that very gap,
// so within a support radius of a trapped bubble's surface they count as under water.
#include "bubbles/BubbleState.h"
#include "post/SubgridBubble.h"
#include "post/WaterVelocityField.h"
#include "scene/Scene.h"

#include <vector>

namespace airtrap {

class SubgridAdvector {
public:
    SubgridAdvector(const SubgridBubbleSettings& settings, const Scene& scene);

    //! m/s, the capped Stokes rise speed of a bubble of `radius` m.
    double riseSpeed(double radius) const;
    //! Advances every bubble by `seconds` through `water` (and the frame's `trapped` bubbles) in
    //! the settings' substeps, then drops the popped, the expired and those that end in air.
    //! Order of the survivors is kept.
    void advance(std::vector<SubgridBubble>& bubbles, const WaterVelocityField& water,
                 const std::vector<BubbleState>& trapped, double seconds) const;
    //! Drops the bubbles in air: they have reached the surface and popped.
    void removeSurfaced(std::vector<SubgridBubble>& bubbles, const WaterVelocityField& water,
                        const std::vector<BubbleState>& trapped) const;

private:
    //! Velocity of a bubble of `radius` at `x`; false in `inWater` where the water ends.
    Vec3d velocityAt(const Vec3d& x, double radius, const WaterVelocityField& water,
                     const std::vector<BubbleState>& trapped, bool& inWater) const;
    //! True within a support radius of a trapped bubble's surface: its own air pocket.
    bool besideTrappedBubble(const Vec3d& x, const std::vector<BubbleState>& trapped) const;

    SubgridBubbleSettings settings_;
    BubbleSettings rise_;
    Vec3d up_;
    double gravity_;
    double particleVolume_;
    double support_;
};

} // namespace airtrap

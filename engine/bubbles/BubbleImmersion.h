#pragma once
// The rule that says whether a bubble is in water, at the surface or out of it
// (docs/VALIDATION.md, "Where the bubbles live"). 26 probes sit on a sphere of radius
// r + spacing/2 around the bubble, in the directions of a cube's 6 faces, 12 edges and 8 corners;
// a probe is wet when a water particle lies within one spacing of it. With at least 13 wet probes
// the bubble is in water; with fewer than a quarter (6.5) it is airborne, out of the water; in
// between it floats at the free surface. The simulation judges its bubbles by this rule (creation,
// the immersed share of the auxiliary forces, the floating and surfaced deletions) and
// `airtrap-cli info --bubbles` reports cached frames by it, so the figures and the method agree.
#include "core/Math.h"
#include "sph/NeighborGrid.h"
#include "sph/NeighborSweep.h"

#include <array>
#include <bitset>

namespace airtrap {

class BubbleImmersion {
public:
    static constexpr int kProbeCount = 26;
    //! Wet probes that make a bubble "in water": half of them.
    static constexpr int kInWaterProbes = 13;
    //! Below this many wet probes (a quarter of 26 is 6.5) a bubble is airborne.
    static constexpr int kAirborneBelow = 7;

    using WetProbes = std::bitset<kProbeCount>;
    enum class Placement { InWater, Floating, Airborne };

    explicit BubbleImmersion(double spacing) : spacing_(spacing) {}

    //! Unit directions of the probes: faces first (−x, +x, −y, +y, −z, +z), then edges, then
    //! corners.
    static const std::array<Vec3d, kProbeCount>& directions();
    //! The 9 probes of the hemisphere `up` points into (a face, 4 edges, 4 corners for an axis).
    static WetProbes hemisphere(const Vec3d& up);

    //! Water particles farther than this from the centre wet no probe of a bubble of `radius`.
    double reach(double radius) const { return radius + 1.5 * spacing_; }
    //! Marks in `wet` the probes of the bubble (centre, radius) that the particle at `x` wets.
    void wetBy(const Vec3d& centre, double radius, const Vec3d& x, WetProbes& wet) const;
    //! The probes that the water of `grid` (sorted `positions`) wets around the bubble.
    WetProbes measure(const Vec3d& centre, double radius, const NeighborGrid& grid,
                      const PositionArrays& positions) const;

    static Placement placement(int wetProbes);
    static Placement placement(const WetProbes& wet) { return placement(int(wet.count())); }

private:
    double spacing_;
};

} // namespace airtrap

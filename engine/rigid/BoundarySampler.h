#pragma once
#include "rigid/BoundaryParticles.h"

namespace airtrap {

//! Places boundary particles on box surfaces (their volumes: sph/BoundaryVolumes).
class BoundarySampler {
public:
    //! Which side of a box the water is on.
    enum class WaterSide { Inside, Outside };

    //! Samples the faces of `box` on a lattice of about `spacing`; the top face (+y) is left out
    //! when `openTop` is set. Normals point to `side`; at edges and corners they are the
    //! normalised sum of the faces' normals.
    static BoundaryParticles sampleBox(const Aabb& box, double spacing, WaterSide side,
                                       bool openTop);
};

} // namespace airtrap

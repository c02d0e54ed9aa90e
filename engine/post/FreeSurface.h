#pragma once
// The water mesh an artist renders (paper §4.1, Fig. 2b/d): the water's surface without the
// parts that lie against a solid or a bubble. Those parts duplicate the other object's own
// surface; rendered together, the two interfaces fight (paper Fig. 2c), and the bubble's
// oscillating mesh could not show through. What remains is the free surface only.
#include "post/FrameSolids.h"
#include "rigid/TriangleMesh.h"

namespace airtrap {

//! `water` without every triangle that has a vertex closer than `margin` (m) to a solid or a
//! bubble of `solids`; vertices no triangle uses any more are removed, the rest keep their order.
TriangleMesh freeSurfaceOnly(const TriangleMesh& water, const FrameSolids& solids, double margin);

} // namespace airtrap

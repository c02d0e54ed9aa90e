#pragma once
// The water mesh an artist renders (paper §4.1, Fig. 2b/d): the water's surface without the
// parts that lie against a solid or a bubble. Those parts duplicate the other object's own
// surface; rendered together, the two interfaces fight (paper Fig. 2c), and the bubble's
// oscillating mesh could not show through. What remains is the free surface only.
#include "post/FrameSolids.h"
#include "rigid/TriangleMesh.h"
#include "scene/Scene.h"

namespace airtrap {

//! `water` without the triangles that lie along a solid or a bubble of `solids`: all three
//! vertices closer than `margin` (m) and the triangle facing it (its normal within 60° of the way
//! into it). The other object's own surface renders there. The water's free surface where it
//! meets a wall or a body is kept even that close, as in a tank's corner. Where triangles were
//! dropped, the edge left behind is moved onto the other surface, so the water meets a body at
//! the waterline with no gap and enters none. Vertices no triangle uses any more are removed, the
//! rest keep their order.
TriangleMesh freeSurfaceOnly(const TriangleMesh& water, const FrameSolids& solids, double margin);

//! The water mesh that `settings.mode` asks for: the free surface of `water` (margin in
//! spacings of `spacing` m), or `water` whole when "closed".
TriangleMesh renderedSurface(const TriangleMesh& water, const FrameSolids& solids,
                             const SurfaceMeshSettings& settings, double spacing);

} // namespace airtrap

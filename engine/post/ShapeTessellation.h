#pragma once
// The primitive body shapes as closed triangle meshes in their shape frame (centred at the
// origin, as BodyShape defines them), for exports. Flat faces get their own vertices, so a
// renderer that smooths normals across shared vertices keeps a box's edges and a cylinder's rims
// sharp.
#include "rigid/TriangleMesh.h"

namespace airtrap {

//! Box of edge lengths `size`: 24 vertices, 12 triangles.
TriangleMesh tessellateBox(const Vec3d& size);
//! Sphere of `radius`: an icosphere of 1280 triangles (its vertices on the sphere).
TriangleMesh tessellateSphere(double radius);
//! Capped cylinder of `radius` and `height` along y, `segments` around (at least 3).
TriangleMesh tessellateCylinder(double radius, double height, int segments = 48);

} // namespace airtrap

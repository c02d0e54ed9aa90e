#pragma once
// A sphere of unit radius tessellated from the icosahedron: each subdivision splits every
// triangle into four and pushes the new vertices out onto the sphere, so the triangles stay
// nearly equilateral at every level (a latitude–longitude sphere crowds its poles).
#include "rigid/TriangleMesh.h"

namespace airtrap {

//! 20·4^subdivisions triangles, counter-clockwise seen from outside; 0 ≤ subdivisions ≤ 6.
TriangleMesh unitIcosphere(int subdivisions);

} // namespace airtrap

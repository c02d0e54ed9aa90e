#pragma once
// GLSL shared by the drawables that show spheres as point sprites (the water's particles, the
// sub-grid bubbles): the sprite's size on screen, the sphere's normal at a fragment of it, and the
// depth of the sphere's surface there, so sprites intersect like balls, not like flat discs.
#include <QString>

namespace airtrap {

class SphereSprite {
public:
    //! `float sphereSpritePixels(float radius, mat4 projection, float viewportHeight, float w)`:
    //! the sphere's projected diameter in pixels at clip depth w, 2 r × (pixels per metre).
    static QString vertexFunctions();
    //! `vec3 sphereSpriteNormal()`: the eye-space unit normal at this fragment of the sprite (the
    //! fragment is discarded outside the disc); and `float sphereSpriteDepth(mat4 projection,
    //! vec3 eyeCentre, vec3 normal, float radius)`: the depth of the surface at that normal.
    static QString fragmentFunctions();
};

} // namespace airtrap

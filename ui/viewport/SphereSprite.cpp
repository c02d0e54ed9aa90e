#include "viewport/SphereSprite.h"

namespace airtrap {

QString SphereSprite::vertexFunctions() {
    return QStringLiteral(R"(
float sphereSpritePixels(float radius, mat4 projection, float viewportHeight, float w) {
    return radius * projection[1][1] * viewportHeight / w;
}
)");
}

QString SphereSprite::fragmentFunctions() {
    return QStringLiteral(R"(
vec3 sphereSpriteNormal() {
    vec2 disc = gl_PointCoord * 2.0 - 1.0;
    disc.y = -disc.y; // gl_PointCoord grows downwards
    float r2 = dot(disc, disc);
    if (r2 > 1.0) {
        discard;
    }
    return vec3(disc, sqrt(1.0 - r2));
}
float sphereSpriteDepth(mat4 projection, vec3 eyeCentre, vec3 normal, float radius) {
    vec4 surface = projection * vec4(eyeCentre + normal * radius, 1.0);
    return 0.5 * surface.z / surface.w + 0.5;
}
)");
}

} // namespace airtrap

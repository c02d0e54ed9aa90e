#pragma once
// The colours of water by speed: deep blue at rest, through cyan, to white at the top of the
// scale (foam-like, so fast spray reads as white water). One table feeds both the particle shader
// and the legend, so the two cannot disagree.
#include <QColor>
#include <QString>

namespace airtrap {

class SpeedColormap {
public:
    //! The colour at `t` in [0, 1] (clamped): 0 is at rest, 1 the top of the scale.
    static QColor colourAt(float t);
    //! GLSL source of `vec3 speedColour(float t)`, the same map for shaders.
    static QString glslFunction();
};

} // namespace airtrap

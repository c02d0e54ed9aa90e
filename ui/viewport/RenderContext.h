#pragma once
// What every drawable needs to draw one frame of the viewport.
#include <QMatrix4x4>
#include <QSize>

class QOpenGLExtraFunctions;

namespace airtrap {

struct RenderContext {
    QOpenGLExtraFunctions& gl;     //!< of the viewport's context, which is current
    QMatrix4x4 view;               //!< world to eye
    QMatrix4x4 projection;         //!< eye to clip
    QMatrix4x4 viewProjection;     //!< world to clip
    QSize framebufferSize;         //!< device pixels
    float devicePixelRatio = 1.0f; //!< device pixels per widget pixel, for line widths
};

} // namespace airtrap
